#include "sim/grid/grid_force_pass.h"

#include <algorithm>
#include <atomic>
#include <limits>
#include <mutex>
#include <vector>

#include "sim/core/force_pass.h"
#include "sim/grid/grid_force_kernel.h"

namespace weft {
namespace {

static_assert(sizeof(Vec3) == 3 * sizeof(double), "the kernel reads Vec3 arrays as doubles");

// Rows are split between threads only when there are enough particles to pay for the
// hand-off (a few microseconds).
constexpr std::size_t min_particles_for_threads = 4096;

SimdLevel detect_simd_level() {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
    if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
        __builtin_cpu_supports("avx512dq"))
        return SimdLevel::avx512;
    if (__builtin_cpu_supports("avx2")) return SimdLevel::avx2;
#endif
    return SimdLevel::baseline;
}

// Scratch of each thread (the pool's threads are persistent): grown on first use, so no
// step allocates once the first has run.
double* thread_scratch(int cols) {
    thread_local std::vector<double> scratch;
    const std::size_t needed = grid_kernel::scratch_doubles(cols);
    if (scratch.size() < needed) scratch.assign(needed, 0.0);
    return scratch.data();
}

// The kernel's view of the cloth's stencil and materials; false if it has more directions
// than the kernel takes (never, for a stencil built by build_grid_stencil).
bool describe_stencil(const Cloth& cloth, std::span<const Vec3> positions, grid_kernel::Job& job) {
    job.rows = cloth.rows;
    job.cols = cloth.cols;
    job.positions = &positions.data()->x;
    job.masses = cloth.topology().masses.data();
    for (const GridStencilDirection& direction : cloth.topology().grid_stencil.directions) {
        if (job.direction_count == grid_kernel::max_directions) return false;
        const SpringGroup& group = cloth.topology().spring_groups[direction.group];
        job.directions[job.direction_count++] = {direction.row_step,
                                                 direction.col_step,
                                                 group.stiffness,
                                                 group.damping,
                                                 direction.rest_lengths.data(),
                                                 direction.rest_lengths_float.data()};
    }
    return true;
}

void describe_field(const ForceField& field, grid_kernel::Job& job) {
    for (int k = 0; k < 3; ++k) {
        job.gravity[k] = field.gravity[k];
        job.wind[k] = field.wind[k];
    }
    job.air_drag = field.air_drag;
}

bool use_threads(const Cloth& cloth, WorkerPool* pool) {
    return pool && pool->thread_count() > 1 && cloth.particle_count() >= min_particles_for_threads;
}

// The row kernel over all rows of `job`, split between the pool's threads when the cloth is
// big enough, each band followed by `after_rows` on its particles; what the fused sweep found
// in any band (nothing unless the job asks for it).
grid_kernel::SweepFlags run_force_rows(const Cloth& cloth, const grid_kernel::Job& job,
                                       WorkerPool* pool, SimdLevel level,
                                       const RowsSteppedWork* after_rows = nullptr) {
    const auto kernel = kernel_of(level, grid_kernel::force_rows_baseline,
                                  grid_kernel::force_rows_avx2, grid_kernel::force_rows_avx512);
    const auto cols = static_cast<std::size_t>(job.cols);
    if (!use_threads(cloth, pool)) {
        const grid_kernel::SweepFlags flags = kernel(job, 0, job.rows, thread_scratch(job.cols));
        if (after_rows)
            after_rows->run(after_rows->context, 0, static_cast<std::size_t>(job.rows) * cols);
        return flags;
    }
    std::atomic<bool> non_finite{false}, moved{false};
    pool->parallel_for(static_cast<std::size_t>(job.rows), [&](std::size_t begin, std::size_t end) {
        const grid_kernel::SweepFlags band =
            kernel(job, static_cast<int>(begin), static_cast<int>(end), thread_scratch(job.cols));
        if (band.non_finite) non_finite.store(true, std::memory_order_relaxed);
        if (band.moved) moved.store(true, std::memory_order_relaxed);
        if (after_rows) after_rows->run(after_rows->context, begin * cols, end * cols);
    });
    return {non_finite.load(), moved.load()};
}

}  // namespace

SimdLevel supported_simd_level() {
    static const SimdLevel supported = detect_simd_level();
    return supported;
}

const char* simd_level_name(SimdLevel level) {
    return level == SimdLevel::avx512 ? "avx-512"
           : level == SimdLevel::avx2 ? "avx2"
                                      : "baseline x86-64";
}

bool accumulate_grid_forces(const Cloth& cloth, const ForceField& field,
                            std::span<const Vec3> positions, std::span<const Vec3> velocities,
                            std::span<Vec3> forces, WorkerPool* pool, SimdLevel level) {
    grid_kernel::Job job;
    if (!grid_stencil_usable(cloth) || !describe_stencil(cloth, positions, job)) return false;
    job.velocities = &velocities.data()->x;
    job.forces = &forces.data()->x;
    describe_field(field, job);
    run_force_rows(cloth, job, pool, level);
    return true;
}

bool step_grid_symplectic_euler(Cloth& cloth, const ForceField& field, double dt,
                                std::vector<Vec3>& next_positions,
                                std::vector<Vec3>& next_velocities, const SweepRequest* sweep,
                                ParticleSweep* sweep_result, WorkerPool* pool, SimdLevel level,
                                const RowsSteppedWork* after_rows, bool single_precision_springs) {
    if (!field.colliders.empty()) return false;
    grid_kernel::Job job;
    if (!grid_stencil_usable(cloth) || !describe_stencil(cloth, cloth.positions, job)) return false;
    const std::size_t count = cloth.particle_count();
    if (next_positions.size() != count) next_positions.resize(count);
    if (next_velocities.size() != count) next_velocities.resize(count);
    job.velocities = &cloth.velocities.data()->x;
    describe_field(field, job);
    job.dt = dt;
    job.inverse_masses = cloth.topology().inverse_masses.data();
    job.next_positions = &next_positions.data()->x;
    job.next_velocities = &next_velocities.data()->x;
    job.single_precision_springs = single_precision_springs;
    if (sweep) {
        job.reference_positions = &sweep->reference_positions->x;
        job.moved_limit_squared = sweep->limit_squared;
    }
    const grid_kernel::SweepFlags flags = run_force_rows(cloth, job, pool, level, after_rows);
    cloth.positions.swap(next_positions);
    cloth.velocities.swap(next_velocities);
    if (sweep && sweep_result) *sweep_result = {flags.non_finite, flags.moved};
    return true;
}

namespace {

// The guard's spring passes over the stencil (below): the cloth's springs as a job over its
// positions, or nothing without a usable stencil; and the bound of their "maybe longer"
// test, ratio² (1 - 1e-9) L², a superset of the exact |d| > ratio L, whose rounding differs.
std::optional<grid_kernel::Job> spring_rows_job(const Cloth& cloth) {
    grid_kernel::Job job;
    if (!grid_stencil_usable(cloth) || !describe_stencil(cloth, cloth.positions, job))
        return std::nullopt;
    return job;
}

double maybe_ratio_squared(double ratio) {
    return ratio * ratio * (1.0 - 1e-9);
}

}  // namespace

std::optional<bool> grid_springs_maybe_longer_than(const Cloth& cloth, double ratio,
                                                   WorkerPool* pool, SimdLevel level) {
    const std::optional<grid_kernel::Job> described = spring_rows_job(cloth);
    if (!described) return std::nullopt;
    const grid_kernel::Job& job = *described;
    const double ratio_squared = maybe_ratio_squared(ratio);
    const auto kernel = kernel_of(level, grid_kernel::rows_maybe_overstretched_baseline,
                                  grid_kernel::rows_maybe_overstretched_avx2,
                                  grid_kernel::rows_maybe_overstretched_avx512);
    if (!use_threads(cloth, pool)) return kernel(job, ratio_squared, 0, job.rows);
    std::atomic<bool> suspect{false};
    pool->parallel_for(static_cast<std::size_t>(job.rows), [&](std::size_t begin, std::size_t end) {
        if (kernel(job, ratio_squared, static_cast<int>(begin), static_cast<int>(end)))
            suspect.store(true, std::memory_order_relaxed);
    });
    return suspect.load();
}

std::optional<grid_kernel::StretchHeadroom> grid_stretch_headroom(const Cloth& cloth, double ratio,
                                                                  WorkerPool* pool,
                                                                  SimdLevel level) {
    const std::optional<grid_kernel::Job> described = spring_rows_job(cloth);
    if (!described) return std::nullopt;
    const grid_kernel::Job& job = *described;
    const double ratio_squared = maybe_ratio_squared(ratio);
    const auto kernel = kernel_of(level, grid_kernel::rows_stretch_headroom_baseline,
                                  grid_kernel::rows_stretch_headroom_avx2,
                                  grid_kernel::rows_stretch_headroom_avx512);
    if (!use_threads(cloth, pool)) return kernel(job, ratio, ratio_squared, 0, job.rows);
    grid_kernel::StretchHeadroom total{false, std::numeric_limits<double>::infinity(), 0.0};
    std::mutex merge;
    pool->parallel_for(static_cast<std::size_t>(job.rows), [&](std::size_t begin, std::size_t end) {
        const grid_kernel::StretchHeadroom part =
            kernel(job, ratio, ratio_squared, static_cast<int>(begin), static_cast<int>(end));
        std::lock_guard lock(merge);
        total.maybe_longer = total.maybe_longer || part.maybe_longer;
        total.headroom = std::min(total.headroom, part.headroom);
        total.scale = std::max(total.scale, part.scale);
    });
    return total;
}

std::optional<double> grid_linearisation_error(const Cloth& cloth, std::span<const Vec3> start,
                                               double ratio, WorkerPool* pool, SimdLevel level) {
    const std::optional<grid_kernel::Job> described = spring_rows_job(cloth);
    if (!described || start.size() != cloth.particle_count()) return std::nullopt;
    const grid_kernel::Job& job = *described;
    const double ratio_squared = maybe_ratio_squared(ratio);
    const auto kernel = kernel_of(level, grid_kernel::rows_linearisation_error_baseline,
                                  grid_kernel::rows_linearisation_error_avx2,
                                  grid_kernel::rows_linearisation_error_avx512);
    const double* at = &start.data()->x;
    if (!use_threads(cloth, pool)) return kernel(job, at, ratio, ratio_squared, 0, job.rows);
    double largest = 0.0;
    std::mutex merge;
    pool->parallel_for(static_cast<std::size_t>(job.rows), [&](std::size_t begin, std::size_t end) {
        const double part =
            kernel(job, at, ratio, ratio_squared, static_cast<int>(begin), static_cast<int>(end));
        std::lock_guard lock(merge);
        largest = std::max(largest, part);
    });
    return largest;
}

ParticleSweep sweep_particles(std::span<const Vec3> positions, std::span<const Vec3> reference,
                              std::span<const Vec3> velocities, double limit_squared,
                              WorkerPool* pool, SimdLevel level) {
    const auto kernel =
        kernel_of(level, grid_kernel::sweep_particles_baseline, grid_kernel::sweep_particles_avx2,
                  grid_kernel::sweep_particles_avx512);
    const std::size_t count = positions.size();
    auto sweep = [&](std::size_t begin, std::size_t end, bool& non_finite, bool& moved) {
        kernel(&positions[begin].x, &reference[begin].x, &velocities[begin].x, end - begin,
               limit_squared, non_finite, moved);
    };
    ParticleSweep result;
    if (!pool || pool->thread_count() <= 1 || count < min_particles_for_threads) {
        if (count > 0) sweep(0, count, result.non_finite, result.moved);
        return result;
    }
    std::atomic<bool> non_finite{false}, moved{false};
    pool->parallel_for(count, [&](std::size_t begin, std::size_t end) {
        bool slice_non_finite = false, slice_moved = false;
        sweep(begin, end, slice_non_finite, slice_moved);
        if (slice_non_finite) non_finite.store(true, std::memory_order_relaxed);
        if (slice_moved) moved.store(true, std::memory_order_relaxed);
    });
    return {non_finite.load(), moved.load()};
}

}  // namespace weft
