// Picking: a ray grabs the cloth only where it actually meets an intact triangle.
#include <gtest/gtest.h>

#include "sim/build/cloth_builder.h"
#include "sim/build/topology_edits.h"
#include "sim/interaction/picking.h"

namespace weft {
namespace {

// A 5×5 vertical sheet from (0, 0, 0) to (0.4, -0.4, 0), spacing 0.1 m, in the z = 0 plane.
Cloth flat_sheet() {
    Scene scene;
    scene.cloth.rows = 5;
    scene.cloth.cols = 5;
    scene.cloth.spacing = 0.1;
    return build_grid_cloth(scene);
}

TEST(Picking, ARayThroughTheSheetHitsItAtTheRightPointAndCorner) {
    const Cloth cloth = flat_sheet();
    // From z = 2 straight at (0.12, -0.21): nearest particle is (row 2, col 1).
    auto hit = cast_ray(cloth, {0.12, -0.21, 2.0}, {0.0, 0.0, -1.0});
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(hit->distance, 2.0, 1e-12);
    EXPECT_NEAR(hit->point.x, 0.12, 1e-12);
    EXPECT_NEAR(hit->point.y, -0.21, 1e-12);
    EXPECT_EQ(hit->particle, 2u * 5 + 1);
    // From behind, too: cloth has two sides.
    auto from_behind = cast_ray(cloth, {0.12, -0.21, -1.0}, {0.0, 0.0, 1.0});
    ASSERT_TRUE(from_behind.has_value());
    EXPECT_EQ(from_behind->particle, hit->particle);
}

TEST(Picking, ARayThatMissesGrabsNothing) {
    const Cloth cloth = flat_sheet();
    EXPECT_FALSE(cast_ray(cloth, {0.6, -0.2, 2.0}, {0.0, 0.0, -1.0}).has_value());  // beside it
    EXPECT_FALSE(cast_ray(cloth, {0.2, -0.2, 2.0}, {0.0, 0.0, 1.0}).has_value());   // away from it
    EXPECT_FALSE(cast_ray(cloth, {0.2, -0.2, 2.0}, {1.0, 0.0, 0.0}).has_value());   // parallel
}

TEST(Picking, ARayThroughATearGrabsNothing) {
    Cloth cloth = flat_sheet();
    // Cut every spring touching particle (2, 2): the four cells around it lose their triangles.
    const std::uint32_t centre = 2 * 5 + 2;
    remove_springs_if(cloth, [&](const Spring& s) { return s.i == centre || s.j == centre; });
    EXPECT_FALSE(cast_ray(cloth, {0.2, -0.2, 2.0}, {0.0, 0.0, -1.0}).has_value());
    EXPECT_TRUE(cast_ray(cloth, {0.05, -0.05, 2.0}, {0.0, 0.0, -1.0}).has_value());  // a far cell
}

}  // namespace
}  // namespace weft
