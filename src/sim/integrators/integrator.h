// Integrators: one function per method, all with the same signature, all sharing the force
// pass. Each advances cloth.positions and cloth.velocities by one step of dt seconds.
//
// Pinned particles have zero inverse mass, so every method leaves them exactly in place
// with zero velocity.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "sim/core/cloth.h"
#include "sim/core/force_pass.h"
#include "sim/core/simulation_options.h"
#include "sim/core/step_profile.h"
#include "sim/grid/grid_force_pass.h"
#include "sim/integrators/implicit/implicit_grid_solve.h"
#include "sim/scene/scene.h"

namespace weft {

// Implicit Euler's per-spring share of h² K + h C: the 3x3 block is
// isotropic · I + along · u uᵀ (see implicit_euler.cpp).
struct ImplicitSpringTerms {
    Vec3 direction{0.0};     // u, unit, from i to j
    double isotropic = 0.0;  // h² k max(0, 1 - L/l)
    double along = 0.0;      // h² (k - that) + h c
};

inline constexpr double implicit_cg_tolerance = 1e-8;  // relative residual |A Δv - b| / |b|
inline constexpr int implicit_cg_max_iterations = 500;

// How the methods compute: chosen by the caller, read by every step.
struct IntegratorSettings {
    WorkerPool* pool = nullptr;      // threads for the force pass (owned by Simulation)
    SimulationOptions options;       // the kernel build and the paths taken on grids
    ImplicitSolveSettings implicit;  // when implicit Euler's solve stops
    bool profiling = false;          // implicit Euler times its phases into the statistics
};

// What some methods carry from one step to the next.
struct IntegratorHistory {
    // False whenever the carried history no longer belongs to the current state and dt: at
    // the start, after a change of dt or integrator, or after the state was edited (a drag).
    bool valid = false;
    std::vector<Vec3> accelerations;       // m/s², a_n (velocity Verlet)
    std::vector<Vec3> previous_positions;  // m, x_{n-1} (position Verlet)
    int implicit_start_depth = 0;          // implicit Euler's next step starts as 2^depth pieces
};

// Each method's scratch arrays, sized by IntegratorWorkspace::resize for one method only.
struct IntegratorScratch {
    std::vector<Vec3> forces;             // N, output of the last force evaluation
    std::vector<Vec3> stage_positions;    // m, RK4 stage state; velocity Verlet's prediction
    std::vector<Vec3> stage_velocities;   // m/s
    std::vector<Vec3> position_rate_sum;  // m/s, RK4's weighted sum k1 + 2 k2 + 2 k3 + k4
    std::vector<Vec3> velocity_rate_sum;  // m/s²
    // The fused grid step's output, swapped with the cloth's state after each step.
    std::vector<Vec3> next_positions;   // m
    std::vector<Vec3> next_velocities;  // m/s
    // Where each particle started a step that was not fused, when the caller asks (sized on
    // first use).
    std::vector<Vec3> start_positions;  // m
    // Implicit Euler (allocated on its first step): the solution Δv (kept: the warm start),
    // right-hand side, CG vectors and per-spring terms of the general path; the structured
    // solve (implicit_grid_solve.h), used where the cloth is a grid, with its own warm start;
    // the start of the step being taken, for a split or a Newton iteration to go back to; the
    // state a linearised step is taken at (implicit_grid_solve.h: ImplicitLinearisation).
    std::vector<Vec3> implicit_delta_v, implicit_rhs, implicit_residual, implicit_direction,
        implicit_product;
    std::vector<ImplicitSpringTerms> implicit_springs;
    ImplicitGridSolver implicit_grid;
    std::vector<Vec3> implicit_step_start_positions, implicit_step_start_velocities;
    std::vector<Vec3> implicit_linearised_positions, implicit_linearised_velocities;
};

// What the steps did, for the caller to report.
struct IntegratorStatistics {
    std::uint64_t force_evaluations = 0;  // total calls of the force pass, for cost studies
    // Implicit Euler's last step: CG iterations over all its pieces, times it was halved
    // and linearised again (implicit_euler.cpp), the relative residual of its last solve, and, when
    // profiling, its phases summed over its pieces.
    int implicit_iterations = 0;
    int implicit_splits = 0;
    int implicit_newton_iterations = 0;    // linearised again where a piece ended
    int implicit_tries_stopped_early = 0;  // failed at the early judgement (implicit_grid_solve.h)
    bool implicit_hand_let_go = false;     // a held step stopped where its grip slipped
    double implicit_relative_residual = 0.0;
    ImplicitPhaseTimes implicit_times;
};

// Work a fused grid step does on its way (grid_force_pass.h), while the particles are in
// cache: what the caller asks for before the step, and what the step did.
struct OnTheWay {
    // Asked: the divergence guard's sweep of the new state; work on each band of rows as it
    // is stepped; the positions each particle started from.
    std::optional<SweepRequest> sweep_request;
    const RowsSteppedWork* after_rows = nullptr;
    bool keep_start_positions = false;
    // Done: the sweep, if the step did it; whether after_rows ran over every particle; the
    // start positions, if asked (in the fused step's buffer, or copied before the step).
    std::optional<ParticleSweep> sweep_result;
    bool rows_done = false;
    std::span<const Vec3> start_positions;
};

// Everything the methods read and write besides the cloth, sized once (resize), so no
// method allocates inside a step.
struct IntegratorWorkspace {
    IntegratorSettings settings;
    IntegratorHistory history;
    IntegratorScratch scratch;
    IntegratorStatistics statistics;
    OnTheWay on_the_way;

    // Sizes the arrays `integrator` steps with for `particle_count` particles (zeroed) and
    // frees every other method's, so a workspace, and each copy of it (a snapshot, a run side
    // by side), holds one method's scratch only. Carried history becomes invalid.
    void resize(std::size_t particle_count, Integrator integrator);
};

// Runs body(begin, end) over the particles [0, count), split between the pool's threads when
// there are enough particles to pay for the hand-off. For the integrators' element-wise
// loops (each particle reads and writes only its own entries) the result is the same bit
// for bit whatever the split.
inline constexpr std::size_t min_particles_for_parallel_loops = 4096;
template <class Body>
void for_particle_ranges(const IntegratorWorkspace& work, std::size_t count, Body&& body) {
    WorkerPool* pool = work.settings.pool;
    if (pool && pool->thread_count() > 1 && count >= min_particles_for_parallel_loops)
        pool->parallel_for(count, body);
    else if (count > 0)
        body(std::size_t{0}, count);
}

// Runs the force pass into work.scratch.forces and counts it.
void evaluate_forces(const Cloth& cloth, const ForceField& field, std::span<const Vec3> positions,
                     std::span<const Vec3> velocities, IntegratorWorkspace& work);

using StepFunction = void (*)(Cloth& cloth, const ForceField& field, double dt,
                              IntegratorWorkspace& work);

void step_explicit_euler(Cloth& cloth, const ForceField& field, double dt,
                         IntegratorWorkspace& work);
void step_symplectic_euler(Cloth& cloth, const ForceField& field, double dt,
                           IntegratorWorkspace& work);
// The same step when the fused grid pass can take it (grid_force_pass.h); false, touching
// nothing, when it cannot. After a true, work.scratch.next_positions holds the positions the step
// started from (the pass's output buffer, swapped with the cloth's): a caller that needs
// them reads them there instead of copying them first. `after_rows`: work for each thread
// on the rows it has just stepped (grid_force_pass.h).
bool step_symplectic_euler_fused(Cloth& cloth, const ForceField& field, double dt,
                                 IntegratorWorkspace& work,
                                 const RowsSteppedWork* after_rows = nullptr);
void step_verlet(Cloth& cloth, const ForceField& field, double dt, IntegratorWorkspace& work);
void step_velocity_verlet(Cloth& cloth, const ForceField& field, double dt,
                          IntegratorWorkspace& work);
void step_rk4(Cloth& cloth, const ForceField& field, double dt, IntegratorWorkspace& work);
void step_implicit_euler(Cloth& cloth, const ForceField& field, double dt,
                         IntegratorWorkspace& work);

// One step of `integrator`, with what work.on_the_way asks done on the way: by the fused grid
// step where symplectic Euler can take it, else around the method's own step.
void integrate(Integrator integrator, Cloth& cloth, const ForceField& field, double dt,
               IntegratorWorkspace& work);

// y = (M + h C + h² K) v for the terms of the last implicit step, the entries of pinned
// particles and of those in `held` (the hand's) zero.
void multiply_implicit_system(const Cloth& cloth, const IntegratorWorkspace& work, double air_drag,
                              double dt, std::span<const Vec3> vector, std::span<Vec3> product,
                              std::span<const std::uint32_t> held = {});

// The largest error of an implicit step's linearisation over the springs that end it
// longer than `ratio` rest lengths, in rest lengths (implicit_euler.cpp); `start`: the
// positions the step was linearised at. Spring by spring over the cloth's springs; the
// stencil's grid_linearisation_error gives the same number.
double largest_linearisation_error(const Cloth& cloth, std::span<const Vec3> start, double ratio,
                                   WorkerPool* pool);

// The step function of a method.
StepFunction step_function(Integrator integrator);

// Force evaluations one step costs (the first step of the Verlets costs one more; implicit
// Euler's CG iterations each cost about two force passes on top).
int force_evaluations_per_step(Integrator integrator);

}  // namespace weft
