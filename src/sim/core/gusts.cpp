#include "sim/core/gusts.h"

#include <cmath>
#include <numbers>

namespace weft {
namespace {

// A unit-bounded, smooth signal: four sines whose weights sum to 1, at frequencies with no
// common period over any run (Hz), from fixed phases (rad). `lane` picks another set of
// phases, so that speed and direction vary independently.
double gust_signal(double time, int lane) {
    constexpr double frequencies[4] = {0.23, 0.61, 1.37, 2.91};  // Hz
    constexpr double weights[4] = {0.45, 0.3, 0.15, 0.1};
    constexpr double phases[2][4] = {{0.3, 2.1, 4.4, 1.2}, {5.1, 0.9, 3.3, 2.6}};  // rad
    double sum = 0.0;
    for (int k = 0; k < 4; ++k)
        sum +=
            weights[k] * std::sin(2.0 * std::numbers::pi * frequencies[k] * time + phases[lane][k]);
    return sum;
}

}  // namespace

Vec3d gusty_wind(const Vec3d& wind, double gust, double time) {
    const double speed = std::hypot(wind[0], wind[1], wind[2]);  // m/s
    if (gust <= 0.0 || speed == 0.0) return wind;
    const double along = 1.0 + gust * gust_signal(time, 0);
    // Across the wind, horizontally; nothing for a wind straight up or down.
    const double horizontal = std::hypot(wind[0], wind[2]);  // m/s
    const double across = horizontal > 0.0 ? 0.5 * gust * speed * gust_signal(time, 1) : 0.0;
    const double side_x = horizontal > 0.0 ? -wind[2] / horizontal : 0.0;
    const double side_z = horizontal > 0.0 ? wind[0] / horizontal : 0.0;
    return {along * wind[0] + across * side_x, along * wind[1], along * wind[2] + across * side_z};
}

}  // namespace weft
