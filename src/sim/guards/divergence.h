// Divergence guard: tells a simulation that has blown up from one that is merely moving
// fast, so the runner can stop with a reason instead of printing NaNs.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "parallel/worker_pool.h"
#include "sim/core/cloth.h"
#include "sim/grid/grid_force_pass.h"

namespace weft {

// A spring longer than this many rest lengths, with tearing off, means the integration has
// run away: no fabric stretches 5× and a stable step never gets there.
inline constexpr double runaway_stretch_ratio = 5.0;

// The largest |x_j - x_i| / L over the live springs, or NaN when none is left: what the
// stretch limits are judged on, for studies and tests to report. With a pool, split between
// its threads (a maximum: the same whatever the split).
double largest_stretch_ratio(const Cloth& cloth, WorkerPool* pool = nullptr);

// Returns why the state is diverged, or nothing if it is sound: a non-finite position or
// velocity (naming the particle), or — when `check_runaway_stretch` — a spring stretched
// past runaway_stretch_ratio × its rest length.
//
// It runs after every step, so the sound case is made cheap: a scan that only says whether
// anything is wrong (no square root, no branch per value, split between the pool's threads)
// runs first, and only if it finds something does the exact scan run to say what. The
// verdict is the same as the exact scan's (see divergence.cpp) whatever the thread count.
// `level`: the kernel build of the grid's passes (kernel_build.h; the same verdict with any).
std::optional<std::string> find_divergence(const Cloth& cloth, bool check_runaway_stretch,
                                           WorkerPool* pool = nullptr,
                                           SimdLevel level = supported_simd_level());

// The guard a simulation runs after every step: the same verdict and message as
// find_divergence, but a sound step usually costs one streaming pass over the particles
// instead of a pass over every spring.
//
// Why that is exact: after a full scan it keeps the positions x_ref and the headroom
// H = min over springs of (ratio L - l_ref). With Δ = x - x_ref, a spring's length now is
// l = |x_j - x_i| <= l_ref + |Δ_j| + |Δ_i| <= l_ref + 2 max|Δ|. While 2 max|Δ| < H (with a
// margin far above rounding) no spring can have reached the runaway stretch and the spring
// scan is skipped; otherwise it runs and x_ref, H are renewed. The sweep that bounds max|Δ|
// also checks finiteness, vectorised and split between threads (grid_force_pass.h).
// Removing springs (tearing, cuts) only raises H, so the bound survives it.
class DivergenceGuard {
  public:
    // The kernel build of its sweeps and spring passes (kernel_build.h).
    void set_kernel_build(SimdLevel level) { kernel_build_ = level; }
    // `swept`: the sweep of this very state for sweep_request(), if a fused step has done
    // it already (grid_force_pass.h).
    std::optional<std::string> check(const Cloth& cloth, bool check_runaway_stretch,
                                     WorkerPool* pool = nullptr,
                                     std::optional<ParticleSweep> swept = std::nullopt);
    // The sweep the next check will make of `cloth`, or nothing if it will scan in full.
    std::optional<SweepRequest> sweep_request(const Cloth& cloth, bool check_runaway_stretch) const;
    // The cloth was rebuilt (reset): the kept positions no longer belong to it.
    void forget() { reference_valid_ = false; }

  private:
    void renew_reference(const Cloth& cloth, WorkerPool* pool);
    // The cloth's positions become the reference, with its springs' headroom and scale.
    void keep_reference(const Cloth& cloth, double headroom, double length_scale);

    std::vector<Vec3> reference_positions_;  // m, x_ref
    double headroom_ = 0.0;                  // m, H
    double length_scale_ = 0.0;              // m, the longest ratio L: scales the margin
    bool reference_valid_ = false;
    SimdLevel kernel_build_ = supported_simd_level();
};

}  // namespace weft
