// Implicit (backward) Euler, M (v1 - v0) = h f(x0 + h v1, v1), by Newton's method on v1
// (Baraff & Witkin 1998 take one iteration from x0). Each iteration linearises the forces at
// an iterate v_k, at the positions x_k = x0 + h v_k it reaches:
//
//   (M - h ∂f/∂v - h² ∂f/∂x) (v1 - v_k) = h f(x_k, v_k) - M (v_k - v0),   x1 = x0 + h v1
//
// The first iterate is v_k = v0: the forces and their stiffness are taken where the cloth
// would be if nothing acted on it, x0 + h v0, so a sheet moving as a whole, falling or
// carried by the hand, is linearised close to where it ends (from x0, a spring carried
// sideways at its rest length shows no stiffness across itself). Exact for linear springs,
// whatever the iterate, so unconditionally stable on them; first order; it damps motion
// (numerical dissipation grows with h ω). Further iterations only where the first leaves a
// large error (step_or_split below).
//
// The Jacobians, per spring with d = x_j - x_i, l = |d|, u = d / l:
//   ∂f_i/∂x_j = k [u uᵀ + (1 - L/l)(I - u uᵀ)],   ∂f_i/∂v_j = c u uᵀ,
// with ∂f_i/∂x_i, ∂f_i/∂v_i their negatives; air drag adds -air_drag I to ∂f/∂v. The
// transverse term (1 - L/l) is clamped at 0 for compressed springs: negative, it makes the
// system indefinite and conjugate gradient unreliable (Choi & Ko 2002 discuss the buckling
// behind it). Repulsion contacts are taken explicitly, in f(x_k, v_k). The hand's particles
// (grab.h) are constrained: their velocities are prescribed, filtered like pins.
//
// The system matrix A = M + h C + h² K is symmetric positive definite; it is never
// assembled. Conjugate gradient multiplies by it spring by spring, with pinned particles
// filtered out of every vector (Baraff & Witkin's constraint filter for fully constrained
// particles), warm-started from the previous step's Δv on a first iterate, until the
// residual is below implicit_cg_tolerance × |b| or implicit_cg_max_iterations is reached.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "sim/core/chunked_reduce.h"
#include "sim/guards/divergence.h"
#include "sim/integrators/integrator.h"

namespace weft {
namespace {

double inner(std::span<const Vec3> a, std::span<const Vec3> b) {
    double sum = 0.0;
    for (std::size_t p = 0; p < a.size(); ++p) sum += glm::dot(a[p], b[p]);
    return sum;
}

}  // namespace

void multiply_implicit_system(const Cloth& cloth, const IntegratorWorkspace& work, double air_drag,
                              double dt, std::span<const Vec3> vector, std::span<Vec3> product,
                              std::span<const std::uint32_t> held) {
    const std::size_t count = cloth.particle_count();
    for (std::size_t p = 0; p < count; ++p)
        product[p] = (cloth.topology().masses[p] + dt * air_drag) * vector[p];
    std::size_t s = 0;
    for (const SpringGroup& group : cloth.topology().spring_groups) {
        for (const Spring& spring : group.springs) {
            const ImplicitSpringTerms& terms = work.scratch.implicit_springs[s++];
            // (h² K + h C) applied to the relative vector of the two ends.
            const Vec3 relative = vector[spring.i] - vector[spring.j];
            const Vec3 block =
                terms.isotropic * relative +
                (terms.along * glm::dot(terms.direction, relative)) * terms.direction;
            product[spring.i] += block;
            product[spring.j] -= block;
        }
    }
    for (std::uint32_t p : cloth.topology().pinned) product[p] = Vec3(0.0);
    for (std::uint32_t p : held) product[p] = Vec3(0.0);
}

// The largest error of the step's linearisation over the springs that end the step longer
// than `ratio` rest lengths, in rest lengths: for each, how far its force at the end of the
// step, k (|d1| - L) d1 / |d1|, is from what the step assumed, f(d0) + K(d0) (d1 - d0) (K as
// in the header, a compressed spring's negative transverse term left out as in the step),
// divided by k L. `start`: the positions x_k the step was linearised at.
//
// Shorter springs are left out. A compressed spring's force is at most k L, so its error
// cannot run away, but it is large by design where a fold turns one over (the step drops its
// negative transverse term); counted, the bend springs in a fold kept a sheet under the hand
// splitting to the deepest level on most steps without the split changing anything.
double largest_linearisation_error(const Cloth& cloth, std::span<const Vec3> start, double ratio,
                                   WorkerPool* pool) {
    double largest = 0.0;
    for (const SpringGroup& group : cloth.topology().spring_groups)
        largest = reduce_in_chunks(
            pool, group.springs.size(), largest,
            [&](std::size_t begin, std::size_t end) {
                double part = 0.0;
                for (std::size_t k = begin; k < end; ++k) {
                    const Spring& spring = group.springs[k];
                    const Vec3 before = start[spring.j] - start[spring.i];
                    const Vec3 after = cloth.positions[spring.j] - cloth.positions[spring.i];
                    const double l0 = glm::length(before), l1 = glm::length(after);
                    if (!(l0 > 0.0) || !(l1 > ratio * spring.rest_length)) continue;
                    const Vec3 u = before / l0, change = after - before;
                    const double along = glm::dot(u, change);
                    const double transverse = std::max(0.0, 1.0 - spring.rest_length / l0);
                    const Vec3 assumed = (l0 - spring.rest_length) * u + along * u +
                                         transverse * (change - along * u);
                    const Vec3 actual = (l1 - spring.rest_length) / l1 * after;
                    part = std::max(part, glm::length(actual - assumed) / spring.rest_length);
                }
                return part;
            },
            [](double a, double b) { return std::max(a, b); });
    return largest;
}

namespace {

// One linearised step of dt from the cloth's state, linearised at `at`, by the structured
// solve where the cloth is a grid, else by the general one below. Returns whether it held
// particles on solids' surfaces (the structured solve's contacts).
bool take_linearised_step(Cloth& cloth, const ForceField& field, double dt,
                          IntegratorWorkspace& work, const ImplicitLinearisation& at);

// The step of dt, or, when its linearisation fails it, the same step linearised again
// where it ended, or two of dt / 2 (each of which may split again, down to
// dt / 2^max_split_depth). The linearised step sees a spring's stiffness only as it is where
// it is linearised: a spring at its rest length has none across itself, so a flat sheet
// released at dt = 1/30 s falls 2.4 spacings in its first step everywhere but at the pins,
// and the springs beside them come out 2.5 rest lengths long (256², cloth_256 material)
// where the step assumed no force at all; the next steps run away. So a step after which
// some spring is longer than split_stretch_ratio rest lengths (a pass that almost never
// finds one, vectorised) and some spring's force is further than split_force_error × k L
// from what the step assumed is not kept. First it is taken again from the same start,
// linearised at the state it reached (a Newton iteration: where the hand flicks the sheet
// back, the springs it whips round are seen stretched), up to newton_iterations times;
// then in halves: the error of the linearisation falls as the square of the step's motion.
// A hand pulling a sheet taut stretches its springs along themselves, where the
// linearisation is close to exact, and is not split. A hand far beyond the sheet's reach
// fails every try, and each half splits again down to the deepest level, dozens of solves
// for a step that is thrown away when the grip slips after it: a try that failed with a
// spring at the hand past the grip ends the step. Returns the depth of the
// finest piece taken.
int step_or_split(Cloth& cloth, const ForceField& field, double dt, IntegratorWorkspace& work,
                  int depth) {
    const ImplicitSolveSettings& settings = work.settings.implicit;
    const bool checked = settings.split_stretch_ratio > 1.0;
    const bool may_split = checked && depth < settings.max_split_depth;
    const std::size_t count = cloth.particle_count();
    IntegratorScratch& scratch = work.scratch;
    scratch.implicit_linearised_positions.resize(count);
    PhaseClock clock(work.settings.profiling);
    double timed_inside = 0.0;  // the linearised step times its own phases
    if (checked) {
        scratch.implicit_step_start_positions.resize(count);
        scratch.implicit_step_start_velocities.resize(count);
        for_particle_ranges(work, count, [&](std::size_t begin, std::size_t end) {
            std::copy(cloth.positions.begin() + begin, cloth.positions.begin() + end,
                      scratch.implicit_step_start_positions.begin() + begin);
            std::copy(cloth.velocities.begin() + begin, cloth.velocities.begin() + end,
                      scratch.implicit_step_start_velocities.begin() + begin);
        });
    }
    auto go_back_to_start = [&] {
        for_particle_ranges(work, count, [&](std::size_t begin, std::size_t end) {
            std::copy(scratch.implicit_step_start_positions.begin() + begin,
                      scratch.implicit_step_start_positions.begin() + end,
                      cloth.positions.begin() + begin);
            std::copy(scratch.implicit_step_start_velocities.begin() + begin,
                      scratch.implicit_step_start_velocities.begin() + end,
                      cloth.velocities.begin() + begin);
        });
    };
    bool held_contacts = false;
    // Whether the step, ended where the cloth now is, is kept (linearised at the positions
    // in scratch.implicit_linearised_positions).
    struct Judgement {
        const Cloth& cloth;
        const IntegratorWorkspace& work;
        // The error is taken over the springs longer than the ratio alone: it is 0 where
        // none is, and the stencil's pass tells that without a square root on almost
        // every row.
        bool kept() const {
            const ImplicitSolveSettings& rule = work.settings.implicit;
            const std::span<const Vec3> start = work.scratch.implicit_linearised_positions;
            WorkerPool* pool = work.settings.pool;
            const std::optional<double> on_stencil = grid_linearisation_error(
                cloth, start, rule.split_stretch_ratio, pool, work.settings.options.kernel_build);
            const double error = on_stencil ? *on_stencil
                                            : largest_linearisation_error(
                                                  cloth, start, rule.split_stretch_ratio, pool);
            return !(error > rule.split_force_error);
        }
    };
    const Judgement judgement{cloth, work};
    // `last`: a try after which a failure leads to no other try (no Newton iteration left and
    // no split), so it is kept whatever its judgement, and must not stop early.
    auto step_linearised_at = [&](std::span<const Vec3> velocities, bool last) {
        clock.lap(work.statistics.implicit_times.split_checks);
        const int iterations_before = work.statistics.implicit_iterations;
        ImplicitLinearisation at{velocities, scratch.implicit_linearised_positions};
        // Judged early where tries fail: under the hand, and on a Newton iteration, which
        // follows a try that failed. A calm step is judged at its end only.
        if (checked && !last && (!field.held.empty() || !velocities.empty())) {
            at.judge = [](const void* context) {
                return static_cast<const Judgement*>(context)->kept();
            };
            at.judge_context = &judgement;
        }
        scratch.implicit_grid.last_rejected_early = false;  // the general solve never is
        held_contacts = take_linearised_step(cloth, field, dt, work, at);
        work.statistics.implicit_iterations += iterations_before;
        clock.lap(timed_inside);
        if (scratch.implicit_grid.last_rejected_early) {
            ++work.statistics.implicit_tries_stopped_early;
            return false;
        }
        const bool kept = !checked || judgement.kept();
        clock.lap(work.statistics.implicit_times.split_checks);
        return kept;
    };
    // The hand's grip (grab.h), judged on a try that failed as the simulation judges it.
    auto grip_slipped = [&] {
        return field.grip_stretch > 0.0 &&
               largest_grip_stretch(field.grip_springs, cloth.positions) > field.grip_stretch;
    };
    bool kept = step_linearised_at({}, !may_split && settings.newton_iterations == 0);
    // Not where the step held particles on solids: each solve settles which of them the
    // surface lets go in one round (implicit_contacts.h), so a sheet pulled off the ground
    // needs the halves' rounds.
    for (int newton = 0; !kept && !held_contacts && newton < settings.newton_iterations; ++newton) {
        ++work.statistics.implicit_newton_iterations;
        scratch.implicit_linearised_velocities.resize(count);
        std::copy(cloth.velocities.begin(), cloth.velocities.end(),
                  scratch.implicit_linearised_velocities.begin());
        go_back_to_start();
        kept = step_linearised_at(scratch.implicit_linearised_velocities,
                                  !may_split && newton + 1 == settings.newton_iterations);
    }
    if (kept || !may_split) return depth;
    // Still failed after its Newton iterations, and past the grip: the hand lets go, and the
    // simulation takes the step again without it, so there is nothing to refine, in this
    // piece or the ones after it. A try that held particles on solids took no Newton
    // iterations, and the halves settle which of them the surface lets go: a hand lifting a
    // sheet off the ground seems past the grip in the whole step and in its halves, and is
    // within it from the quarters on. Such tries are judged from the quarters on.
    if ((!held_contacts || depth > 1) && grip_slipped()) {
        work.statistics.implicit_hand_let_go = true;
        return depth;
    }
    ++work.statistics.implicit_splits;
    go_back_to_start();
    clock.lap(work.statistics.implicit_times.split_checks);
    const int first = step_or_split(cloth, field, 0.5 * dt, work, depth + 1);
    if (work.statistics.implicit_hand_let_go) return first;
    return std::max(first, step_or_split(cloth, field, 0.5 * dt, work, depth + 1));
}

}  // namespace

void step_implicit_euler(Cloth& cloth, const ForceField& field, double dt,
                         IntegratorWorkspace& work) {
    work.statistics.implicit_iterations = 0;
    work.statistics.implicit_splits = 0;
    work.statistics.implicit_newton_iterations = 0;
    work.statistics.implicit_tries_stopped_early = 0;
    work.statistics.implicit_hand_let_go = false;
    // A step-size controller's memory: a step that had to be split is followed by one that
    // starts one level coarser than its finest piece, not by a whole step that would most
    // likely fail again and be thrown away. Each step that needs no split of its own takes
    // the next one level closer to a whole step.
    const int start =
        std::min(work.history.implicit_start_depth, work.settings.implicit.max_split_depth);
    const int pieces = 1 << start;
    int finest = start;
    for (int piece = 0; piece < pieces && !work.statistics.implicit_hand_let_go; ++piece)
        finest = std::max(finest, step_or_split(cloth, field, dt / pieces, work, start));
    // A step the hand let go of is taken again without it: it says nothing of the next.
    if (!work.statistics.implicit_hand_let_go)
        work.history.implicit_start_depth = std::max(0, finest - 1);
}

namespace {

bool take_linearised_step(Cloth& cloth, const ForceField& field, double dt,
                          IntegratorWorkspace& work, const ImplicitLinearisation& at) {
    if (work.settings.options.structured_implicit_solve &&
        step_implicit_euler_grid(
            cloth, field, dt, work.settings.implicit, work.scratch.implicit_grid,
            work.settings.pool, work.settings.options.kernel_build, at,
            work.settings.profiling ? &work.statistics.implicit_times : nullptr)) {
        ++work.statistics.force_evaluations;
        work.statistics.implicit_iterations = work.scratch.implicit_grid.last_iterations;
        work.statistics.implicit_relative_residual =
            work.scratch.implicit_grid.last_relative_residual;
        return work.scratch.implicit_grid.last_held_contacts;
    }
    const std::size_t count = cloth.particle_count();
    work.scratch.implicit_springs.resize(
        cloth.spring_count());  // shrinks with tearing, never grows
    if (work.scratch.implicit_delta_v.size() != count) {
        for (auto* array : {&work.scratch.implicit_delta_v, &work.scratch.implicit_rhs,
                            &work.scratch.implicit_residual, &work.scratch.implicit_direction,
                            &work.scratch.implicit_product})
            array->assign(count, Vec3(0.0));
    }
    // The iterate v_k and the positions it reaches, x_k = x0 + h v_k (pins stay put).
    const bool first_iterate = at.velocities.empty();
    const std::span<const Vec3> vk =
        first_iterate ? std::span<const Vec3>(cloth.velocities) : at.velocities;
    const std::span<Vec3> xk = at.positions;
    positions_at_iterate(cloth, vk, dt, xk);
    evaluate_forces(cloth, field, xk, vk, work);

    // Per-spring terms of h² K + h C at x_k.
    std::size_t s = 0;
    for (const SpringGroup& group : cloth.topology().spring_groups) {
        for (const Spring& spring : group.springs) {
            const Vec3 d = xk[spring.j] - xk[spring.i];
            const double length = glm::length(d);
            ImplicitSpringTerms& terms = work.scratch.implicit_springs[s++];
            if (length <= 0.0) {
                terms = {Vec3(0.0), 0.0, 0.0};
                continue;
            }
            const double transverse =
                group.stiffness * std::max(0.0, 1.0 - spring.rest_length / length);
            terms.direction = d / length;
            terms.isotropic = dt * dt * transverse;
            terms.along = dt * dt * (group.stiffness - transverse) + dt * group.damping;
        }
    }
    // b = h f(x_k, v_k) - M (v_k - v0), for the change v1 - v_k.
    std::span<Vec3> b = work.scratch.implicit_rhs;
    const std::span<const double> masses = cloth.topology().masses;
    for (std::size_t p = 0; p < count; ++p)
        b[p] = dt * work.scratch.forces[p] - masses[p] * (vk[p] - cloth.velocities[p]);
    for (std::uint32_t p : cloth.topology().pinned) b[p] = Vec3(0.0);
    // The hand's particles keep the velocity it prescribes (a change of 0): filtered like pins;
    // their neighbours' forces above already see where the hand takes them.
    for (std::uint32_t p : field.held) b[p] = Vec3(0.0);

    // Conjugate gradient from the warm start (the previous step's Δv) on a first iterate,
    // from no change on a later one.
    std::span<Vec3> x = work.scratch.implicit_delta_v, r = work.scratch.implicit_residual,
                    d = work.scratch.implicit_direction, q = work.scratch.implicit_product;
    if (!first_iterate) std::fill(x.begin(), x.end(), Vec3(0.0));
    for (std::uint32_t p : cloth.topology().pinned) x[p] = Vec3(0.0);
    for (std::uint32_t p : field.held) x[p] = Vec3(0.0);
    multiply_implicit_system(cloth, work, field.air_drag, dt, x, q, field.held);
    for (std::size_t p = 0; p < count; ++p) r[p] = b[p] - q[p], d[p] = r[p];
    const double b_norm = std::sqrt(inner(b, b));
    const double target = implicit_cg_tolerance * b_norm;
    double r_squared = inner(r, r);
    int iteration = 0;
    while (std::sqrt(r_squared) > target && iteration < implicit_cg_max_iterations) {
        multiply_implicit_system(cloth, work, field.air_drag, dt, d, q, field.held);
        const double curvature = inner(d, q);
        if (!(curvature > 0.0)) break;  // not positive definite (or NaN): stop, the guard will see
        const double alpha = r_squared / curvature;
        for (std::size_t p = 0; p < count; ++p) x[p] += alpha * d[p], r[p] -= alpha * q[p];
        const double next_r_squared = inner(r, r);
        const double beta = next_r_squared / r_squared;
        r_squared = next_r_squared;
        for (std::size_t p = 0; p < count; ++p) d[p] = r[p] + beta * d[p];
        ++iteration;
    }
    work.statistics.implicit_iterations = iteration;
    work.statistics.implicit_relative_residual = b_norm > 0.0 ? std::sqrt(r_squared) / b_norm : 0.0;

    for (std::size_t p = 0; p < count; ++p) {
        const Vec3 v1 = vk[p] + x[p];
        x[p] = v1 - cloth.velocities[p];  // the warm start keeps the step's whole change
        cloth.velocities[p] = v1;
        cloth.positions[p] += dt * v1;
    }
    return false;
}

}  // namespace

}  // namespace weft
