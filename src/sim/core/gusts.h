// Gusts: a wind that is not steady. Its speed rises and falls by up to `gust` of itself, and
// it veers sideways (horizontally, across it) by up to half that, in a smooth, seeded sum of
// sines from about 0.2 to 3 Hz — the same at the same time on every run and thread count, as
// weft's determinism asks. The wind is uniform in space at each instant: the flutter comes
// from the cloth's own response to the changing wind.
#pragma once

#include "sim/scene/scene.h"

namespace weft {

// The wind at simulated time `time` (s) for a mean wind `wind` (m/s) and a gust strength in
// [0, 1]: wind itself when gust is 0 or the wind is still. Its speed along the mean wind stays
// within (1 ± gust) |wind|, its sideways part within gust/2 |wind|.
Vec3d gusty_wind(const Vec3d& wind, double gust, double time);

}  // namespace weft
