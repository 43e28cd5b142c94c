// Divergence guard: tells a simulation that has blown up from one that is merely moving
// fast, so the runner can stop with a reason instead of printing NaNs.
#pragma once

#include <optional>
#include <string>

#include "sim/cloth.h"

namespace weft {

// A spring longer than this many rest lengths, with tearing off, means the integration has
// run away: no fabric stretches 5× and a stable step never gets there.
inline constexpr double runaway_stretch_ratio = 5.0;

// Returns why the state is diverged, or nothing if it is sound: a non-finite position or
// velocity (naming the particle), or — when `check_runaway_stretch` — a spring stretched
// past runaway_stretch_ratio × its rest length.
std::optional<std::string> find_divergence(const Cloth& cloth, bool check_runaway_stretch);

}  // namespace weft
