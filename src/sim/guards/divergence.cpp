#include "sim/guards/divergence.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <mutex>
#include <sstream>

#include "sim/core/chunked_reduce.h"
#include "sim/grid/grid_force_pass.h"

namespace weft {

double largest_stretch_ratio(const Cloth& cloth, WorkerPool* pool) {
    double largest = -std::numeric_limits<double>::infinity();
    for (const SpringGroup& group : cloth.topology().spring_groups)
        largest = reduce_in_chunks(
            pool, group.springs.size(), largest,
            [&](std::size_t begin, std::size_t end) {
                double part = -std::numeric_limits<double>::infinity();
                for (std::size_t k = begin; k < end; ++k) {
                    const Spring& s = group.springs[k];
                    part = std::max(part, glm::length(cloth.positions[s.j] - cloth.positions[s.i]) /
                                              s.rest_length);
                }
                return part;
            },
            [](double a, double b) { return std::max(a, b); });
    return std::isfinite(largest) ? largest : std::numeric_limits<double>::quiet_NaN();
}
namespace {

bool is_finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Work below this many items stays on the calling thread.
constexpr std::size_t min_items_for_threads = 8192;

template <class Body>
void for_ranges(WorkerPool* pool, std::size_t count, Body&& body) {
    parallel_for_if(pool, count >= min_items_for_threads, count, body);
}

// True if any of the values is infinite or NaN: x - x is 0 for a finite x and NaN
// otherwise, and NaN == 0 is false. Written without an early exit so it vectorises.
bool any_non_finite(const double* values, std::size_t count) {
    unsigned bad = 0;
    for (std::size_t k = 0; k < count; ++k) bad |= (values[k] - values[k] == 0.0) ? 0u : 1u;
    return bad != 0;
}

// True if some spring may be past the runaway stretch: |d|² > (ratio L)² (1 - 1e-9). The
// margin makes this a superset of the exact test |d| > ratio L, whose rounding differs.
bool any_spring_maybe_runaway(const SpringGroup& group, const Vec3* x, std::size_t begin,
                              std::size_t end) {
    constexpr double ratio_squared = runaway_stretch_ratio * runaway_stretch_ratio * (1.0 - 1e-9);
    const Spring* springs = group.springs.data();
    unsigned suspect = 0;
    for (std::size_t s = begin; s < end; ++s) {
        const Vec3 d = x[springs[s].j] - x[springs[s].i];
        const double rest = springs[s].rest_length;
        suspect |= d.x * d.x + d.y * d.y + d.z * d.z > ratio_squared * rest * rest ? 1u : 0u;
    }
    return suspect != 0;
}

// Whether some position or velocity is not finite.
bool state_non_finite(const Cloth& cloth, WorkerPool* pool) {
    std::atomic<bool> found{false};
    const std::size_t values = 3 * cloth.particle_count();
    for_ranges(pool, values, [&](std::size_t begin, std::size_t end) {
        if (any_non_finite(&cloth.positions.data()->x + begin, end - begin) ||
            any_non_finite(&cloth.velocities.data()->x + begin, end - begin))
            found.store(true, std::memory_order_relaxed);
    });
    return found.load();
}

// Whether the exact scan below could find anything.
bool maybe_diverged(const Cloth& cloth, bool check_runaway_stretch, WorkerPool* pool,
                    SimdLevel level) {
    if (state_non_finite(cloth, pool)) return true;
    if (!check_runaway_stretch) return false;
    std::atomic<bool> found{false};
    // A grid tests its springs per direction over rows; anything else spring by spring.
    if (auto suspect = grid_springs_maybe_longer_than(cloth, runaway_stretch_ratio, pool, level))
        return *suspect;
    for (const SpringGroup& group : cloth.topology().spring_groups) {
        for_ranges(pool, group.springs.size(), [&](std::size_t begin, std::size_t end) {
            if (any_spring_maybe_runaway(group, cloth.positions.data(), begin, end))
                found.store(true, std::memory_order_relaxed);
        });
    }
    return found.load();
}

}  // namespace

std::optional<std::string> find_divergence(const Cloth& cloth, bool check_runaway_stretch,
                                           WorkerPool* pool, SimdLevel level) {
    if (!maybe_diverged(cloth, check_runaway_stretch, pool, level)) return std::nullopt;
    for (std::size_t p = 0; p < cloth.particle_count(); ++p) {
        if (!is_finite(cloth.positions[p]))
            return particle_name(cloth, p) + " has a non-finite position";
        if (!is_finite(cloth.velocities[p]))
            return particle_name(cloth, p) + " has a non-finite velocity";
    }
    if (!check_runaway_stretch) return std::nullopt;
    for (const SpringGroup& group : cloth.topology().spring_groups) {
        for (const Spring& spring : group.springs) {
            const double length =
                glm::length(cloth.positions[spring.j] - cloth.positions[spring.i]);
            if (length > runaway_stretch_ratio * spring.rest_length) {
                std::ostringstream out;
                out << spring_family_name(group.family) << " spring between "
                    << particle_name(cloth, spring.i) << " and " << particle_name(cloth, spring.j)
                    << " stretched to " << length / spring.rest_length << "x its rest length";
                return out.str();
            }
        }
    }
    return std::nullopt;
}

void DivergenceGuard::renew_reference(const Cloth& cloth, WorkerPool* pool) {
    // H = min over live springs of (ratio L - l): one pass with a square root per spring,
    // run only when the bound stopped holding.
    double headroom = std::numeric_limits<double>::infinity();
    double scale = 0.0;
    std::mutex merge;
    for (const SpringGroup& group : cloth.topology().spring_groups) {
        for_ranges(pool, group.springs.size(), [&](std::size_t begin, std::size_t end) {
            const Vec3* x = cloth.positions.data();
            double minimum = std::numeric_limits<double>::infinity(), longest = 0.0;
            for (std::size_t s = begin; s < end; ++s) {
                const Spring& spring = group.springs[s];
                const double length = glm::length(x[spring.j] - x[spring.i]);
                const double limit = runaway_stretch_ratio * spring.rest_length;
                minimum = std::min(minimum, limit - length);
                longest = std::max(longest, limit);
            }
            std::lock_guard lock(merge);
            headroom = std::min(headroom, minimum);
            scale = std::max(scale, longest);
        });
    }
    keep_reference(cloth, headroom, scale);
}

void DivergenceGuard::keep_reference(const Cloth& cloth, double headroom, double length_scale) {
    reference_positions_ = cloth.positions;
    headroom_ = headroom;
    length_scale_ = length_scale;
    reference_valid_ = true;
}

std::optional<SweepRequest> DivergenceGuard::sweep_request(const Cloth& cloth,
                                                           bool check_runaway_stretch) const {
    if (!reference_valid_ || reference_positions_.size() != cloth.particle_count())
        return std::nullopt;
    // Every spring is at most 2 m longer than at the reference, m the largest distance a
    // particle has moved: the scan can be skipped while 2 m < H. A margin of 1e-9, relative
    // to the lengths involved, covers rounding in l_ref, L, m and the exact scan's own |d|
    // (each off by parts in 1e16).
    // (A cloth without springs has an infinite headroom: only finiteness to watch.)
    const double reach = std::isinf(headroom_) && headroom_ > 0.0
                             ? headroom_
                             : 0.5 * (headroom_ - 1e-9 * (std::abs(headroom_) + length_scale_));
    const double limit_squared = !check_runaway_stretch ? std::numeric_limits<double>::infinity()
                                 : reach > 0.0          ? reach * reach * (1.0 - 1e-9)
                                                        : 0.0;
    return SweepRequest{reference_positions_.data(), limit_squared};
}

std::optional<std::string> DivergenceGuard::check(const Cloth& cloth, bool check_runaway_stretch,
                                                  WorkerPool* pool,
                                                  std::optional<ParticleSweep> swept) {
    if (const std::optional<SweepRequest> request = sweep_request(cloth, check_runaway_stretch)) {
        const ParticleSweep sweep =
            swept ? *swept
                  : sweep_particles(cloth.positions,
                                    {request->reference_positions, cloth.particle_count()},
                                    cloth.velocities, request->limit_squared, pool, kernel_build_);
        if (!sweep.non_finite && !sweep.moved) return std::nullopt;
    }
    // A grid's springs answer the runaway test and give the next reference's headroom in one
    // pass (the same numbers as the scans below, which took two passes at every frame-sized
    // implicit step of a large sheet, one of them spring by spring).
    if (check_runaway_stretch)
        if (const auto grid =
                grid_stretch_headroom(cloth, runaway_stretch_ratio, pool, kernel_build_);
            grid && !grid->maybe_longer && !state_non_finite(cloth, pool)) {
            keep_reference(cloth, grid->headroom, grid->scale);
            return std::nullopt;
        }
    std::optional<std::string> verdict =
        find_divergence(cloth, check_runaway_stretch, pool, kernel_build_);
    if (verdict) {
        reference_valid_ = false;
        return verdict;
    }
    if (check_runaway_stretch) {
        renew_reference(cloth, pool);
    } else {
        // Only finiteness to watch: the positions serve as the reference, the bound is unused
        // (a headroom of -infinity sends a later stretch check to the full scan).
        keep_reference(cloth, -std::numeric_limits<double>::infinity(), length_scale_);
    }
    return std::nullopt;
}

}  // namespace weft
