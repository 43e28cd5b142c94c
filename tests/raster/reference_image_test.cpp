// A rendered scene against a reference image computed independently: for every pixel, the
// eye ray through its centre (built from the camera's definition, not the library's
// matrices) is intersected with each triangle analytically (Möller–Trumbore) and the nearest
// hit's flat colour is the reference.
//
// Tolerance: at most 1 % of pixels may differ, and only edge pixels — pixels whose four
// corner rays do not all see the same triangle as the centre ray — because exactly at an
// edge the two computations may round a pixel centre either way. Away from edges the images
// must be identical.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include <glm/geometric.hpp>

#include <glm/vec4.hpp>

#include "raster/camera.h"
#include "raster/framebuffer.h"
#include "raster/triangle_rasterizer.h"
#include "raster_test_support.h"

namespace weft::raster {
namespace {

using testing::intersect_triangle;
using testing::reference_ray;

struct FlatTriangle {
    glm::vec3 a, b, c;
    Rgba8 colour;
};

constexpr Rgba8 background{10, 20, 30, 255};

// Index of the nearest triangle hit through window point (x, y), or -1.
int nearest_hit(const std::vector<FlatTriangle>& scene, const Camera& camera, int width, int height,
                float x, float y) {
    const testing::ReferenceRay ray = reference_ray(camera, width, height, x, y);
    int nearest = -1;
    float nearest_distance = 1e30f;
    for (std::size_t i = 0; i < scene.size(); ++i) {
        const std::optional<float> t = intersect_triangle(ray, scene[i].a, scene[i].b, scene[i].c);
        if (t && *t < nearest_distance && *t >= camera.near_plane) {
            nearest_distance = *t;
            nearest = static_cast<int>(i);
        }
    }
    return nearest;
}

void expect_matches_ray_cast_reference(const std::vector<FlatTriangle>& scene, const Camera& camera,
                                       int width, int height) {
    Framebuffer fb(width, height);
    fb.clear(background);
    const glm::mat4 view_projection = view_projection_matrix(camera, fb);
    for (const FlatTriangle& t : scene) {
        ClipVertex v[3];
        v[0].position = view_projection * glm::vec4(t.a, 1.0f);
        v[1].position = view_projection * glm::vec4(t.b, 1.0f);
        v[2].position = view_projection * glm::vec4(t.c, 1.0f);
        draw_triangle(fb, {}, v[0], v[1], v[2], [&t](const Fragment&) { return t.colour; });
    }

    int differing = 0, covered = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const float cx = static_cast<float>(x) + 0.5f, cy = static_cast<float>(y) + 0.5f;
            const int centre = nearest_hit(scene, camera, width, height, cx, cy);
            const Rgba8 expected =
                centre < 0 ? background : scene[static_cast<std::size_t>(centre)].colour;
            if (centre >= 0) ++covered;
            if (fb.colour(x, y) == expected) continue;
            ++differing;
            bool edge = false;
            for (float dx : {-0.5f, 0.5f}) {
                for (float dy : {-0.5f, 0.5f}) {
                    edge = edge ||
                           nearest_hit(scene, camera, width, height, cx + dx, cy + dy) != centre;
                }
            }
            EXPECT_TRUE(edge) << "pixel (" << x << ", " << y << ") differs away from any edge";
        }
    }
    EXPECT_LE(differing, width * height / 100) << differing << " pixels differ";
    EXPECT_GT(covered, width * height / 4);  // the scene is really in view
}

TEST(ReferenceImage, OverlappingTrianglesMatchRayCastWithinEdgePixels) {
    // Three triangles at different depths and slants, overlapping, one interpenetrating.
    const std::vector<FlatTriangle> scene = {
        {{-1.5f, -1.0f, -0.5f}, {1.5f, -1.1f, -0.8f}, {0.0f, 1.3f, -0.6f}, {220, 60, 50, 255}},
        {{-0.4f, -0.6f, 0.4f}, {1.8f, 0.2f, -1.6f}, {0.3f, 1.0f, 0.2f}, {50, 200, 90, 255}},
        {{-1.9f, 0.8f, 0.8f}, {-0.9f, -1.4f, 0.1f}, {0.6f, 0.1f, 0.5f}, {60, 90, 230, 255}},
    };
    Camera camera = make_camera({0.3f, 0.4f, 3.0f}, {0.0f, 0.0f, 0.0f}, 50.0f);
    expect_matches_ray_cast_reference(scene, camera, 96, 64);
}

TEST(ReferenceImage, AxisAlignedQuadFacingCameraCoversItsProjectedRectangle) {
    // A unit square 2 m in front of the eye, facing it. Its projection is the rectangle
    // centre ± (0.5 / 2) / tan(fov/2) · (height/2) pixels — computable exactly.
    const int width = 80, height = 60;
    Camera camera = make_camera({0.0f, 0.0f, 2.0f}, {0.0f, 0.0f, 0.0f}, 40.0f);
    const glm::vec3 a(-0.5f, -0.5f, 0.0f), b(0.5f, -0.5f, 0.0f), c(0.5f, 0.5f, 0.0f),
        d(-0.5f, 0.5f, 0.0f);
    const std::vector<FlatTriangle> scene = {{a, b, c, {255, 255, 255, 255}},
                                             {a, c, d, {255, 255, 255, 255}}};
    expect_matches_ray_cast_reference(scene, camera, width, height);

    Framebuffer fb(width, height);
    fb.clear(background);
    const glm::mat4 view_projection = view_projection_matrix(camera, fb);
    for (const FlatTriangle& t : scene) {
        ClipVertex v[3];
        v[0].position = view_projection * glm::vec4(t.a, 1.0f);
        v[1].position = view_projection * glm::vec4(t.b, 1.0f);
        v[2].position = view_projection * glm::vec4(t.c, 1.0f);
        draw_triangle(fb, {}, v[0], v[1], v[2], [](const Fragment&) {
            return Rgba8{255, 255, 255, 255};
        });
    }
    const double half_pixels = 0.25 / std::tan(glm::radians(20.0)) * height / 2.0;
    const double x0 = width / 2.0 - half_pixels, x1 = width / 2.0 + half_pixels;
    const double y0 = height / 2.0 - half_pixels, y1 = height / 2.0 + half_pixels;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const double cx = x + 0.5, cy = y + 0.5;
            const bool inside = cx >= x0 && cx < x1 && cy >= y0 && cy < y1;
            EXPECT_EQ(fb.colour(x, y) == Rgba8(255, 255, 255, 255), inside)
                << "pixel (" << x << ", " << y << ")";
        }
    }
}

TEST(ReferenceImage, CameraInsideAFoldMatchesRayCastWithTheNearPlaneCut) {
    // A waving sheet bulging over the eye (the cloth is about 1 cm away, closer than the near
    // plane): triangles cross the near plane and reach behind the camera. The reference keeps
    // a ray's hit only if it is at least `near` ahead along the view axis — exactly what
    // clipping at z = -w keeps — and colours it by the side it sees.
    const int width = 80, height = 60, n = 24;
    std::vector<glm::vec3> grid;
    for (int r = 0; r < n; ++r) {
        for (int c = 0; c < n; ++c) {
            const float x = -1.0f + 2.0f * static_cast<float>(c) / (n - 1);
            const float y = 1.0f - 2.0f * static_cast<float>(r) / (n - 1);
            grid.push_back(
                {x, y,
                 0.10f * std::sin(3.0f * x) * std::cos(2.0f * y) + 0.05f * std::sin(5.0f * y)});
        }
    }
    const Rgba8 front{230, 120, 60, 255}, back{60, 110, 210, 255};
    std::vector<std::array<glm::vec3, 3>> triangles;
    for (int r = 0; r + 1 < n; ++r) {
        for (int c = 0; c + 1 < n; ++c) {
            const int i = r * n + c;
            triangles.push_back({grid[i], grid[i + n], grid[i + 1]});  // counter-clockwise from +z
            triangles.push_back({grid[i + 1], grid[i + n], grid[i + n + 1]});
        }
    }
    const Camera camera = make_camera({0.1f, 0.2f, 0.06f}, {0.4f, 0.7f, 0.45f}, 60.0f);

    Framebuffer fb(width, height);
    fb.clear(background);
    const glm::mat4 view_projection = view_projection_matrix(camera, fb);
    for (const auto& t : triangles) {
        ClipVertex v[3];
        for (int k = 0; k < 3; ++k) v[k].position = view_projection * glm::vec4(t[k], 1.0f);
        draw_triangle(fb, {}, v[0], v[1], v[2],
                      [&](const Fragment& f) { return f.front_facing ? front : back; });
    }

    const glm::vec3 forward = glm::normalize(camera.target - camera.position);
    auto reference = [&](float x, float y) {
        const testing::ReferenceRay ray = reference_ray(camera, width, height, x, y);
        float nearest = 1e30f;
        Rgba8 colour = background;
        for (const auto& t : triangles) {
            const std::optional<float> hit = intersect_triangle(ray, t[0], t[1], t[2]);
            if (!hit || *hit >= nearest) continue;
            if (*hit * glm::dot(ray.direction, forward) < camera.near_plane) continue;  // cut
            nearest = *hit;
            const glm::vec3 normal = glm::cross(t[1] - t[0], t[2] - t[0]);
            colour = glm::dot(normal, ray.direction) < 0.0f ? front : back;
        }
        return colour;
    };
    int differing = 0, cloth = 0, hole = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const float cx = static_cast<float>(x) + 0.5f, cy = static_cast<float>(y) + 0.5f;
            const Rgba8 expected = reference(cx, cy);
            (expected == background ? hole : cloth)++;
            if (fb.colour(x, y) == expected) continue;
            ++differing;
            bool edge = false;
            for (float dx : {-0.5f, 0.5f}) {
                for (float dy : {-0.5f, 0.5f})
                    edge = edge || reference(cx + dx, cy + dy) != expected;
            }
            EXPECT_TRUE(edge) << "pixel (" << x << ", " << y << ") differs away from any edge";
        }
    }
    EXPECT_LE(differing, width * height / 100) << differing << " pixels differ";
    EXPECT_GT(cloth, width * height / 4);  // much of the view is cloth…
    EXPECT_GT(hole, width * height / 4);   // …and much is cut away by the near plane
}

}  // namespace
}  // namespace weft::raster
