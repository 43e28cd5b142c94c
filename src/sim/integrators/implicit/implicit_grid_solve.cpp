#include "sim/integrators/implicit/implicit_grid_solve.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <glm/geometric.hpp>

#include "sim/core/force_pass.h"
#include "sim/grid/grid_force_pass.h"

namespace weft {
namespace {

// Rows are split between threads only when there are enough particles to pay for the
// hand-offs (four per iteration).
constexpr std::size_t min_particles_for_threads = 4096;

// Runs pass(begin, end) over the rows, split between the pool's threads when worth it, in
// whole pairs of rows: the update pass sums each pair into the first coarse level.
template <class Pass>
void over_rows(const ImplicitGridSolver& solver, WorkerPool* pool, Pass&& pass) {
    const auto count =
        static_cast<std::size_t>(solver.rows) * static_cast<std::size_t>(solver.cols);
    if (pool && pool->thread_count() > 1 && count >= min_particles_for_threads)
        pool->parallel_for(static_cast<std::size_t>((solver.rows + 1) / 2), [&](std::size_t begin,
                                                                                std::size_t end) {
            pass(static_cast<int>(2 * begin), std::min(static_cast<int>(2 * end), solver.rows));
        });
    else
        pass(0, solver.rows);
}

// Σ over rows, in row order: the same sum whatever rows each thread had.
double sum_rows(const double* per_row, int rows) {
    double sum = 0.0;
    for (int row = 0; row < rows; ++row) sum += per_row[row];
    return sum;
}

double largest_of_rows(const double* per_row, int rows) {
    double largest = 0.0;
    for (int row = 0; row < rows; ++row) largest = std::max(largest, per_row[row]);
    return largest;
}

}  // namespace

void ImplicitGridSolver::prepare(int grid_rows, int grid_cols) {
    if (grid_rows == rows && grid_cols == cols && !storage.empty()) return;
    rows = grid_rows;
    cols = grid_cols;
    const std::size_t count = static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols);
    // Two rows and two columns either way, rounded to whole vectors of sixteen floats.
    pad = (2 * static_cast<std::size_t>(cols) + 2 + 15) / 16 * 16;
    stride = (count + 2 * pad + 15) / 16 * 16;
    constexpr int arrays = 4 * implicit_kernel::max_directions + 2 + 6 + 6 + 11 * 3;
    storage.assign(stride * arrays, 0.0f);
    row_sums.assign(4 * static_cast<std::size_t>(rows), 0.0);
    forces.assign(count, Vec3(0.0));
    first_iterate.assign(count, Vec3(0.0));
    judged_positions.assign(count, Vec3(0.0));
    fixed.assign(count, 0);
    has_previous_change = false;
    contacts.held.clear();  // their particles belonged to the old grid
    job = implicit_kernel::Job{};
    bind();
}

ImplicitGridSolver::ImplicitGridSolver(const ImplicitGridSolver& other) {
    *this = other;  // one list of what a copy takes: the assignment's
}

ImplicitGridSolver& ImplicitGridSolver::operator=(const ImplicitGridSolver& other) {
    if (this == &other) return *this;
    rows = other.rows;
    cols = other.cols;
    pad = other.pad;
    stride = other.stride;
    storage = other.storage;
    row_sums = other.row_sums;
    forces = other.forces;
    first_iterate = other.first_iterate;
    fixed = other.fixed;
    job = other.job;
    multilevel = other.multilevel;
    contacts = other.contacts;
    has_previous_change = other.has_previous_change;
    last_held_contacts = other.last_held_contacts;
    last_iterations = other.last_iterations;
    last_rejected_early = other.last_rejected_early;
    judged_positions.resize(other.judged_positions.size());  // scratch: its size only
    last_relative_residual = other.last_relative_residual;
    if (!storage.empty()) bind();
    return *this;
}

void ImplicitGridSolver::bind() {
    float* next = storage.data();
    auto take = [&] {
        float* array = next;
        next += stride;
        return array;
    };
    auto take3 = [&] { return implicit_kernel::Field3{take(), take(), take()}; };
    job.rows = rows;
    job.cols = cols;
    job.pad = pad;
    for (implicit_kernel::DirectionTerms& d : job.directions) {
        d.iso = take();
        d.axial_x = take();
        d.axial_y = take();
        d.axial_z = take();
    }
    job.mass_diagonal = take();
    job.free = take();
    for (float*& e : job.diagonal) e = take();
    for (float*& e : job.inverse_diagonal) e = take();
    job.rhs_change = take3();
    job.rhs = take3();
    job.start = take3();
    job.guess_change = take3();
    job.solution = take3();
    job.residual = take3();
    job.preconditioned = take3();
    job.direction = take3();
    job.applied = take3();
    job.product = take3();
    job.contact_normal = take3();
}

void positions_at_iterate(const Cloth& cloth, std::span<const Vec3> velocities, double dt,
                          std::span<Vec3> positions) {
    const std::vector<double>& inverse_masses = cloth.topology().inverse_masses;
    for (std::size_t p = 0; p < cloth.particle_count(); ++p)
        positions[p] =
            inverse_masses[p] != 0.0 ? cloth.positions[p] + dt * velocities[p] : cloth.positions[p];
}

bool step_implicit_euler_grid(Cloth& cloth, const ForceField& field, double dt,
                              const ImplicitSolveSettings& settings, ImplicitGridSolver& solver,
                              WorkerPool* pool, SimdLevel level,
                              const ImplicitLinearisation& linearisation,
                              ImplicitPhaseTimes* times) {
    if (!field.colliders.empty() || !grid_stencil_usable(cloth)) return false;
    if (cloth.topology().grid_stencil.directions.size() > implicit_kernel::max_directions)
        return false;
    ImplicitPhaseTimes unused;
    ImplicitPhaseTimes& phases = times ? *times : unused;
    PhaseClock clock(times != nullptr);
    solver.prepare(cloth.rows, cloth.cols);
    solver.last_rejected_early = false;
    implicit_kernel::Job& job = solver.job;
    // The state the step is linearised at, x_k = x0 + h v_k (pins stay put), and the forces
    // there, f(x_k, v_k): gravity, the wind, air drag, the springs and their dampers.
    std::span<const Vec3> at_velocities = linearisation.velocities.empty()
                                              ? std::span<const Vec3>(cloth.velocities)
                                              : linearisation.velocities;
    const std::span<Vec3> at_positions = linearisation.positions;
    const std::size_t count = cloth.particle_count();
    const double* inverse_masses = cloth.topology().inverse_masses.data();
    // Particles about to meet the solids (implicit_contacts.h), of those the pins and the
    // hand leave free, chosen from the step's start. A step that holds some is linearised at
    // x0 (the first iterate v_k = 0 for every free particle): predicted at x0 + h v0, the
    // sheet beside the particles a surface stops is seen still falling, several spacings
    // away from them, and a sheet landing on a ball gained energy.
    const bool contacts = !field.solids.empty() || !solver.contacts.held.empty();
    if (contacts) {
        for (std::size_t p = 0; p < count; ++p) solver.fixed[p] = inverse_masses[p] == 0.0;
        for (const std::uint32_t p : field.held) solver.fixed[p] = 1;
        solver.contacts.choose(cloth, field.solids, field.gravity, dt, solver.fixed, job);
        if (!solver.contacts.held.empty() && linearisation.velocities.empty()) {
            for (std::size_t p = 0; p < count; ++p)
                solver.first_iterate[p] = solver.fixed[p] ? at_velocities[p] : Vec3(0.0);
            at_velocities = solver.first_iterate;
        }
    }
    positions_at_iterate(cloth, at_velocities, dt, at_positions);
    if (!accumulate_grid_forces(cloth, field, at_positions, at_velocities, solver.forces, pool,
                                level))
        return false;
    job.dt = dt;
    job.air_drag = field.air_drag;
    job.direction_count = 0;
    for (const GridStencilDirection& direction : cloth.topology().grid_stencil.directions) {
        const SpringGroup& group = cloth.topology().spring_groups[direction.group];
        implicit_kernel::DirectionTerms& d = job.directions[job.direction_count++];
        d.row_step = direction.row_step;
        d.col_step = direction.col_step;
        d.stiffness = group.stiffness;
        d.damping = group.damping;
        d.rest_lengths = direction.rest_lengths.data();
    }
    // Directions the cloth no longer has must not leave old terms behind.
    for (int k = job.direction_count; k < implicit_kernel::max_directions; ++k) {
        implicit_kernel::DirectionTerms& d = job.directions[k];
        for (float* array : {d.iso, d.axial_x, d.axial_y, d.axial_z})
            std::fill(array, array + solver.stride, 0.0f);
    }
    job.positions = &at_positions.data()->x;
    job.velocities = &at_velocities.data()->x;
    job.initial_velocities = &cloth.velocities.data()->x;
    // The solve starts from v0 and the warm start on a first iterate, from v_k on a later one.
    job.linearised_at_start = at_velocities.data() != solver.first_iterate.data();
    job.start_velocities =
        linearisation.velocities.empty() ? &cloth.velocities.data()->x : &at_velocities.data()->x;
    job.forces = &solver.forces.data()->x;
    job.masses = cloth.topology().masses.data();
    job.inverse_masses = cloth.topology().inverse_masses.data();

    const double warm_start =
        settings.warm_start && solver.has_previous_change && linearisation.velocities.empty() ? 1.0
                                                                                              : 0.0;
    const auto setup =
        kernel_of(level, implicit_kernel::setup_rows_baseline, implicit_kernel::setup_rows_avx2,
                  implicit_kernel::setup_rows_avx512);
    over_rows(solver, pool, [&](int begin, int end) { setup(job, begin, end, warm_start); });
    // Particles in the hand (grab.h): constrained, with their velocities prescribed (Baraff &
    // Witkin's z). Filtered out like pins, but their velocity stays in the vector the solve
    // multiplies, so every free neighbour's row sees where the hand takes them.
    for (const std::uint32_t p : field.held) {
        const std::size_t i = solver.pad + p;
        const Vec3& v = cloth.velocities[p];
        job.free[i] = 0.0f;
        job.rhs_change.x[i] = job.rhs_change.y[i] = job.rhs_change.z[i] = 0.0f;
        job.start.x[i] = job.solution.x[i] = static_cast<float>(v.x);
        job.start.y[i] = job.solution.y[i] = static_cast<float>(v.y);
        job.start.z[i] = job.solution.z[i] = static_cast<float>(v.z);
    }
    // The particles held on the solids' surfaces: before the residual pass, whose
    // preconditioner is filtered for them.
    if (contacts) solver.contacts.hold(job);
    solver.last_held_contacts = job.has_contacts;

    const int rows = solver.rows;
    double* sums = solver.row_sums.data();
    const implicit_kernel::RowSums row_sums{sums, sums + rows, sums + 2 * rows, sums + 3 * rows};
    const auto residual =
        kernel_of(level, implicit_kernel::residual_rows_baseline,
                  implicit_kernel::residual_rows_avx2, implicit_kernel::residual_rows_avx512);
    const auto direction =
        kernel_of(level, implicit_kernel::direction_rows_baseline,
                  implicit_kernel::direction_rows_avx2, implicit_kernel::direction_rows_avx512);
    const auto update =
        kernel_of(level, implicit_kernel::update_rows_baseline, implicit_kernel::update_rows_avx2,
                  implicit_kernel::update_rows_avx512);
    const auto smooth =
        kernel_of(level, implicit_kernel::smooth_rows_baseline, implicit_kernel::smooth_rows_avx2,
                  implicit_kernel::smooth_rows_avx512);
    const bool multilevel = settings.multilevel;
    job.flexible = false;  // until the coarse levels are built with a K-cycle
    // The local bound (ImplicitSolveSettings): the largest velocity error a particle may
    // keep, by the block-Jacobi estimate. Not for a fixed tolerance, which studies ask for
    // alone.
    const bool bound_locally =
        settings.fixed_tolerance <= 0.0 && settings.position_tolerance > 0.0 && cloth.spacing > 0.0;
    const double largest_velocity_error = settings.position_tolerance * cloth.spacing / dt;
    int iteration = 0;
    double r_r = 0.0, scale = 0.0;

    // A particle's velocity at the end of the step: the solution where it is free, the
    // prescribed velocity where the hand or a pin fixes it.
    auto end_velocity = [&](std::size_t i) {
        return job.free[i] != 0.0f ? Vec3(job.solution.x[i], job.solution.y[i], job.solution.z[i])
                                   : Vec3(job.start.x[i], job.start.y[i], job.start.z[i]);
    };
    // The early judgement (ImplicitSolveSettings::early_judgement) of the solve so far: the
    // cloth is shown where it would end the step, x0 + h v1, and put back. Nothing the
    // solve holds changes, so a try judged kept goes on exactly as if never stopped.
    auto judged_kept = [&] {
        std::vector<Vec3>& ends = solver.judged_positions;
        over_rows(solver, pool, [&](int begin, int end) {
            for (std::size_t p = static_cast<std::size_t>(begin) * solver.cols;
                 p < static_cast<std::size_t>(end) * solver.cols; ++p)
                ends[p] = cloth.positions[p] + dt * end_velocity(solver.pad + p);
        });
        cloth.positions.swap(ends);
        const bool kept = linearisation.judge(linearisation.judge_context);
        cloth.positions.swap(ends);
        return kept;
    };

    // Preconditioned conjugate gradient (block Jacobi plus the coarse levels), in single
    // precision; the scalars and every sum in double; from the guess in job.solution.
    auto solve = [&](bool first_round) {
        ImplicitMultilevel::detach(job);
        over_rows(solver, pool, [&](int begin, int end) { residual(job, begin, end, row_sums); });
        clock.lap(phases.setup);
        double r_z = sum_rows(row_sums.first, rows);
        r_r = sum_rows(row_sums.second, rows);
        double largest_z = largest_of_rows(row_sums.largest, rows);
        if (multilevel) {
            // The coarse levels need the fine diagonal blocks of the pass just run (the
            // same in every round); from here on the update passes restrict their residual
            // into the first level on the way.
            if (first_round) {
                solver.multilevel.build(job, settings.coarse_cycle, pool, level);
                job.flexible = solver.multilevel.uses_k_cycle;
                clock.lap(phases.coarse_levels);
            }
            r_z += solver.multilevel.apply(job, false, pool);
            solver.multilevel.attach(job);
        }
        scale = std::sqrt(sum_rows(row_sums.third, rows));
        const double target = settings.tolerance(dt) * scale;
        for (float* array : {job.direction.x, job.direction.y, job.direction.z, job.product.x,
                             job.product.y, job.product.z})
            std::fill(array, array + solver.stride, 0.0f);
        double beta = 0.0;
        auto within = [&](double factor) {
            return std::sqrt(r_r) <= factor * target &&
                   (!bound_locally || std::sqrt(largest_z) <= factor * largest_velocity_error);
        };
        // Judged early only on the first round, without contacts: the contacts' rounds
        // change the system itself.
        bool judge_early = first_round && linearisation.judge && !job.has_contacts &&
                           settings.early_judgement > 1.0;
        while (!within(1.0) && iteration < settings.max_iterations) {
            if (judge_early && within(settings.early_judgement)) {
                judge_early = false;
                if (!judged_kept()) {
                    solver.last_rejected_early = true;
                    break;
                }
            }
            const auto beta_f = static_cast<float>(beta);
            over_rows(solver, pool,
                      [&](int begin, int end) { direction(job, begin, end, beta_f, row_sums); });
            const double curvature = sum_rows(row_sums.first, rows);
            if (!(curvature > 0.0)) break;  // not positive definite (or NaN): the guard will see
            const auto alpha_f = static_cast<float>(r_z / curvature);
            over_rows(solver, pool,
                      [&](int begin, int end) { update(job, begin, end, alpha_f, row_sums); });
            double next_r_z = sum_rows(row_sums.first, rows);
            if (multilevel) next_r_z += solver.multilevel.apply(job, true, pool);
            r_r = sum_rows(row_sums.second, rows);
            largest_z = largest_of_rows(row_sums.largest, rows);
            // Flexible (Polak-Ribière) where the preconditioner varies with r: β =
            // r_new · (z_new - z_old) / r_old · z_old, which is Fletcher-Reeves' for a fixed one.
            const double new_old = job.flexible ? sum_rows(row_sums.third, rows) : 0.0;
            beta = r_z > 0.0 ? (next_r_z - new_old) / r_z : 0.0;
            r_z = next_r_z;
            ++iteration;
        }
        // The damped block-Jacobi step after the iterations (ImplicitSolveSettings).
        if (settings.post_smoothing > 0.0) {
            const auto omega = static_cast<float>(settings.post_smoothing);
            over_rows(solver, pool, [&](int begin, int end) { smooth(job, begin, end, omega); });
        }
        clock.lap(phases.iterations);
    };
    solve(true);
    if (job.has_contacts) {
        // The surfaces' impulses: where one pulled, its particle is let go and the step
        // solved again from where it stands (implicit_contacts.h); then friction.
        const auto unfiltered = kernel_of(level, implicit_kernel::unfiltered_product_rows_baseline,
                                          implicit_kernel::unfiltered_product_rows_avx2,
                                          implicit_kernel::unfiltered_product_rows_avx512);
        // applied = A (v1 - v_k), unfiltered; the search direction is free after a solve.
        auto impulses = [&] {
            const implicit_kernel::Field3 &change = job.direction, &v1 = job.solution,
                                          &vs = job.start;
            const float at_start = job.linearised_at_start ? 1.0f : 0.0f;  // v_k = v_s, or 0
            for (std::size_t i = 0; i < solver.stride; ++i) {
                change.x[i] = v1.x[i] - at_start * vs.x[i];
                change.y[i] = v1.y[i] - at_start * vs.y[i];
                change.z[i] = v1.z[i] - at_start * vs.z[i];
            }
            over_rows(solver, pool, [&](int begin, int end) { unfiltered(job, begin, end); });
        };
        impulses();
        if (solver.contacts.let_go_of_pulled(job) > 0) {
            solve(false);
            if (job.has_contacts) impulses();
        }
        solver.contacts.apply_friction(cloth, job);
    }
    solver.last_iterations = iteration;
    solver.last_relative_residual = scale > 0.0 ? std::sqrt(r_r) / scale : 0.0;
    clock.lap(phases.setup);  // the contacts' impulses and friction, when there are any

    // v1 = the solution, x1 = x0 + h v1; pinned particles stay where they are, held ones go
    // where the hand takes them. The warm start keeps the whole step's change, v1 - v0.
    over_rows(solver, pool, [&](int begin, int end) {
        for (int row = begin; row < end; ++row) {
            for (int c = 0; c < solver.cols; ++c) {
                const std::size_t p = static_cast<std::size_t>(row) * solver.cols + c;
                const std::size_t i = solver.pad + p;
                const bool is_free = job.free[i] != 0.0f;
                const Vec3 v1 = end_velocity(i);
                const Vec3 v0 = cloth.velocities[p];
                const float keep = is_free ? 1.0f : 0.0f;
                job.guess_change.x[i] = keep * (job.solution.x[i] - static_cast<float>(v0.x));
                job.guess_change.y[i] = keep * (job.solution.y[i] - static_cast<float>(v0.y));
                job.guess_change.z[i] = keep * (job.solution.z[i] - static_cast<float>(v0.z));
                cloth.velocities[p] = v1;
                cloth.positions[p] += dt * v1;
            }
        }
    });
    clock.lap(phases.setup);
    solver.has_previous_change = true;
    return true;
}

}  // namespace weft
