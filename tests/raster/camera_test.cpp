// The camera. Truths: the target appears at the centre of the screen; points on the near and
// far planes get depths 0 and 1; and the pixel ray (built from the camera frame and the fov)
// and the projection (glm's matrices) are inverse to each other — two independent
// computations that must agree.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <glm/geometric.hpp>

#include "raster/camera.h"

namespace weft::raster {
namespace {

TEST(Camera, TargetProjectsToTheCentreOfTheWindow) {
    const Camera camera = make_camera({1.0f, 2.0f, 3.0f}, {-0.5f, 0.2f, 0.1f}, 45.0f);
    const auto window = project_to_window(camera, 640, 480, camera.target);
    ASSERT_TRUE(window.has_value());
    EXPECT_NEAR(window->x, 320.0f, 1e-3f);
    EXPECT_NEAR(window->y, 240.0f, 1e-3f);
}

TEST(Camera, NearAndFarPlanesMapToDepthZeroAndOne) {
    Camera camera = make_camera({0, 0, 0}, {0, 0, -1}, 60.0f);
    camera.near_plane = 0.1f;
    camera.far_plane = 50.0f;
    EXPECT_NEAR(project_to_window(camera, 100, 100, {0, 0, -0.1f})->z, 0.0f, 1e-5f);
    EXPECT_NEAR(project_to_window(camera, 100, 100, {0, 0, -50.0f})->z, 1.0f, 1e-5f);
    EXPECT_FALSE(project_to_window(camera, 100, 100, {0, 0, 1.0f}).has_value());    // behind
    EXPECT_FALSE(project_to_window(camera, 100, 100, {0, 0, -0.05f}).has_value());  // too near
}

TEST(Camera, UpOnScreenIsUpInTheWorldAndRightIsRight) {
    const Camera camera = make_camera({0, 0, 5}, {0, 0, 0}, 50.0f);
    EXPECT_LT(project_to_window(camera, 100, 100, {0, 1, 0})->y, 50.0f);  // rows count down
    EXPECT_GT(project_to_window(camera, 100, 100, {1, 0, 0})->x, 50.0f);
}

TEST(Camera, RayThroughAPixelProjectsBackOntoThatPixel) {
    const int width = 1280, height = 720;
    const Camera camera = make_camera({0.7f, 1.3f, 2.9f}, {0.1f, -0.4f, 0.0f}, 50.0f);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> x(0.0f, 1280.0f), y(0.0f, 720.0f), distance(0.2f, 40.0f);
    for (int i = 0; i < 200; ++i) {
        const glm::vec2 pixel(x(rng), y(rng));
        const Ray ray = camera_ray(camera, width, height, pixel);
        EXPECT_NEAR(glm::length(ray.direction), 1.0f, 1e-6f);
        EXPECT_EQ(ray.origin, camera.position);
        const auto window = project_to_window(camera, width, height, ray.at(distance(rng)));
        ASSERT_TRUE(window.has_value());
        EXPECT_NEAR(window->x, pixel.x, 2e-3f);
        EXPECT_NEAR(window->y, pixel.y, 2e-3f);
    }
    const Ray centre = camera_ray(camera, width, height, {640.0f, 360.0f});
    const glm::vec3 forward = glm::normalize(camera.target - camera.position);
    EXPECT_NEAR(glm::dot(centre.direction, forward), 1.0f, 1e-6f);
}

TEST(Camera, DegenerateSetupsStillGiveFiniteMatrices) {
    const Camera cameras[] = {
        make_camera({0, 0, 0}, {0, 0, 0}, 50.0f),   // target on the eye
        make_camera({0, 5, 0}, {0, 0, 0}, 50.0f),   // looking straight down the up axis
        make_camera({0, 0, 3}, {0, 0, 0}, 0.0f),    // zero fov
        make_camera({0, 0, 3}, {0, 0, 0}, 400.0f),  // absurd fov
    };
    for (const Camera& camera : cameras) {
        const glm::mat4 m = view_projection_matrix(camera, 64, 48);
        for (int c = 0; c < 4; ++c) {
            for (int r = 0; r < 4; ++r) EXPECT_TRUE(std::isfinite(m[c][r]));
        }
        const Ray ray = camera_ray(camera, 64, 48, {10.0f, 20.0f});
        EXPECT_TRUE(std::isfinite(ray.direction.x) && std::isfinite(ray.direction.y) &&
                    std::isfinite(ray.direction.z));
    }
    Camera flat = make_camera({0, 0, 3}, {0, 0, 0}, 50.0f);
    flat.near_plane = -1.0f;
    flat.far_plane = -2.0f;
    const glm::mat4 m = view_projection_matrix(flat, 64, 48);
    EXPECT_TRUE(std::isfinite(m[2][2]) && std::isfinite(m[3][2]));
}

}  // namespace
}  // namespace weft::raster
