// Home frames the cloth: the camera placed along its own direction so the cloth's box fills
// the view with a margin, checked by projecting the box's corners through the camera the
// rasterizer draws with.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <vector>

#include "app/camera_framing.h"
#include "raster/camera.h"
#include "sim/build/cloth_builder.h"

namespace weft::app {
namespace {

struct ViewPx {
    int width, height;
};

// How far the box's corners reach toward the view's edges: the largest |x| and |y| over the
// corners in normalised window units (0 the centre, 1 the edge), or nothing if one is not in
// front of the camera.
std::optional<float> reach_of_corners(const CameraRig& rig, const Box& box, ViewPx view) {
    float reach = 0.0f;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p(corner & 1 ? box.high.x : box.low.x, corner & 2 ? box.high.y : box.low.y,
                          corner & 4 ? box.high.z : box.low.z);
        auto at = raster::project_to_window(rig.camera(), view.width, view.height, p);
        if (!at) return std::nullopt;
        reach = std::max({reach, std::abs(at->x / (0.5f * float(view.width)) - 1.0f),
                          std::abs(at->y / (0.5f * float(view.height)) - 1.0f)});
    }
    return reach;
}

TEST(CameraFraming, EveryCornerInsideTheViewAndOneOnTheMarginsBorder) {
    const std::vector<Box> boxes = {
        {{-0.6f, -1.2f, -0.1f}, {0.6f, 0.0f, 0.1f}},    // a hanging sheet
        {{-1.0f, -0.05f, -1.0f}, {1.0f, 0.05f, 1.0f}},  // a sheet lying flat
        {{2.0f, 3.0f, -7.0f}, {2.5f, 3.2f, -6.0f}},     // small and far from the origin
    };
    const std::vector<CameraRig> rigs = {
        CameraRig::looking_at({0.0f, 0.0f, 3.0f}, {0.0f, -0.5f, 0.0f}, 50.0f),
        CameraRig::looking_at({1.9f, 0.2f, -1.2f}, {0.0f, -0.1f, -0.1f}, 50.0f),
        CameraRig::looking_at({0.0f, 5.0f, 0.5f}, {0.0f, 0.0f, 0.0f}, 30.0f),  // from above
        CameraRig::looking_at({-3.0f, -1.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, 70.0f),
    };
    const std::vector<ViewPx> views = {{896, 720}, {500, 600}, {1920, 400}, {300, 900}};
    for (const Box& box : boxes) {
        for (const CameraRig& rig : rigs) {
            for (ViewPx view : views) {
                const CameraRig home =
                    framed(rig, box, float(view.width) / float(view.height), frame_margin);
                EXPECT_LT(glm::length(home.forward() - rig.forward()), 1e-6f);  // same direction
                EXPECT_LT(glm::length(home.target() - box.centre()), 1e-4f);  // looks at its centre
                const std::optional<float> reach = reach_of_corners(home, box, view);
                ASSERT_TRUE(reach.has_value());
                EXPECT_LE(*reach, 1.0f - frame_margin + 1e-3f) << view.width << "x" << view.height;
                EXPECT_GE(*reach, 1.0f - frame_margin - 1e-3f) << view.width << "x" << view.height;
            }
        }
    }
}

TEST(CameraFraming, CloseUpOrFarAwayTheSameFrame) {
    const Box sheet{{-0.6f, -1.2f, 0.0f}, {0.6f, 0.0f, 0.0f}};
    const CameraRig near_rig =
        CameraRig::looking_at({0.1f, -0.5f, 0.2f}, {0.1f, -0.5f, 0.0f}, 50.0f);
    const CameraRig far_rig = CameraRig::looking_at({0.0f, 0.0f, 40.0f}, {0.0f, 0.0f, 0.0f}, 50.0f);
    const CameraRig a = framed(near_rig, sheet, 1.5f), b = framed(far_rig, sheet, 1.5f);
    EXPECT_LT(glm::length(a.position - b.position), 1e-4f);
    EXPECT_NEAR(a.target_distance, b.target_distance, 1e-4f);
}

TEST(CameraFraming, BoundingBoxHoldsEveryParticle) {
    const std::vector<Vec3> positions = {{0.0, 1.0, -2.0}, {3.0, -1.0, 0.5}, {-1.0, 0.0, 0.0}};
    const Box box = bounding_box(positions);
    EXPECT_EQ(box.low, glm::vec3(-1.0f, -1.0f, -2.0f));
    EXPECT_EQ(box.high, glm::vec3(3.0f, 1.0f, 0.5f));
    const Box empty = bounding_box({});
    EXPECT_EQ(empty.low, empty.high);
}

// Home after a cut: the box is the larger piece's, not one around a scrap that fell away.
TEST(CameraFraming, TheLargestPieceIsFramedNotAScrapThatFellAway) {
    Scene scene;
    scene.cloth.rows = 10;
    scene.cloth.cols = 10;
    scene.shear.enabled = scene.bend.enabled = true;
    Cloth cloth = build_cloth(scene);
    const Box whole = bounding_box(cloth.positions);
    const Box one_piece = largest_piece_box(cloth);
    EXPECT_EQ(one_piece.low, whole.low);
    EXPECT_EQ(one_piece.high, whole.high);
    // Cut every spring between columns 0-2 and 3-9, and drop the three columns 50 m.
    auto column = [&](std::uint32_t p) { return static_cast<int>(p) % cloth.cols; };
    for (SpringGroup& group : cloth.edit_topology().spring_groups)
        std::erase_if(group.springs,
                      [&](const Spring& s) { return (column(s.i) <= 2) != (column(s.j) <= 2); });
    Vec3 low_of_rest(1e9), high_of_rest(-1e9);
    for (std::uint32_t p = 0; p < cloth.positions.size(); ++p) {
        if (column(p) <= 2) {
            cloth.positions[p].y -= 50.0;
        } else {
            low_of_rest = glm::min(low_of_rest, cloth.positions[p]);
            high_of_rest = glm::max(high_of_rest, cloth.positions[p]);
        }
    }
    const Box piece = largest_piece_box(cloth);
    EXPECT_EQ(piece.low, glm::vec3(low_of_rest));
    EXPECT_EQ(piece.high, glm::vec3(high_of_rest));
    // A particle at no finite position is left out.
    cloth.positions[99] = Vec3(std::nan(""), 0.0, 0.0);
    EXPECT_TRUE(std::isfinite(largest_piece_box(cloth).low.x));
}

}  // namespace
}  // namespace weft::app
