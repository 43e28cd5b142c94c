// The keyboard camera: aimed where asked, moving and turning independently of frame rate.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "app/camera_rig.h"

namespace weft::app {
namespace {

void expect_near(const glm::vec3& a, const glm::vec3& b, float tolerance) {
    EXPECT_LT(glm::length(a - b), tolerance)
        << a.x << " " << a.y << " " << a.z << " vs " << b.x << " " << b.y << " " << b.z;
}

TEST(CameraRig, LooksAtItsTarget) {
    const CameraRig rig = CameraRig::looking_at({1.0f, 2.0f, 3.0f}, {0.0f, 0.5f, -1.0f}, 50.0f);
    expect_near(rig.forward(), glm::normalize(glm::vec3(-1.0f, -1.5f, -4.0f)), 1e-5f);
    const raster::Camera camera = rig.camera();
    expect_near(glm::normalize(camera.target - camera.position), rig.forward(), 1e-5f);
}

TEST(CameraRig, MotionDoesNotDependOnTheFrameRate) {
    CameraRig fast = CameraRig::looking_at({0, 0, 3}, {0, 0, 0}, 50.0f), slow = fast;
    for (int frame = 0; frame < 100; ++frame)
        fast.move({1.0f, 0.0f, 1.0f}, 1.0f, 0.01f), fast.turn(0.5f, 0.2f, 0.01f);
    slow.move({1.0f, 0.0f, 1.0f}, 1.0f, 1.0f);
    slow.turn(0.5f, 0.2f, 1.0f);
    // Moving before turning at each frame differs from one big move by the turn's effect
    // on later moves; compare positions of pure moves and headings of pure turns.
    CameraRig a = CameraRig::looking_at({0, 0, 3}, {0, 0, 0}, 50.0f), b = a;
    for (int frame = 0; frame < 100; ++frame) a.move({1.0f, 0.5f, -1.0f}, 2.0f, 0.01f);
    b.move({1.0f, 0.5f, -1.0f}, 2.0f, 1.0f);
    expect_near(a.position, b.position, 1e-4f);
    EXPECT_NEAR(fast.yaw, slow.yaw, 1e-5f);
    EXPECT_NEAR(fast.pitch, slow.pitch, 1e-5f);
}

TEST(CameraRig, ForwardMovesAlongTheViewAndPitchStopsShortOfVertical) {
    CameraRig rig = CameraRig::looking_at({0, 0, 3}, {0, 0, 0}, 50.0f);
    rig.move({0.0f, 0.0f, 1.0f}, 1.0f, 1.0f);
    expect_near(rig.position, {0, 0, 2}, 1e-6f);
    rig.turn(0.0f, 10.0f, 1.0f);  // far past straight up
    EXPECT_LT(rig.forward().y, 1.0f);
    EXPECT_GT(rig.forward().y, 0.999f);
    rig.turn(static_cast<float>(M_PI / 2), -10.0f, 1.0f);
    EXPECT_GT(rig.forward().y, -1.0f);
}

}  // namespace
}  // namespace weft::app
