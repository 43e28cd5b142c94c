// Depth testing and interpolation. Truths: the nearer surface wins whatever the draw order;
// the depth buffer holds the projected depth of the surface point seen through each pixel
// centre (ray–plane intersection, projected with the camera's matrices), exactly the
// vertex's own depth at a vertex; and an attribute across a receding floor matches its
// analytic value at the ray's hit point (perspective-correct, not affine in screen space).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include "raster/camera.h"
#include "raster/framebuffer.h"
#include "raster/triangle_rasterizer.h"
#include "raster_test_support.h"

namespace weft::raster {
namespace {

using testing::reference_ray;
using testing::window_vertex;

constexpr Rgba8 red{255, 0, 0, 255};
constexpr Rgba8 blue{0, 0, 255, 255};
constexpr Rgba8 background{0, 0, 0, 255};

auto flat(Rgba8 colour) {
    return [colour](const Fragment&) { return colour; };
}

TEST(DepthTest, NearerTriangleWinsRegardlessOfDrawOrder) {
    Framebuffer first(32, 32), second(32, 32);
    const ClipVertex near_a = window_vertex(first, 2, 2, 0.3f),
                     near_b = window_vertex(first, 28, 6, 0.3f),
                     near_c = window_vertex(first, 6, 28, 0.3f);
    const ClipVertex far_a = window_vertex(first, 30, 30, 0.6f),
                     far_b = window_vertex(first, 3, 12, 0.6f),
                     far_c = window_vertex(first, 26, 1, 0.6f);
    first.clear(background);
    draw_triangle(first, {}, near_a, near_b, near_c, flat(red));
    draw_triangle(first, {}, far_a, far_b, far_c, flat(blue));
    second.clear(background);
    draw_triangle(second, {}, far_a, far_b, far_c, flat(blue));
    draw_triangle(second, {}, near_a, near_b, near_c, flat(red));
    int overlap = 0;
    for (int y = 0; y < 32; ++y) {
        for (int x = 0; x < 32; ++x) {
            ASSERT_EQ(first.colour(x, y), second.colour(x, y))
                << "pixel (" << x << ", " << y << ")";
            ASSERT_EQ(first.depth(x, y), second.depth(x, y));
            if (first.colour(x, y) == red && first.depth(x, y) < 0.31f) ++overlap;
        }
    }
    EXPECT_GT(overlap, 150);
    EXPECT_EQ(first.colour(12, 12), red);  // inside both triangles
}

TEST(DepthTest, InterpenetratingTrianglesShowTheNearerSurfacePerPixel) {
    // Two triangles crossing each other in depth: per pixel, the one with the smaller
    // analytic depth (each is a plane in window space) must show.
    Framebuffer fb(48, 48);
    fb.clear(background);
    const glm::vec3 a[3] = {{2, 2, 0.2f}, {46, 6, 0.8f}, {10, 44, 0.5f}};
    const glm::vec3 b[3] = {{44, 44, 0.25f}, {4, 20, 0.75f}, {40, 3, 0.4f}};
    auto vertex = [&](const glm::vec3& p) { return window_vertex(fb, p.x, p.y, p.z); };
    draw_triangle(fb, {}, vertex(a[0]), vertex(a[1]), vertex(a[2]), flat(red));
    draw_triangle(fb, {}, vertex(b[0]), vertex(b[1]), vertex(b[2]), flat(blue));
    auto plane_depth = [](const glm::vec3(&t)[3], float x, float y, float& depth) {
        const glm::vec3 n = glm::cross(t[1] - t[0], t[2] - t[0]);
        const float d0 = (t[1].x - t[0].x) * (y - t[0].y) - (t[1].y - t[0].y) * (x - t[0].x);
        const float d1 = (t[2].x - t[1].x) * (y - t[1].y) - (t[2].y - t[1].y) * (x - t[1].x);
        const float d2 = (t[0].x - t[2].x) * (y - t[2].y) - (t[0].y - t[2].y) * (x - t[2].x);
        depth = t[0].z - (n.x * (x - t[0].x) + n.y * (y - t[0].y)) / n.z;
        return (d0 > 0 && d1 > 0 && d2 > 0) || (d0 < 0 && d1 < 0 && d2 < 0);
    };
    int both = 0;
    for (int y = 0; y < 48; ++y) {
        for (int x = 0; x < 48; ++x) {
            float depth_a = 0, depth_b = 0;
            const float cx = static_cast<float>(x) + 0.5f, cy = static_cast<float>(y) + 0.5f;
            if (!plane_depth(a, cx, cy, depth_a) || !plane_depth(b, cx, cy, depth_b)) continue;
            if (std::abs(depth_a - depth_b) < 1e-4f) continue;  // the intersection line itself
            ++both;
            EXPECT_EQ(fb.colour(x, y), depth_a < depth_b ? red : blue)
                << "pixel (" << x << ", " << y << ")";
        }
    }
    EXPECT_GT(both, 200);
}

TEST(DepthTest, DepthBufferHoldsProjectedDepthOfTheSurfaceSeenThroughEachPixel) {
    const int width = 40, height = 30;
    Framebuffer fb(width, height);
    Camera camera = make_camera({0.4f, 0.7f, 2.5f}, {0.0f, 0.0f, 0.0f}, 55.0f);
    const glm::vec3 p[3] = {{-1.2f, -0.4f, 0.5f}, {1.4f, -0.2f, -1.5f}, {0.1f, 1.1f, -0.3f}};
    const glm::mat4 view_projection = view_projection_matrix(camera, fb);
    ClipVertex v[3];
    for (int i = 0; i < 3; ++i) v[i].position = view_projection * glm::vec4(p[i], 1.0f);
    draw_triangle(fb, {}, v[0], v[1], v[2], flat(red));

    const glm::vec3 normal = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
    int checked = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            if (fb.colour(x, y) != red) continue;
            const testing::ReferenceRay ray = reference_ray(
                camera, width, height, static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
            const float t = glm::dot(p[0] - ray.origin, normal) / glm::dot(ray.direction, normal);
            const glm::vec4 clip =
                view_projection * glm::vec4(ray.origin + t * ray.direction, 1.0f);
            const float expected = clip.z / clip.w * 0.5f + 0.5f;
            EXPECT_NEAR(fb.depth(x, y), expected, 2e-6f) << "pixel (" << x << ", " << y << ")";
            ++checked;
        }
    }
    EXPECT_GT(checked, 150);
}

TEST(DepthTest, DepthAtAVertexPixelIsThatVertexsProjectedDepth) {
    // A fan of triangles around a vertex placed exactly on a pixel centre: the fan covers
    // that pixel, whose depth must be the vertex's own, however deep the rim vertices are.
    const int width = 32, height = 32;
    Framebuffer fb(width, height);
    Camera camera = make_camera({0.0f, 0.0f, 3.0f}, {0.0f, 0.0f, 0.0f}, 50.0f);
    const glm::mat4 view_projection = view_projection_matrix(camera, fb);
    const float centre_distances[] = {0.3f, 1.7f, 4.0f, 25.0f};
    for (float distance : centre_distances) {
        fb.clear(background);
        const float px = 13.5f, py = 17.5f;
        const glm::vec3 centre = reference_ray(camera, width, height, px, py).origin +
                                 distance * reference_ray(camera, width, height, px, py).direction;
        std::vector<glm::vec3> rim;
        for (int i = 0; i < 7; ++i) {
            const float angle = 2.0f * std::numbers::pi_v<float> * static_cast<float>(i) / 7.0f;
            rim.push_back(centre + glm::vec3(0.3f * std::cos(angle), 0.3f * std::sin(angle),
                                             (i % 2 == 0 ? 0.4f : -0.5f) * distance * 0.2f));
        }
        auto vertex = [&](const glm::vec3& world) {
            ClipVertex v;
            v.position = view_projection * glm::vec4(world, 1.0f);
            return v;
        };
        for (int i = 0; i < 7; ++i) {
            draw_triangle(fb, {}, vertex(centre), vertex(rim[i]), vertex(rim[(i + 1) % 7]),
                          flat(red));
        }
        const glm::vec4 clip = view_projection * glm::vec4(centre, 1.0f);
        ASSERT_EQ(fb.colour(13, 17), red) << "distance " << distance;
        EXPECT_NEAR(fb.depth(13, 17), clip.z / clip.w * 0.5f + 0.5f, 1e-6f)
            << "distance " << distance;
    }
}

TEST(Interpolation, AttributeAlongRecedingFloorIsPerspectiveCorrect) {
    // A floor quad reaching from about 1.5 m to over 25 m ahead; varying 0 is the world z. Seen
    // through a pixel, the correct value is the z of the ray's hit point on the floor;
    // affine screen-space interpolation would be off by metres. The corners are where the
    // rays through points of the 1/256-pixel lattice meet the floor, so snapping moves
    // nothing and the only error left is rounding.
    const int width = 48, height = 48;
    Framebuffer fb(width, height);
    Camera camera = make_camera({0.0f, 1.0f, 0.0f}, {0.0f, 0.6f, -1.0f}, 60.0f);
    const glm::mat4 view_projection = view_projection_matrix(camera, fb);
    const glm::vec2 window_corners[4] = {
        {3.0f, 46.5f}, {44.25f, 46.0f}, {34.5f, 8.25f}, {12.0f, 8.5f}};
    glm::vec3 corners[4];
    ClipVertex v[4];
    for (int i = 0; i < 4; ++i) {
        const auto ray =
            reference_ray(camera, width, height, window_corners[i].x, window_corners[i].y);
        corners[i] = ray.origin + (-ray.origin.y / ray.direction.y) * ray.direction;
        v[i].position = view_projection * glm::vec4(corners[i], 1.0f);
        v[i].varyings[0] = corners[i].z;
        v[i].varyings[1] = 1.0f;  // a constant must stay exactly constant
    }
    ASSERT_GT(corners[2].z, -80.0f);
    ASSERT_LT(corners[2].z, -25.0f);
    std::vector<float> value(static_cast<std::size_t>(width * height), 0.0f);
    std::vector<float> constant(value.size(), 0.0f);
    RasterState state;
    state.varying_count = 2;
    auto record = [&](const Fragment& f) {
        value[static_cast<std::size_t>(f.y * width + f.x)] = f.varyings[0];
        constant[static_cast<std::size_t>(f.y * width + f.x)] = f.varyings[1];
        return red;
    };
    draw_triangle(fb, state, v[0], v[1], v[2], record);
    draw_triangle(fb, state, v[0], v[2], v[3], record);

    int checked = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            if (fb.colour(x, y) != red) continue;
            const auto ray = reference_ray(camera, width, height, static_cast<float>(x) + 0.5f,
                                           static_cast<float>(y) + 0.5f);
            const float t = -ray.origin.y / ray.direction.y;
            const float expected = ray.origin.z + t * ray.direction.z;
            const std::size_t i = static_cast<std::size_t>(y * width + x);
            EXPECT_NEAR(value[i], expected, 2e-5f * std::abs(expected))
                << "pixel (" << x << ", " << y << ")";
            EXPECT_NEAR(constant[i], 1.0f, 1e-6f);
            ++checked;
        }
    }
    EXPECT_GT(checked, 300);
    // Sanity check that the test has teeth: z varies non-linearly down the screen, so the
    // midpoint (in screen y) of two covered pixels in one column is not the mean of their z.
    const int column = width / 2;
    int top = -1, bottom = -1;
    for (int y = 0; y < height; ++y) {
        if (fb.colour(column, y) != red) continue;
        if (top < 0) top = y;
        bottom = y;
    }
    ASSERT_GT(bottom - top, 10);
    const int middle = (top + bottom) / 2;
    const float mean = 0.5f * (value[static_cast<std::size_t>(top * width + column)] +
                               value[static_cast<std::size_t>(bottom * width + column)]);
    EXPECT_GT(std::abs(value[static_cast<std::size_t>(middle * width + column)] - mean), 2.0f);
}

}  // namespace
}  // namespace weft::raster
