// Gusts (sim/gusts.h): none when asked for none; otherwise a wind whose speed and direction
// stay within the stated bounds, reach near them, and change smoothly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "sim/core/gusts.h"
#include "sim/scene_io/scene_loader.h"

namespace weft {
namespace {

double dot(const Vec3d& a, const Vec3d& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

TEST(Gusts, NoneAtZeroOrInStillAir) {
    const Vec3d wind{6.0, 0.5, 1.5};
    for (double t : {0.0, 0.37, 12.5}) {
        EXPECT_EQ(gusty_wind(wind, 0.0, t), wind);
        EXPECT_EQ(gusty_wind({0.0, 0.0, 0.0}, 0.8, t), (Vec3d{0.0, 0.0, 0.0}));
    }
}

TEST(Gusts, SpeedAndVeerStayWithinTheirBoundsReachNearThemAndChangeSmoothly) {
    const Vec3d wind{6.0, 0.0, 1.5};  // m/s
    const double speed = std::sqrt(dot(wind, wind));
    const Vec3d unit{wind[0] / speed, 0.0, wind[2] / speed};
    const Vec3d side{-unit[2], 0.0, unit[0]};
    const double gust = 0.6;
    double lowest = 1e9, highest = -1e9, widest = 0.0;
    const double h = 1e-3;  // s
    // The signal's rate is at most 2π Σ weight·frequency = 4.92 per second of its unit range.
    const double most_change = 2.0 * M_PI * 0.783 * gust * speed * 1.5 * h;  // m/s per step
    Vec3d last = gusty_wind(wind, gust, 0.0);
    for (int k = 1; k <= 60000; ++k) {  // a minute
        const Vec3d w = gusty_wind(wind, gust, k * h);
        const double along = dot(w, unit) / speed, across = dot(w, side) / speed;
        lowest = std::min(lowest, along);
        highest = std::max(highest, along);
        widest = std::max(widest, std::abs(across));
        EXPECT_EQ(w[1], 0.0);
        const Vec3d change{w[0] - last[0], w[1] - last[1], w[2] - last[2]};
        ASSERT_LE(std::sqrt(dot(change, change)), most_change) << "at " << k * h << " s";
        last = w;
    }
    EXPECT_GE(lowest, 1.0 - gust - 1e-12);
    EXPECT_LE(highest, 1.0 + gust + 1e-12);
    EXPECT_LE(widest, 0.5 * gust + 1e-12);
    // It does gust: over a minute the speed spans most of its range, and it veers.
    EXPECT_LT(lowest, 1.0 - 0.6 * gust);
    EXPECT_GT(highest, 1.0 + 0.6 * gust);
    EXPECT_GT(widest, 0.3 * gust);
}

TEST(Gusts, AWindStraightUpOnlyChangesItsSpeed) {
    for (double t : {0.1, 1.7, 9.3}) {
        const Vec3d w = gusty_wind({0.0, 3.0, 0.0}, 1.0, t);
        EXPECT_EQ(w[0], 0.0);
        EXPECT_EQ(w[2], 0.0);
        EXPECT_GE(w[1], 0.0);
        EXPECT_LE(w[1], 6.0);
    }
}

TEST(Gusts, TheSceneKeyIsAShareFromZeroToOne) {
    SceneLoadResult loaded = load_scene_text("[forces]\nwind = [3.0, 0.0, 0.0]\ngust = 0.4\n", "g");
    ASSERT_TRUE(loaded.ok()) << loaded.error->message();
    EXPECT_EQ(loaded.scene->forces.gust, 0.4);
    for (const char* bad : {"gust = -0.1", "gust = 1.5", "gust = \"strong\""}) {
        SceneLoadResult refused = load_scene_text(std::string("[forces]\n") + bad + "\n", "g");
        ASSERT_FALSE(refused.ok()) << bad;
        EXPECT_NE(refused.error->message().find("gust"), std::string::npos)
            << refused.error->message();
    }
}

}  // namespace
}  // namespace weft
