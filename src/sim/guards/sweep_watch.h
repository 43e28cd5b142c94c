// The divergence guard's sweep (divergence.h), kept valid through the corrections that
// follow a step, so that a step with contacts does not sweep the whole sheet twice.
//
// The fused grid step sweeps every particle on its way (grid_force_pass.h). Contacts and
// self-collision then move a few of them. Instead of a second sweep of the whole sheet, each
// correction checks the particles it moved, right after moving them, with the sweep's test.
// Every particle's final state is then checked: by the step's sweep if no correction moved
// it, otherwise by the last correction that did. A particle flagged after one correction
// and brought back by a later one stays flagged; the guard's exact scan then decides. So the
// flags are never fewer than a fresh sweep's would be, and the guard's verdicts are the
// same.
#pragma once

#include <atomic>
#include <cmath>
#include <cstddef>

#include "sim/core/cloth.h"
#include "sim/grid/grid_force_pass.h"

namespace weft {

class SweepWatch {
  public:
    // `request`: what the step swept for; `swept`: what it found (add it later if the
    // corrections start before the step's sweep is done).
    explicit SweepWatch(const SweepRequest& request, const ParticleSweep& swept = {})
        : request_(request), non_finite_(swept.non_finite), moved_(swept.moved) {}

    void add(const ParticleSweep& swept) {
        if (swept.non_finite) non_finite_.store(true, std::memory_order_relaxed);
        if (swept.moved) moved_.store(true, std::memory_order_relaxed);
    }

    // Checks particle p after a correction moved it to x with velocity v. Any thread.
    // The test grid_kernel::sweep_particles makes a superset of: |x - x_ref|² >= the limit,
    // or a non-finite coordinate (of x - x_ref, or of v).
    void check(std::size_t p, const Vec3& x, const Vec3& v) {
        const Vec3 d = x - request_.reference_positions[p];
        const double moved_squared = d.x * d.x + d.y * d.y + d.z * d.z;
        if (!std::isfinite(moved_squared) || !std::isfinite(v.x) || !std::isfinite(v.y) ||
            !std::isfinite(v.z))
            non_finite_.store(true, std::memory_order_relaxed);
        if (moved_squared >= request_.limit_squared) moved_.store(true, std::memory_order_relaxed);
    }

    ParticleSweep result() const {
        return {non_finite_.load(std::memory_order_relaxed),
                moved_.load(std::memory_order_relaxed)};
    }

  private:
    SweepRequest request_;
    std::atomic<bool> non_finite_;
    std::atomic<bool> moved_;
};

}  // namespace weft
