// The structured implicit Euler step: the same linearised backward Euler as
// implicit_euler.cpp (Baraff & Witkin 1998) for a cloth whose springs are a regular grid
// (grid_stencil.h), solved matrix-free in single precision over per-direction stencils, on
// every thread of the pool, with a block-Jacobi preconditioner and a warm start.
//
// The general path (implicit_euler.cpp) stays the reference: it solves the same system in
// double for any topology, and a test shows the two agree to the solve's tolerance.
//
// The particles in the user's hand enter the system as constraints with prescribed
// velocities (grab.h), so the rest of the sheet answers the hand within the step at any dt.
// Results are the same bit for bit for any number of threads and every kernel build.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "parallel/worker_pool.h"
#include "sim/core/cloth.h"
#include "sim/core/step_profile.h"
#include "sim/integrators/implicit/implicit_contacts.h"
#include "sim/integrators/implicit/implicit_grid_kernel.h"
#include "sim/integrators/implicit/implicit_multilevel.h"

namespace weft {

struct ForceField;

// When the conjugate-gradient loop stops. The residual is measured against the right-hand
// side of the Δv form, |g| (implicit_grid_kernel.h: the residual at v1 = v_k): the part of the
// step the solve is there to find.
//
// The error a stopped solve leaves in v1 is about the relative residual times the step's
// own change, every step, so over a fixed time it does not shrink with h, while implicit
// Euler's own error does (first order). A tolerance proportional to h keeps the solve's
// share of the error about fixed at every h. At 1.2/s × h, 0.02 at a 60 Hz step, the solve's
// error measured 8 % of the method's own on cloth_128.toml after 0.5 s (2.8 mm against
// 35 mm RMS; 7 % at 0.01 for 19 % more iterations, 17 % at 0.04; docs/accuracy.md).
//
// A norm over the whole sheet can hide a spike: at the snap that ends cloth_128's fall, the
// solve stopped at 0.02 left a few springs 60 % over their rest length where the converged
// solve has 5.5 % (256²: 275 % against 11.5 %). So the default rule also bounds each
// particle's share, estimated by the block-Jacobi part of the preconditioner (which sees a
// local spike well; the smooth error is the global norm's): h |D⁻¹ r_p| at most
// position_tolerance spacings. At 0.005 that took the snap to 10.5 % (13 % at 256²) for
// 18.4 iterations a step instead of 17.2 (29.6 instead of 27.8).
struct ImplicitSolveSettings {
    double tolerance_rate = 1.2;        // 1/s: stop at relative residual tolerance_rate × h ...
    double least_tolerance = 1e-6;      // ... but never ask for less (single precision's reach)
    double position_tolerance = 0.005;  // spacings: largest h |D⁻¹ r_p| left (0: no bound)
    double fixed_tolerance = 0.0;       // > 0: stop at this relative residual alone (studies)
    int max_iterations = 300;
    // Neither bound sees an error that builds up from step to step where the sheet's forces
    // barely act: near its rest length a spring has almost no stiffness across itself, so
    // the sheet's motion out of its plane is held by its mass alone. What each stopped solve
    // leaves there is carried on by the warm start and the motion until a snap stretches it
    // (docs/performance.md, the falling 256² sheet). On such modes the block-Jacobi part of
    // the preconditioner P_J is about A⁻¹, so one damped block-Jacobi step after the
    // iterations, v1 += ω P_J r, removes most of what they left, for a pass over the particles
    // without a product. With ω λ_max(P_J A) < 2 (λ_max ≤ 2, as for the coarse levels in
    // implicit_multilevel.h) the step never adds error in the energy norm.
    double post_smoothing = 0.5;      // ω of that step (0: none)
    bool warm_start = true;           // start from v0 + the previous step's Δv instead of v0
    bool multilevel = true;           // add the coarse levels to the block-Jacobi preconditioner
    ImplicitCycleShape coarse_cycle;  // how the coarse levels correct (implicit_multilevel.h)
    // A step that leaves some spring beyond split_stretch_ratio rest lengths and some
    // spring's force further than split_force_error × k L from what the linearised step
    // assumed is linearised again where it ended (a Newton iteration), up to
    // newton_iterations times, and then taken again as two halves, at most max_split_depth
    // times over (implicit_euler.cpp; a ratio of 0: never).
    double split_stretch_ratio = 1.3;
    double split_force_error = 0.1;
    int newton_iterations = 3;
    int max_split_depth = 3;
    // A try the hand or a Newton iteration takes is judged once before its solve is done,
    // when the solve is within early_judgement times its stopping rule: most tries that fail
    // already fail there, as the linearisation's error depends on where the step ends, not
    // on its last digits, and stop at once. A try judged kept solves on from where it was,
    // the same iterations as without the judgement, and is judged again at the end, so
    // what is kept is never judged on a loose solve. The last try a step may take is kept
    // whatever its judgement, so it is never stopped (0: judged only at the end).
    double early_judgement = 10.0;

    double tolerance(double dt) const {
        return fixed_tolerance > 0.0 ? fixed_tolerance
                                     : std::max(least_tolerance, tolerance_rate * dt);
    }
};

// Scratch and history of the structured solve: sized on first use for a cloth (rows x
// cols), so no step allocates after the first.
struct ImplicitGridSolver {
    int rows = 0, cols = 0;
    std::size_t pad = 0;     // floats of zeros before and after every array
    std::size_t stride = 0;  // floats per array
    std::vector<float> storage;
    std::vector<double> row_sums;     // 3 per row
    std::vector<Vec3> forces;         // N, f(x_k, v_k)
    std::vector<Vec3> first_iterate;  // m/s, v_k of a step with contacts
    std::vector<std::uint8_t> fixed;  // 1 where a pin or the hand fixes a particle
    std::vector<Vec3> zero_velocities;
    std::vector<Vec3> judged_positions;  // m, where the early judgement sees the step end
    implicit_kernel::Job job;
    ImplicitMultilevel multilevel;
    ImplicitContacts contacts;
    bool has_previous_change = false;  // guess_change holds a previous step's Δv
    // How the last solve went: iterations, residual, and whether it held particles on
    // solids' surfaces.
    bool last_held_contacts = false;
    int last_iterations = 0;
    bool last_rejected_early = false;  // the early judgement rejected the try
    double last_relative_residual = 0.0;

    ImplicitGridSolver() = default;
    // Copies (snapshots, runs side by side) keep the history, so a copy steps exactly as
    // the original would; the job's pointers are re-aimed at the copy's own storage.
    ImplicitGridSolver(const ImplicitGridSolver& other);
    ImplicitGridSolver& operator=(const ImplicitGridSolver& other);

    void prepare(int grid_rows, int grid_cols);  // sizes everything; keeps history if same

  private:
    void bind();  // points the job's arrays into storage
};

// Where a linearised step takes the forces and their Jacobians: the velocities v_k of a
// Newton iterate of the backward Euler system and the positions x_k = x0 + h v_k they reach
// (pinned particles stay at x0). The first iterate is v_k = v0, the inertial prediction.
struct ImplicitLinearisation {
    std::span<const Vec3> velocities;  // m/s, v_k; empty: the cloth's own (v0)
    std::span<Vec3> positions;         // m, out: x_k, one per particle
    // The early judgement (ImplicitSolveSettings::early_judgement), when set: called with
    // the cloth's positions where the solve so far would end the step, true if such a step
    // would be kept.
    bool (*judge)(const void* context) = nullptr;
    const void* judge_context = nullptr;
};

// x_k = x0 + h v_k into `positions`: the cloth's positions moved by `velocities` over dt,
// except the pinned particles (the hand's are free particles whose v_k is the hand's).
void positions_at_iterate(const Cloth& cloth, std::span<const Vec3> velocities, double dt,
                          std::span<Vec3> positions);

// One implicit Euler step of the structured solve, or false, touching nothing, when it
// cannot take it: no usable grid stencil, or repulsion contacts (forces the general path
// takes explicitly). Particles about to meet the field's impulse solids are held on their
// surfaces inside the solve (implicit_contacts.h). `times`, when given, gains the step's
// phases.
// `level`: the build of its row kernels (kernel_build.h); every build gives the same bits.
bool step_implicit_euler_grid(Cloth& cloth, const ForceField& field, double dt,
                              const ImplicitSolveSettings& settings, ImplicitGridSolver& solver,
                              WorkerPool* pool, SimdLevel level,
                              const ImplicitLinearisation& linearisation,
                              ImplicitPhaseTimes* times = nullptr);

}  // namespace weft
