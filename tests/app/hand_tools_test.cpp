// The hand tools in window terms: grabbing only the cloth, the grab plane, cut strokes.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "app/hand_tools.h"

namespace weft::app {
namespace {

// A 5x5 vertical sheet 0.4 m wide centred on the view of a camera 2 m in front of it.
Simulation facing_sheet() {
    Scene scene;
    scene.cloth.rows = 5;
    scene.cloth.cols = 5;
    scene.cloth.spacing = 0.1;
    scene.cloth.origin = {-0.2, 0.2, 0.0};
    return Simulation(scene);
}

raster::Camera facing_camera() {
    return raster::make_camera({0.0f, 0.0f, 2.0f}, {0.0f, 0.0f, 0.0f}, 50.0f);
}

TEST(HandTools, TheCursorOverTheSheetFindsItAndTheBackgroundDoesNot) {
    const Simulation sim = facing_sheet();
    const raster::Camera camera = facing_camera();
    auto hit = cloth_under_cursor(sim.cloth(), camera, 800, 600, {400.0f, 300.0f});
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->particle, 2u * 5 + 2);  // the centre particle
    EXPECT_FALSE(cloth_under_cursor(sim.cloth(), camera, 800, 600, {50.0f, 50.0f}).has_value());
}

TEST(HandTools, TheGrabPlaneKeepsTheGrabDepth) {
    const raster::Camera camera = facing_camera();
    const Vec3 anchor(0.0, 0.0, 0.0);
    auto point = point_on_grab_plane(camera, 800, 600, {600.0f, 300.0f}, anchor);
    ASSERT_TRUE(point.has_value());
    EXPECT_NEAR(point->z, 0.0, 1e-6);  // same depth as the anchor
    EXPECT_GT(point->x, 0.2);          // to the right, where the cursor is
    EXPECT_NEAR(point->y, 0.0, 1e-6);
}

TEST(HandTools, SegmentsCrossOnlyWhenTheyCross) {
    EXPECT_TRUE(segments_cross({0, 0}, {2, 2}, {0, 2}, {2, 0}));
    EXPECT_FALSE(segments_cross({0, 0}, {1, 1}, {2, 0}, {3, 1}));
    EXPECT_FALSE(segments_cross({0, 0}, {2, 0}, {0, 1}, {2, 1}));  // parallel
}

TEST(HandTools, AVerticalStrokeThroughTheMiddleCutsTheHorizontalSpringsItCrosses) {
    Simulation sim = facing_sheet();
    const std::size_t before = sim.cloth().spring_count();
    // From above the sheet to below it, between columns 1 and 2 (x = -0.05 m).
    const float x = 400.0f - 0.05f * 300.0f / (2.0f * std::tan(25.0f * 3.14159265f / 180.0f));
    const std::size_t cut =
        cut_along_stroke(sim, facing_camera(), 800, 600, {x, 50.0f}, {x, 550.0f});
    EXPECT_EQ(cut, 5u);  // the structural spring (r, 1)-(r, 2) of each of the 5 rows
    EXPECT_EQ(sim.cloth().spring_count(), before - 5);
}

}  // namespace
}  // namespace weft::app
