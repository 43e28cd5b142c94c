// The structured force pass: the same forces as the general pass (force_pass.h) for a cloth
// whose springs are a regular grid (grid_stencil.h), computed per direction over rows of
// per-component arrays so the loops vectorise, and split between threads by rows.
//
// It agrees with the general pass to rounding (only the order of each particle's sum
// differs: tested), and is bit-identical for any number of threads and for every build of
// its kernel (baseline x86-64, AVX2, AVX-512: no fused multiply-add, IEEE operations only).
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "parallel/worker_pool.h"
#include "sim/core/cloth.h"
#include "sim/grid/grid_force_kernel.h"
#include "sim/grid/kernel_build.h"

namespace weft {

struct ForceField;

// Every pass below runs the kernel build `level` (kernel_build.h).

// Gravity, air drag and every spring force into `forces` (overwritten), or false — touching
// nothing — when the cloth has no usable grid stencil. Repulsion contacts are the caller's
// (accumulate_forces adds them after).
bool accumulate_grid_forces(const Cloth& cloth, const ForceField& field,
                            std::span<const Vec3> positions, std::span<const Vec3> velocities,
                            std::span<Vec3> forces, WorkerPool* pool, SimdLevel level);

// The divergence guard's sweep over the particles (divergence.h): whether any position or
// velocity is not finite, and whether any particle is at |x - x_ref|² >= limit_squared from
// its reference position.
struct ParticleSweep {
    bool non_finite = false;
    bool moved = false;
};
struct SweepRequest {
    const Vec3* reference_positions = nullptr;  // m, x_ref, one per particle
    double limit_squared = 0.0;                 // m²
};

// One symplectic Euler step in the structured pass itself: each particle's force is used
// as soon as it is summed, v' = v + (dt m⁻¹) f, x' = x + dt v', so the forces never make a
// round trip through memory, and the step is one split between threads instead of two. The
// new state is written to `next_positions` and `next_velocities` (resized on first use),
// which are then swapped with the cloth's. Same bits as the force pass followed by
// step_symplectic_euler's loop (tested).
//
// With `sweep`, the guard's sweep of the new state is done in the same pass, into
// `sweep_result`. Returns false, touching nothing, when the pass cannot take the step: no
// usable grid stencil, or a force the pass does not compute (repulsion).
//
// With `after_rows`, each thread then goes on with that work on the particles of the rows
// it has just stepped, while they are in its cache: run(context, begin, end) over particles
// [begin, end), each particle once, the ranges of different threads at the same time. The
// new state is then in next_positions and next_velocities; the cloth's arrays still hold
// the step's start.
//
// Whether a step is fused is the caller's choice (SimulationOptions::fused_grid_steps: tests
// and benchmarks compare the two).
//
// With `single_precision_springs`, the spring forces and their sums are computed in float
// (grid_kernel::Job::single_precision_springs): no longer the force pass's bits, but still the
// same bits for any thread count and kernel build.
struct RowsSteppedWork {
    void (*run)(void* context, std::size_t begin, std::size_t end) = nullptr;
    void* context = nullptr;
};
bool step_grid_symplectic_euler(Cloth& cloth, const ForceField& field, double dt,
                                std::vector<Vec3>& next_positions,
                                std::vector<Vec3>& next_velocities, const SweepRequest* sweep,
                                ParticleSweep* sweep_result, WorkerPool* pool, SimdLevel level,
                                const RowsSteppedWork* after_rows = nullptr,
                                bool single_precision_springs = false);

// The divergence guard's stretch test over the stencil: whether some live spring may be
// longer than `ratio` rest lengths, by |d|² > ratio² (1 - 1e-9) L² — a superset of the exact
// test |d| > ratio L, which the caller then runs. Nothing when there is no usable stencil.
std::optional<bool> grid_springs_maybe_longer_than(const Cloth& cloth, double ratio,
                                                   WorkerPool* pool, SimdLevel level);

// The guard's pass after a far move, over the stencil: grid_springs_maybe_longer_than's test
// and the headroom min (ratio L - |d|) and scale max (ratio L) over live springs (the same
// numbers as spring by spring: minima and maxima are exact in any order). Nothing when there
// is no usable stencil.
std::optional<grid_kernel::StretchHeadroom> grid_stretch_headroom(const Cloth& cloth, double ratio,
                                                                  WorkerPool* pool,
                                                                  SimdLevel level);

// implicit_euler.cpp's largest linearisation error over the stencil: the largest over live
// springs that end longer than `ratio` rest lengths of how far the force at the cloth's
// positions is from what the step linearised at `start` assumed, in k L (the same number as
// spring by spring: a maximum is exact in any order); 0 without such a spring. Nothing when
// there is no usable stencil.
std::optional<double> grid_linearisation_error(const Cloth& cloth, std::span<const Vec3> start,
                                               double ratio, WorkerPool* pool, SimdLevel level);

// The guard's sweep on its own, vectorised with the same kernel builds.
ParticleSweep sweep_particles(std::span<const Vec3> positions, std::span<const Vec3> reference,
                              std::span<const Vec3> velocities, double limit_squared,
                              WorkerPool* pool, SimdLevel level);

}  // namespace weft
