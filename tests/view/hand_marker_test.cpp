// The hand marker: drawn where the hand is, with a line to the held point while the two
// differ, and nothing while the hand holds nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "sim/build/cloth_builder.h"
#include "sim/interaction/grab.h"
#include "view/hand_marker.h"

namespace weft::view {
namespace {

constexpr raster::Rgba8 background{0, 0, 0, 255};

bool is_marker(const raster::Rgba8& c) {
    return c.r > 200 && c.g > 150 && c.b < 120;
}

int marker_pixels_near(const raster::Framebuffer& framebuffer, glm::vec3 window, int half) {
    int count = 0;
    for (int y = static_cast<int>(window.y) - half; y <= static_cast<int>(window.y) + half; ++y)
        for (int x = static_cast<int>(window.x) - half; x <= static_cast<int>(window.x) + half; ++x)
            if (x >= 0 && y >= 0 && x < framebuffer.width() && y < framebuffer.height())
                count += is_marker(framebuffer.colours()[framebuffer.index(x, y)]);
    return count;
}

struct HeldSheet {
    Cloth cloth;
    Grab grab;
    raster::Camera camera = raster::make_camera({0.3f, -0.3f, 2.0f}, {0.3f, -0.3f, 0.0f}, 50.0f);
    raster::Framebuffer framebuffer{320, 240};
    HeldSheet() {
        Scene scene;
        scene.cloth.rows = scene.cloth.cols = 8;
        scene.cloth.spacing = 0.08;
        cloth = build_grid_cloth(scene);
        const std::uint32_t grabbed = 4 * 8 + 4;
        grab = grab_cloth(cloth, {0, grabbed, 1.0, cloth.positions[grabbed]}, 0.01);
        framebuffer.clear(background);
    }
    int total() const {
        return static_cast<int>(
            std::count_if(framebuffer.colours().begin(), framebuffer.colours().end(), is_marker));
    }
};

TEST(HandMarker, NothingIsDrawnWhileTheHandHoldsNothing) {
    HeldSheet setup;
    draw_hand_marker(setup.framebuffer, setup.camera, Grab{}, setup.cloth);
    EXPECT_EQ(setup.total(), 0);
}

TEST(HandMarker, AMarkerAtTheHandAndNoLineWhileItIsWhereTheHeldPointIs) {
    HeldSheet setup;
    draw_hand_marker(setup.framebuffer, setup.camera, setup.grab, setup.cloth);
    const auto at = raster::project_to_window(setup.camera, 320, 240, glm::vec3(setup.grab.target));
    ASSERT_TRUE(at.has_value());
    const int near_hand = marker_pixels_near(setup.framebuffer, *at, 5);
    EXPECT_GE(near_hand, 50);             // a 9-pixel square, about
    EXPECT_EQ(setup.total(), near_hand);  // and nothing else
}

TEST(HandMarker, ALineJoinsTheHandToTheHeldPointWhileTheyDiffer) {
    HeldSheet setup;
    setup.grab.target += Vec3(0.3, 0.2, 0.0);  // the hand has moved on; the cloth not yet
    draw_hand_marker(setup.framebuffer, setup.camera, setup.grab, setup.cloth);
    const auto hand =
        raster::project_to_window(setup.camera, 320, 240, glm::vec3(setup.grab.target));
    const auto held = raster::project_to_window(
        setup.camera, 320, 240, glm::vec3(setup.cloth.positions[setup.grab.particles[0]]));
    ASSERT_TRUE(hand && held);
    EXPECT_GE(marker_pixels_near(setup.framebuffer, *hand, 5), 50);
    // The line's midpoint is drawn, and the line reaches the held point.
    EXPECT_GT(marker_pixels_near(setup.framebuffer, 0.5f * (*hand + *held), 1), 0);
    EXPECT_GT(marker_pixels_near(setup.framebuffer, *held, 1), 0);
    EXPECT_GT(setup.total(), marker_pixels_near(setup.framebuffer, *hand, 5));
}

}  // namespace
}  // namespace weft::view
