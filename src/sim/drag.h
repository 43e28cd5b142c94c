// Dragging: the user pulls the cloth by a handle. Particles near the grab point are pulled
// towards where the cursor wants them by a damped spring whose force is capped, so a fast
// flick of the mouse cannot inject enough energy to blow the cloth up. The drag is a force,
// not a position constraint: every integrator sees it in the same force pass, and on
// release the cloth simply keeps the velocity the drag gave it.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "sim/cloth.h"
#include "sim/picking.h"

namespace weft {

struct DragHandle {
    std::vector<std::uint32_t> particles;  // pulled particles (pinned ones excluded)
    std::vector<double> weights;           // in (0, 1]: 1 at the grab point, 0 at the radius
    std::vector<Vec3> offsets;             // m, particle minus grab point when grabbed
    Vec3 target{0.0};                      // m, where the grab point is pulled to
    // The pull on a particle of mass m and weight w is
    //   f = w m (ω² (target + offset - x) - ω v),  |f| <= w m max_acceleration:
    // a spring of angular frequency ω damped at half the critical rate, capped. Stiff, so the
    // hand holds the cloth where the cursor is (Simulation::start_drag lowers ω for large
    // steps: h ω <= 0.5 keeps h²ω² + 2 h ω well inside symplectic Euler's bound of 4).
    double angular_frequency = 300.0;  // rad/s: follows the cursor within ~0.01 s
    double max_acceleration =
        5000.0;  // m/s², about 500 g: enough to pull a sheet, not to explode it
    // The structured implicit step takes the hand's spring into its system, uncapped, and
    // instead moves each particle's goal at most max_speed × h from where the particle is:
    // at a frame-sized step a capped force no longer bounds the step (h² a_max is 1.4 m at
    // 60 Hz), while a bounded goal bounds how far the hand can move the cloth in one step.
    double max_speed = 3.0;  // m/s, a fast hand

    bool active() const { return !particles.empty(); }
};

// A handle grabbing the cloth where `hit` is, pulling every free particle within `radius`
// (m) of the hit point with a weight (1 - (d/r)²)²; the hit triangle's nearest corner is
// always included, so a small radius still grabs one particle.
DragHandle grab_cloth(const Cloth& cloth, const RayHit& hit, double radius);

// Adds the drag forces (N) for the state (positions, velocities).
void accumulate_drag_forces(const DragHandle& drag, const Cloth& cloth,
                            std::span<const Vec3> positions, std::span<const Vec3> velocities,
                            std::span<Vec3> forces);

}  // namespace weft
