// Near-plane clipping. Truths: the clipped polygon lies in front of the near plane and its
// varyings are the linear blend of the originals; a ground triangle reaching behind the
// camera draws only below the horizon (wrapping around would paint the sky), exactly where
// eye rays hit it; and quads crossing the near plane still share their diagonal without
// cracks, which needs the clipper to cut a shared edge identically in both triangles.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "raster/camera.h"
#include "raster/clipping.h"
#include "raster/framebuffer.h"
#include "raster/triangle_rasterizer.h"
#include "raster_test_support.h"

namespace weft::raster {
namespace {

using testing::CoverageCounter;
using testing::intersect_triangle;
using testing::no_depth_state;
using testing::reference_ray;

ClipVertex clip_vertex(float x, float y, float z, float w, float varying) {
    ClipVertex v;
    v.position = {x, y, z, w};
    v.varyings[0] = varying;
    return v;
}

TEST(TriangleClipping, OneVertexBehindNearPlaneGivesAQuadInFront) {
    const ClipVertex a = clip_vertex(-1, -1, 0, 1, 0), b = clip_vertex(1, -1, 0, 1, 1);
    const ClipVertex c = clip_vertex(0, 1, -3, 1, 2);  // z < -w
    ClippedPolygon polygon;
    clip_triangle(a, b, c, outside_near, 1, polygon);
    ASSERT_EQ(polygon.count, 4);
    for (int i = 0; i < polygon.count; ++i) {
        const glm::vec4& p = polygon.vertices[i].position;
        EXPECT_GE(p.z + p.w, -1e-6f);
        // Varying 0 was set to blend like the vertex index; the cut points lie a third of
        // the way from the inside vertex (z + w: 1 inside, -2 outside).
        if (std::abs(p.z + p.w) < 1e-6f) {
            EXPECT_NEAR(p.y, -1.0f + 2.0f / 3.0f, 1e-6f);
        }
    }
    EXPECT_FLOAT_EQ(polygon.vertices[2].varyings[0], 1.0f + 1.0f / 3.0f);  // b → c, a third
    EXPECT_FLOAT_EQ(polygon.vertices[3].varyings[0], 2.0f / 3.0f);         // a ← c, a third
}

TEST(TriangleClipping, TwoVerticesBehindGiveASmallerTriangleAndThreeGiveNothing) {
    const ClipVertex a = clip_vertex(0, 0, 0, 1, 0);
    const ClipVertex b = clip_vertex(1, 0, -5, 1, 0), c = clip_vertex(0, 1, -5, 1, 0);
    ClippedPolygon polygon;
    clip_triangle(a, b, c, outside_near, 0, polygon);
    EXPECT_EQ(polygon.count, 3);
    clip_triangle(clip_vertex(0, 0, -3, 1, 0), b, c, outside_near, 0, polygon);
    EXPECT_EQ(polygon.count, 0);
    const TriangleOutcodes behind{clip_outcode({0, 0, -3, 1}), clip_outcode(b.position),
                                  clip_outcode(c.position)};
    EXPECT_TRUE(behind.culled());
}

TEST(TriangleClipping, SharedEdgeIsCutAtBitIdenticalPointsInBothTriangles) {
    const ClipVertex p = clip_vertex(0.3f, -0.2f, 0.1f, 0.7f, 0),
                     q = clip_vertex(-7.1f, 3.3f, -90.0f, -80.0f, 0);
    const ClipVertex r = clip_vertex(0.9f, 0.4f, 0.2f, 1.1f, 0),
                     s = clip_vertex(-0.8f, 0.5f, 0.2f, 0.9f, 0);
    ClippedPolygon first, second;
    clip_triangle(p, q, r, outside_near, 0, first);   // edge p → q
    clip_triangle(q, p, s, outside_near, 0, second);  // edge q → p
    auto on_plane = [](const ClippedPolygon& polygon) {
        std::vector<glm::vec4> cut;
        for (int i = 0; i < polygon.count; ++i) {
            const glm::vec4& v = polygon.vertices[i].position;
            if (v != glm::vec4(0.3f, -0.2f, 0.1f, 0.7f) && v != glm::vec4(0.9f, 0.4f, 0.2f, 1.1f) &&
                v != glm::vec4(-0.8f, 0.5f, 0.2f, 0.9f)) {
                cut.push_back(v);
            }
        }
        return cut;
    };
    const std::vector<glm::vec4> cuts_first = on_plane(first), cuts_second = on_plane(second);
    ASSERT_EQ(cuts_first.size(), 2u);
    ASSERT_EQ(cuts_second.size(), 2u);
    // p–q is cut in both; compare bit for bit.
    const auto shared = std::count(cuts_second.begin(), cuts_second.end(), cuts_first[0]) +
                        std::count(cuts_second.begin(), cuts_second.end(), cuts_first[1]);
    EXPECT_EQ(shared, 1);
}

TEST(TriangleClipping, GroundTriangleReachingBehindCameraStaysBelowHorizon) {
    // Eye 1 m above the ground looking level: the horizon is the middle of the screen. The
    // triangle's two near corners are 20 m behind the eye.
    const int width = 64, height = 48;
    Framebuffer fb(width, height);
    Camera camera = make_camera({0, 1, 0}, {0, 1, -1}, 60.0f);
    const glm::vec3 a(-50, 0, 20), b(50, 0, 20), c(0, 0, -200);
    const glm::mat4 view_projection = view_projection_matrix(camera, fb);
    auto vertex = [&](const glm::vec3& p) {
        ClipVertex v;
        v.position = view_projection * glm::vec4(p, 1.0f);
        return v;
    };
    CoverageCounter counter(fb);
    draw_triangle(fb, no_depth_state(), vertex(a), vertex(b), vertex(c), counter.shader());

    int covered = 0, mismatches = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const int count = counter.at(x, y);
            covered += count;
            ASSERT_LE(count, 1);
            if (y < height / 2) {
                ASSERT_EQ(count, 0) << "pixel (" << x << ", " << y << ") above the horizon";
                continue;
            }
            // Ray-cast truth, tolerating only pixels whose corners disagree (edge pixels).
            auto hit = [&](float dx, float dy) {
                const float px = static_cast<float>(x) + 0.5f + dx,
                            py = static_cast<float>(y) + 0.5f + dy;
                return intersect_triangle(reference_ray(camera, width, height, px, py), a, b, c)
                    .has_value();
            };
            const bool centre = hit(0, 0);
            const bool edge = hit(-0.5f, -0.5f) != centre || hit(0.5f, -0.5f) != centre ||
                              hit(-0.5f, 0.5f) != centre || hit(0.5f, 0.5f) != centre;
            if ((count == 1) != centre) {
                ++mismatches;
                EXPECT_TRUE(edge) << "pixel (" << x << ", " << y << ") away from any edge";
            }
        }
    }
    EXPECT_GT(covered, width * height / 4);  // the near ground fills the lower part
    EXPECT_EQ(counter.at(width / 2, height - 1), 1);
    EXPECT_LE(mismatches, width / 2);
}

// A convex polygon (window space, double precision) and the signed distance of a point to
// its outline: positive inside.
double distance_inside(const std::vector<glm::dvec2>& polygon, const glm::dvec2& point) {
    double area = 0.0;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const glm::dvec2 &p = polygon[i], &q = polygon[(i + 1) % polygon.size()];
        area += p.x * q.y - p.y * q.x;
    }
    double nearest = 1e300;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const glm::dvec2 &p = polygon[i], &q = polygon[(i + 1) % polygon.size()];
        const glm::dvec2 edge = q - p;
        const double length = std::sqrt(edge.x * edge.x + edge.y * edge.y);
        if (length == 0.0) continue;
        const double cross = edge.x * (point.y - p.y) - edge.y * (point.x - p.x);
        nearest = std::min(nearest, (area > 0 ? cross : -cross) / length);
    }
    return nearest;
}

TEST(TriangleClipping, QuadsCrossingTheNearPlaneShareTheirDiagonalWithoutCracks) {
    // Planar quads with corners up to a kilometre behind the eye and just in front of it:
    // the diagonal is cut by the near plane in both triangles, far from the cut point, where
    // float rounding would move the two cuts apart if they were computed differently.
    const int width = 64, height = 64;
    Framebuffer fb(width, height);
    const glm::dmat4 projection = glm::perspectiveRH_NO(glm::radians(70.0), 1.0, 0.05, 100.0);
    std::mt19937 rng(12345);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    // The outline's far corners sit up to 10^6 pixels away, where float window coordinates
    // are only good to a few hundredths of a pixel: centres this close to the outline may go
    // either way. The diagonal needs no margin — both triangles must agree on it exactly.
    const double outline_margin = 0.25;
    int tested = 0, pixels_inside = 0;
    for (int trial = 0; trial < 3000 && !HasFailure(); ++trial) {
        // Quad in eye space: a random plane through a point just ahead of the eye.
        const glm::dvec3 centre(unit(rng) - 0.5, unit(rng) - 0.5, -0.06 - 0.3 * unit(rng));
        const glm::dvec3 normal =
            glm::normalize(glm::dvec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5));
        const glm::dvec3 u = glm::normalize(glm::cross(normal, glm::dvec3(0.3, 0.8, 0.5)));
        const glm::dvec3 v = glm::cross(normal, u);
        std::array<glm::dvec2, 4> in_plane;
        for (int i = 0; i < 4; ++i) {
            const double angle = (i + 0.6 * unit(rng)) * 1.5707963;
            const double radius = unit(rng) < 0.5 ? 0.2 + unit(rng) : 50.0 + 950.0 * unit(rng);
            in_plane[i] = radius * glm::dvec2(std::cos(angle), std::sin(angle));
        }
        bool convex = true;  // counter-clockwise in the plane, every turn a left turn
        for (int i = 0; i < 4; ++i) {
            const glm::dvec2 e = in_plane[(i + 1) % 4] - in_plane[i];
            const glm::dvec2 f = in_plane[(i + 2) % 4] - in_plane[(i + 1) % 4];
            convex = convex && e.x * f.y - e.y * f.x > 1e-6 * glm::length(e) * glm::length(f);
        }
        if (!convex) continue;
        std::array<glm::dvec3, 4> corners;
        for (int i = 0; i < 4; ++i) corners[i] = centre + in_plane[i].x * u + in_plane[i].y * v;
        std::array<glm::dvec4, 4> clip;
        std::array<ClipVertex, 4> vertex;
        for (int i = 0; i < 4; ++i) {
            clip[i] = projection * glm::dvec4(corners[i], 1.0);
            vertex[i].position = glm::vec4(clip[i]);
        }
        // Truth: the quad clipped at z = -w in double precision, projected.
        std::vector<glm::dvec4> kept;
        for (int i = 0; i < 4; ++i) {
            const glm::dvec4 &p = clip[i], &q = clip[(i + 1) % 4];
            const double dp = p.z + p.w, dq = q.z + q.w;
            if (dp >= 0) kept.push_back(p);
            if ((dp >= 0) != (dq >= 0)) kept.push_back(p + dp / (dp - dq) * (q - p));
        }
        if (kept.size() < 3) continue;
        std::vector<glm::dvec2> outline;
        for (const glm::dvec4& p : kept) {
            outline.push_back({(p.x / p.w + 1.0) * 0.5 * width, (1.0 - p.y / p.w) * 0.5 * height});
        }
        ++tested;
        CoverageCounter counter(fb);
        const int diagonal = trial % 2;
        draw_triangle(fb, no_depth_state(), vertex[diagonal], vertex[diagonal + 1],
                      vertex[diagonal + 2], counter.shader());
        draw_triangle(fb, no_depth_state(), vertex[diagonal], vertex[diagonal + 2],
                      vertex[(diagonal + 3) % 4], counter.shader());
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x) {
                const double inside = distance_inside(outline, {x + 0.5, y + 0.5});
                const int count = counter.at(x, y);
                ASSERT_LE(count, 1) << "trial " << trial << " pixel (" << x << ", " << y << ")";
                if (inside > outline_margin) {
                    ++pixels_inside;
                    ASSERT_EQ(count, 1)
                        << "crack: trial " << trial << " pixel (" << x << ", " << y << ")";
                }
                if (inside < -outline_margin) {
                    ASSERT_EQ(count, 0) << "trial " << trial << " pixel (" << x << ", " << y << ")";
                }
            }
        }
    }
    EXPECT_GT(tested, 1000);
    EXPECT_GT(pixels_inside, 100000);
}

}  // namespace
}  // namespace weft::raster
