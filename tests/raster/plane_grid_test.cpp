// Grids on planes (the ground, and tilted plane colliders such as a slope). Truths: the
// ground grid is the plane grid of a horizontal plane, pixel for pixel; every pixel a tilted
// grid draws looks at a point of its plane, inside the grid and on one of its lines (to
// within the pixel's footprint there).
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <span>

#include "raster/camera.h"
#include "raster/framebuffer.h"
#include "raster/ground_grid.h"

namespace weft::raster {
namespace {

constexpr Rgba8 background{0, 0, 0, 255};

TEST(PlaneGrid, TheGroundGridIsThePlaneGridOfAHorizontalPlane) {
    const Camera camera = make_camera({1.5f, 1.2f, 2.5f}, {0.0f, -0.4f, 0.0f}, 50.0f);
    Framebuffer ground(320, 240), plane(320, 240);
    ground.clear(background);
    plane.clear(background);
    GroundGrid grid;
    grid.height = -0.4f;
    grid.centre = {0.25f, -0.5f};
    draw_ground_grid(ground, camera, grid);
    PlaneGrid same = PlaneGrid::facing({0.25f, -0.4f, -0.5f}, {0.0f, 2.0f, 0.0f});
    draw_plane_grid(plane, camera, same);
    int drawn = 0;
    for (int y = 0; y < 240; ++y)
        for (int x = 0; x < 320; ++x) {
            ASSERT_EQ(ground.colour(x, y), plane.colour(x, y)) << x << ", " << y;
            drawn += !(ground.colour(x, y) == background);
        }
    EXPECT_GT(drawn, 1000);
}

TEST(PlaneGrid, EveryPixelOfATiltedGridLooksAtOneOfItsLines) {
    const int width = 400, height = 300;
    const float fov = 50.0f;
    const Camera camera = make_camera({2.4f, 1.1f, 1.2f}, {0.0f, -0.4f, 0.5f}, fov);
    const glm::vec3 normal = glm::normalize(glm::vec3(0.0f, 0.90631f, 0.42262f));  // 25° slope
    const glm::vec3 centre(0.0f, -0.3f, 0.6438f);
    PlaneGrid grid = PlaneGrid::facing(centre, normal);
    grid.cell_count = 8;
    EXPECT_NEAR(glm::dot(grid.axis_u, normal), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(grid.axis_v, normal), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(grid.axis_u, grid.axis_v), 0.0f, 1e-6f);
    EXPECT_NEAR(grid.axis_u.y, 0.0f, 1e-6f);  // across the slope: level
    Framebuffer framebuffer(width, height);
    framebuffer.clear(background);
    draw_plane_grid(framebuffer, camera, grid);
    const float half = 0.5f * static_cast<float>(grid.cell_count) * grid.cell_size;
    const float pixel_angle =
        2.0f * std::tan(glm::radians(0.5f * fov)) / static_cast<float>(height);
    int drawn = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            if (framebuffer.colour(x, y) == background) continue;
            ++drawn;
            const Ray ray =
                camera_ray(camera, width, height,
                           {static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f});
            const float facing = glm::dot(ray.direction, normal);
            ASSERT_NE(facing, 0.0f);
            const float distance = glm::dot(centre - ray.origin, normal) / facing;
            ASSERT_GT(distance, 0.0f) << "a pixel looks away from the plane";
            const glm::vec3 hit = ray.at(distance) - centre;
            // Two pixels of slack, stretched by how obliquely the ray meets the plane.
            const float slack = 2.0f * pixel_angle * distance / std::abs(facing);
            const float u = glm::dot(hit, grid.axis_u) + half,
                        v = glm::dot(hit, grid.axis_v) + half;
            ASSERT_GE(u, -slack);
            ASSERT_LE(u, 2 * half + slack);
            ASSERT_GE(v, -slack);
            ASSERT_LE(v, 2 * half + slack);
            auto off_line = [&](float w) {
                const float r = std::fmod(w, grid.cell_size);
                return std::min(r, grid.cell_size - r);
            };
            EXPECT_LE(std::min(off_line(u), off_line(v)), slack) << x << ", " << y;
        }
    EXPECT_GT(drawn, 500);
}

// The grid draws its lines in batches; a grid of more lines than a batch holds must still be
// exactly its 2 (cells + 1) lines, each drawn on its own here from the grid's definition.
TEST(PlaneGrid, AGridOfManyCellsIsExactlyItsLines) {
    const Camera camera = make_camera({0.3f, 6.0f, 0.4f}, {0.0f, 0.0f, 0.0f}, 70.0f);
    PlaneGrid grid = PlaneGrid::facing({0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f});
    grid.cell_count = 41;  // 84 lines
    grid.cell_size = 0.2f;
    Framebuffer batched(400, 300), one_by_one(400, 300);
    batched.clear(background);
    one_by_one.clear(background);
    draw_plane_grid(batched, camera, grid);
    const float extent = static_cast<float>(grid.cell_count) * grid.cell_size;
    const glm::vec3 corner = grid.centre - 0.5f * extent * (grid.axis_u + grid.axis_v);
    for (int i = 0; i <= grid.cell_count; ++i) {
        const float offset = static_cast<float>(i) * grid.cell_size;
        const Rgba8 colour = 2 * i == grid.cell_count ? grid.centre_colour : grid.colour;
        const glm::vec3 u_line = corner + offset * grid.axis_u;
        const glm::vec3 v_line = corner + offset * grid.axis_v;
        const LineSegment lines[2] = {{u_line, u_line + extent * grid.axis_v, colour, colour},
                                      {v_line, v_line + extent * grid.axis_u, colour, colour}};
        for (const LineSegment& line : lines)
            draw_lines(one_by_one, camera, std::span<const LineSegment>(&line, 1));
    }
    int drawn = 0;
    for (int y = 0; y < 300; ++y)
        for (int x = 0; x < 400; ++x) {
            ASSERT_EQ(batched.colour(x, y), one_by_one.colour(x, y)) << x << ", " << y;
            drawn += !(batched.colour(x, y) == background);
        }
    EXPECT_GT(drawn, 84 * 100);  // every line crosses most of the view
}

}  // namespace
}  // namespace weft::raster
