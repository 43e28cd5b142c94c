// XPBD cloth on weft's springs: the peer a user would pick instead of a force-based step,
// written as Jolt Physics' soft body runs it (float storage and arithmetic, one thread,
// substeps of a 60 Hz frame, one Gauss–Seidel sweep over the constraints per substep: the
// "small steps" of Macklin et al. 2019). A reference for weft-bench's realtime study, not a
// part of weft's simulator.
//
// Each spring (i, j, L) of a family of stiffness k (N/m) and damping c (N·s/m) becomes a
// distance constraint C = |x_j - x_i| - L with compliance α = 1/k (m/N); XPBD with that
// compliance has the spring's potential ½ k C², so it settles where the spring force would.
// Per substep of h seconds (Macklin, Müller, Chentanez 2016, "XPBD", eqs. 18 and 26):
//
//   predict   v += h g;  v = w + (v - w) exp(-h a / m)  (air drag a toward the wind w);
//             p = x;  x += h v
//   project   for every spring in order, with λ starting at 0 in each substep:
//             α̃ = α / h²,  γ = α c / h  (eq. 26's α̃ β̃ / h with β̃ = h² c),
//             Δλ = -(C + γ ∇C·(x - p)) / ((1 + γ)(w_i + w_j) + α̃),
//             x_i -= w_i Δλ u,  x_j += w_j Δλ u  (u = (x_j - x_i) / |x_j - x_i|)
//   velocity  v = (x - p) / h
//
// Multiplied through by k h², Δλ is the backward-Euler update of one spring with its
// dashpot, (k h² C + c h Ċ h) / ((k h² + c h)(w_i + w_j) + 1): the damper is implicit, as
// the spring is. Pinned particles (inverse mass 0) never move.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "sim/core/cloth.h"
#include "sim/core/force_pass.h"

namespace weft::bench {

class XpbdCloth {
  public:
    // The cloth's state, masses, pins and springs (all families, in the cloth's order), and
    // the field's gravity, air drag and wind; the user's pull and colliders are not modelled.
    // With `spring_damping` false the dashpots are left out (γ = 0).
    XpbdCloth(const Cloth& cloth, const ForceField& field, bool spring_damping = true);

    // One frame of `frame_seconds` in `substeps` substeps of equal length.
    void step_frame(double frame_seconds, int substeps);
    void substep(float h);  // s

    // In Cloth's layout (double), for comparing with weft's methods.
    std::vector<Vec3> positions() const;
    std::vector<Vec3> velocities() const;
    // Σ m v (kg·m/s) over the free particles, summed in double.
    Vec3 momentum() const;
    // Whether every position and velocity is finite.
    bool is_finite() const;

  private:
    struct Constraint {
        std::uint32_t i, j;  // particles
        float rest_length;   // m
    };
    struct Family {
        float compliance;  // α = 1/k, m/N
        float damping;     // c, N·s/m
        std::vector<Constraint> constraints;
    };
    void cache_drag_factors(float h);

    // Per-substep state.
    std::vector<glm::vec3> positions_;           // m
    std::vector<glm::vec3> previous_positions_;  // m, p: the positions at the substep's start
    std::vector<glm::vec3> velocities_;          // m/s
    // Constants.
    std::vector<float> inverse_masses_;  // 1/kg, 0 = pinned
    std::vector<float> drag_rates_;      // 1/s, air_drag / m
    std::vector<float> drag_factors_;    // exp(-h air_drag / m) for drag_factors_h_
    float drag_factors_h_ = -1.0f;       // s
    std::vector<Family> families_;
    glm::vec3 gravity_;  // m/s²
    glm::vec3 wind_;     // m/s
};

}  // namespace weft::bench
