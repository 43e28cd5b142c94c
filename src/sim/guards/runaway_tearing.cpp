#include "sim/guards/runaway_tearing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace weft {
namespace {

// The most springs one straight line across the sheet crosses: a row's worth, across the
// shorter side (a row of a wide sheet crosses the springs between two rows: about
// springs / (rows - 1) of them).
// A mesh (one "row" of particles) counts as a square sheet of as many particles.
double springs_per_line(const Cloth& cloth, std::size_t springs) {
    const int across =
        cloth.is_mesh() ? static_cast<int>(std::sqrt(static_cast<double>(cloth.particle_count())))
                        : std::min(cloth.rows, cloth.cols);
    const int gaps = std::max(across - 1, 1);
    return static_cast<double>(springs) / gaps;
}

}  // namespace

std::optional<std::string> RunawayTearingGuard::check(const Cloth& cloth,
                                                      std::span<const Spring> torn, double time,
                                                      const Grab& hand) {
    if (!valid_) {
        valid_ = true;
        recent_.clear();
        recent_springs_ = 0;
        const std::size_t springs = cloth.spring_count() + torn.size();  // before this step
        allowed_ = std::max(allowed_share * static_cast<double>(springs),
                            allowed_lines * springs_per_line(cloth, springs));
    }
    while (!recent_.empty() && recent_.front().time <= time - window) {
        recent_springs_ -= recent_.front().springs;
        recent_.pop_front();
    }
    const bool ignored = ignore_next_step_;
    ignore_next_step_ = false;
    if (torn.empty() || ignored) return std::nullopt;
    // The hand's particles are in ascending order (grab_cloth visits them so).
    auto held = [&](std::uint32_t p) {
        return std::binary_search(hand.particles.begin(), hand.particles.end(), p);
    };
    const int cols = std::max(cloth.cols, 1);
    Burst burst{time, 0, cloth.rows, -1, cols, -1};
    for (const Spring& spring : torn) {
        if (held(spring.i) || held(spring.j)) continue;
        ++burst.springs;
        for (const std::uint32_t p : {spring.i, spring.j}) {
            const int row = static_cast<int>(p) / cols;
            const int col = static_cast<int>(p) % cols;
            burst.row_min = std::min(burst.row_min, row);
            burst.row_max = std::max(burst.row_max, row);
            burst.col_min = std::min(burst.col_min, col);
            burst.col_max = std::max(burst.col_max, col);
        }
    }
    if (burst.springs == 0) return std::nullopt;
    recent_.push_back(burst);
    recent_springs_ += burst.springs;
    if (!(static_cast<double>(recent_springs_) > allowed_)) return std::nullopt;
    // Where: the grid rows and columns the window's tears span.
    Burst span = recent_.front();
    for (const Burst& b : recent_) {
        span.row_min = std::min(span.row_min, b.row_min);
        span.row_max = std::max(span.row_max, b.row_max);
        span.col_min = std::min(span.col_min, b.col_min);
        span.col_max = std::max(span.col_max, b.col_max);
    }
    char message[320];
    std::snprintf(message, sizeof message,
                  "tearing ran away: %zu springs broke within %.3g s across rows %d-%d, columns "
                  "%d-%d (the guard allows %.0f: a tenth of the sheet, or two lines across it; "
                  "a stable tear runs along a line)",
                  recent_springs_, window, span.row_min, span.row_max, span.col_min, span.col_max,
                  allowed_);
    return std::string(message);
}

}  // namespace weft
