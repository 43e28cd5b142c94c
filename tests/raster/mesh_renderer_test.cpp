// Mesh drawing and its shading. Truths: hand-computed normals of simple shapes; the shading
// formula evaluated by hand for a flat quad (every pixel sees the same normal); which colour
// each side shows from which side; a sphere's silhouette against the analytic disc.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>

#include "raster/camera.h"
#include "raster/framebuffer.h"
#include "raster/mesh.h"
#include "raster/mesh_renderer.h"
#include "raster/sphere.h"
#include "raster_test_support.h"

namespace weft::raster {
namespace {

constexpr Rgba8 background{0, 0, 0, 255};

// A unit square in the z = 0 plane, counter-clockwise seen from +z (its front).
struct Square {
    std::vector<glm::vec3> positions{
        {-0.5f, -0.5f, 0}, {0.5f, -0.5f, 0}, {0.5f, 0.5f, 0}, {-0.5f, 0.5f, 0}};
    std::vector<glm::vec3> normals = std::vector<glm::vec3>(4, glm::vec3(0, 0, 1));
    std::vector<glm::vec2> uvs{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    std::vector<TriangleIndices> triangles{{0, 1, 2}, {0, 2, 3}};
    MeshView view() const { return {positions, normals, triangles, uvs}; }
};

// Lighting that makes the output the base colour itself: ambient 1, nothing else.
Lighting unlit() {
    Lighting lighting;
    lighting.ambient_colour = glm::vec3(1.0f);
    lighting.light_colour = glm::vec3(0.0f);
    lighting.eye_fill_colour = glm::vec3(0.0f);
    return lighting;
}

SurfaceStyle two_colours() {
    SurfaceStyle style;
    style.front_colour = {0.8f, 0.2f, 0.1f};
    style.back_colour = {0.1f, 0.3f, 0.9f};
    style.specular_strength = 0.0f;
    return style;
}

TEST(VertexNormals, FlatGridHasThePlaneNormalEverywhere) {
    std::vector<glm::vec3> positions;
    std::vector<TriangleIndices> triangles;
    const int n = 5;
    for (int r = 0; r < n; ++r) {
        for (int c = 0; c < n; ++c)
            positions.push_back(
                {0.3f * static_cast<float>(c), 0.0f, -0.2f * static_cast<float>(r)});
    }
    for (std::uint32_t r = 0; r + 1 < n; ++r) {
        for (std::uint32_t c = 0; c + 1 < n; ++c) {
            const std::uint32_t i = r * n + c;
            triangles.push_back({i, i + 1, i + n});  // counter-clockwise seen from +y
            triangles.push_back({i + 1, i + n + 1, i + n});
        }
    }
    for (const glm::vec3& normal : compute_vertex_normals(positions, triangles)) {
        EXPECT_NEAR(normal.x, 0.0f, 1e-6f);
        EXPECT_NEAR(normal.y, 1.0f, 1e-6f);
        EXPECT_NEAR(normal.z, 0.0f, 1e-6f);
    }
}

TEST(VertexNormals, AreWeightedByTriangleArea) {
    // Vertex 0 is shared by a triangle of area 2 in the z = 0 plane (normal +z) and one of
    // area 1/2 in the x = 0 plane (normal +x): the sum is (1/2, 0, 2), normalised.
    const std::vector<glm::vec3> positions{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 1, 0}, {0, 0, 1}};
    const std::vector<TriangleIndices> triangles{{0, 1, 2}, {0, 3, 4}};
    const std::vector<glm::vec3> normals = compute_vertex_normals(positions, triangles);
    const glm::vec3 expected = glm::normalize(glm::vec3(0.5f, 0.0f, 2.0f));
    EXPECT_NEAR(normals[0].x, expected.x, 1e-6f);
    EXPECT_NEAR(normals[0].y, expected.y, 1e-6f);
    EXPECT_NEAR(normals[0].z, expected.z, 1e-6f);
    EXPECT_NEAR(normals[1].z, 1.0f, 1e-6f);
    EXPECT_NEAR(normals[4].x, 1.0f, 1e-6f);
}

TEST(VertexNormals, UnusedVertexAndBadIndicesGiveZeroWithoutCrashing) {
    const std::vector<glm::vec3> positions{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 5}};
    const std::vector<TriangleIndices> triangles{{0, 1, 2}, {0, 1, 99}};
    const std::vector<glm::vec3> normals = compute_vertex_normals(positions, triangles);
    EXPECT_EQ(normals[3], glm::vec3(0.0f));
    EXPECT_NEAR(normals[0].z, 1.0f, 1e-6f);
}

TEST(VertexNormals, FacesThenGathersInSlicesEqualTheWholeMeshSums) {
    // An irregular mesh: a crumpled grid, plus a triangle naming a vertex twice, one with an
    // index out of range, and a vertex no triangle uses.
    std::vector<glm::vec3> positions;
    const int side = 9;
    for (int j = 0; j < side; ++j)
        for (int i = 0; i < side; ++i)
            positions.push_back(
                {static_cast<float>(i) * 0.37f + 0.05f * std::sin(3.1f * static_cast<float>(j)),
                 static_cast<float>(j) * 0.29f, 0.2f * std::cos(1.7f * static_cast<float>(i * j))});
    positions.push_back({5.0f, 5.0f, 5.0f});  // unused
    std::vector<TriangleIndices> triangles;
    for (std::uint32_t j = 0; j + 1 < side; ++j) {
        for (std::uint32_t i = 0; i + 1 < side; ++i) {
            const std::uint32_t c = j * side + i;
            triangles.push_back({c, c + 1, c + side});
            triangles.push_back({c + 1, c + side + 1, c + side});
        }
    }
    triangles.push_back({3, 3, 20});
    triangles.push_back({4, 5, 1000});
    const std::vector<glm::vec3> whole = compute_vertex_normals(positions, triangles);
    VertexTriangles around;
    find_vertex_triangles(triangles, positions.size(), around);
    for (std::size_t slice : {std::size_t{1}, std::size_t{7}, positions.size()}) {
        std::vector<glm::vec3> faces(triangles.size(), glm::vec3(9.0f));
        for (std::size_t begin = 0; begin < triangles.size(); begin += slice)
            compute_face_normals(positions, triangles, faces, begin,
                                 std::min(begin + slice, triangles.size()));
        std::vector<glm::vec3> gathered(positions.size(), glm::vec3(9.0f));
        for (std::size_t begin = 0; begin < positions.size(); begin += slice)
            gather_vertex_normals(faces, around, gathered, begin,
                                  std::min(begin + slice, positions.size()));
        for (std::size_t v = 0; v < positions.size(); ++v)
            for (int k = 0; k < 3; ++k)  // bit for bit: the same sums in the same order
                EXPECT_EQ(std::bit_cast<std::uint32_t>(gathered[v][k]),
                          std::bit_cast<std::uint32_t>(whole[v][k]))
                    << "vertex " << v << ", slices of " << slice;
    }
    EXPECT_EQ(whole.back(), glm::vec3(0.0f));
}

TEST(UniqueEdges, ListsEachEdgeOfAQuadOnce) {
    const std::vector<TriangleIndices> triangles{{0, 1, 2}, {0, 2, 3}};
    const std::vector<LineIndices> expected{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {2, 3}};
    EXPECT_EQ(unique_edges(triangles), expected);
}

TEST(MeshRenderer, ShowsFrontColourFromTheFrontAndBackColourFromBehind) {
    const Square square;
    Framebuffer fb(32, 32);
    for (float side : {1.0f, -1.0f}) {
        fb.clear(background);
        Camera camera = make_camera({0.2f, 0.1f, 2.0f * side}, {0, 0, 0}, 50.0f);
        ASSERT_TRUE(draw_mesh(fb, camera, square.view(), two_colours(), unlit()));
        const glm::vec3 expected =
            side > 0 ? two_colours().front_colour : two_colours().back_colour;
        EXPECT_EQ(fb.colour(16, 16), to_rgba8(expected)) << (side > 0 ? "front" : "back");
    }
}

TEST(MeshRenderer, VertexColoursReplaceBothSideColours) {
    Square square;
    const std::vector<glm::vec3> colours(4, glm::vec3(0.2f, 0.7f, 0.3f));
    MeshView view = square.view();
    view.colours = colours;
    Framebuffer fb(32, 32);
    for (float side : {1.0f, -1.0f}) {
        fb.clear(background);
        ASSERT_TRUE(draw_mesh(fb, make_camera({0, 0, 2.0f * side}, {0, 0, 0}, 50.0f), view,
                              two_colours(), unlit()));
        // Interpolated, so allow one step of 8-bit rounding (0.7 · 255 is exactly 178.5).
        const Rgba8 expected = to_rgba8(colours[0]), actual = fb.colour(16, 16);
        EXPECT_LE(std::abs(actual.r - expected.r), 1);
        EXPECT_LE(std::abs(actual.g - expected.g), 1);
        EXPECT_LE(std::abs(actual.b - expected.b), 1);
    }
}

TEST(MeshRenderer, LambertShadingMatchesTheFormulaAndBackFacesUseTheFlippedNormal) {
    // Light at 60° from the square's front normal: front pixels get
    // base · (ambient + light · cos 60°); seen from behind, the flipped normal faces away
    // from the light, leaving ambient only. Then light the back instead.
    const Square square;
    SurfaceStyle style = two_colours();
    Lighting lighting;
    lighting.ambient_colour = glm::vec3(0.2f);
    lighting.light_colour = glm::vec3(0.6f);
    lighting.eye_fill_colour = glm::vec3(0.0f);
    lighting.direction_to_light = {std::sin(glm::radians(60.0f)), 0.0f,
                                   std::cos(glm::radians(60.0f))};
    Framebuffer fb(32, 32);
    auto render_from = [&](float z) {
        fb.clear(background);
        EXPECT_TRUE(draw_mesh(fb, make_camera({0, 0, z}, {0, 0, 0}, 50.0f), square.view(), style,
                              lighting));
        return fb.colour(16, 16);
    };
    EXPECT_EQ(render_from(2.0f), to_rgba8(style.front_colour * (0.2f + 0.6f * 0.5f)));
    EXPECT_EQ(render_from(-2.0f), to_rgba8(style.back_colour * 0.2f));
    lighting.direction_to_light.z = -lighting.direction_to_light.z;
    EXPECT_EQ(render_from(-2.0f), to_rgba8(style.back_colour * (0.2f + 0.6f * 0.5f)));
    EXPECT_EQ(render_from(2.0f), to_rgba8(style.front_colour * 0.2f));
}

TEST(MeshRenderer, SpecularHighlightFollowsBlinnPhong) {
    // Eye and light both along the normal: the halfway vector is the normal, the highlight
    // is at full strength: base · (ambient + light) + light · strength.
    SurfaceStyle style = two_colours();
    style.specular_strength = 0.25f;
    style.shininess = 16.0f;
    Lighting lighting;
    lighting.ambient_colour = glm::vec3(0.1f);
    lighting.light_colour = glm::vec3(0.5f);
    lighting.eye_fill_colour = glm::vec3(0.0f);
    lighting.direction_to_light = {0, 0, 1};
    const glm::vec3 lit =
        shade_surface(style, lighting, style.front_colour, {0, 0, 1}, {0, 0, 1}, true);
    const glm::vec3 expected = style.front_colour * 0.6f + glm::vec3(0.5f * 0.25f);
    EXPECT_NEAR(lit.r, expected.r, 1e-6f);
    EXPECT_NEAR(lit.g, expected.g, 1e-6f);
    // Eye 60° off the normal, light on it: n·h = cos 30°.
    const glm::vec3 to_eye(std::sin(glm::radians(60.0f)), 0.0f, std::cos(glm::radians(60.0f)));
    const glm::vec3 off =
        shade_surface(style, lighting, style.front_colour, {0, 0, 1}, to_eye, true);
    const float highlight = 0.5f * 0.25f * std::pow(std::cos(glm::radians(30.0f)), 16.0f);
    EXPECT_NEAR(off.b, style.front_colour.b * 0.6f + highlight, 1e-6f);
}

TEST(MeshRenderer, CheckerPatternAlternatesCellsFromTextureCoordinates) {
    SurfaceStyle style;
    style.pattern = SurfacePattern::checker;
    style.pattern_frequency = 4.0f;
    style.pattern_contrast = 0.5f;
    EXPECT_EQ(pattern_factor(style, {0.1f, 0.1f}), 1.0f);
    EXPECT_EQ(pattern_factor(style, {0.3f, 0.1f}), 0.5f);
    EXPECT_EQ(pattern_factor(style, {0.3f, 0.3f}), 1.0f);
    EXPECT_EQ(pattern_factor(style, {-0.1f, 0.1f}), 0.5f);
    style.pattern = SurfacePattern::stripes;
    EXPECT_EQ(pattern_factor(style, {0.3f, 0.3f}), 0.5f);
    style.pattern = SurfacePattern::none;
    EXPECT_EQ(pattern_factor(style, {0.3f, 0.1f}), 1.0f);

    // Drawn: the square seen head-on shows a 2×2 checker with frequency 2.
    const Square square;
    SurfaceStyle drawn = two_colours();
    drawn.pattern = SurfacePattern::checker;
    drawn.pattern_frequency = 2.0f;
    drawn.pattern_contrast = 0.5f;
    Framebuffer fb(64, 64);
    fb.clear(background);
    ASSERT_TRUE(
        draw_mesh(fb, make_camera({0, 0, 1.5f}, {0, 0, 0}, 50.0f), square.view(), drawn, unlit()));
    const Rgba8 full = to_rgba8(drawn.front_colour), dark = to_rgba8(drawn.front_colour * 0.5f);
    EXPECT_EQ(fb.colour(24, 40), full);  // u < 0.5, v < 0.5 (lower left)
    EXPECT_EQ(fb.colour(40, 40), dark);
    EXPECT_EQ(fb.colour(40, 24), full);
    EXPECT_EQ(fb.colour(24, 24), dark);
}

TEST(MeshRenderer, RejectsMismatchedArraysAndSkipsBadIndices) {
    Square square;
    Framebuffer fb(16, 16);
    fb.clear(background);
    const Camera camera = make_camera({0, 0, 2}, {0, 0, 0}, 50.0f);
    MeshView view = square.view();
    view.normals = std::span<const glm::vec3>(square.normals).first(3);
    EXPECT_FALSE(draw_mesh(fb, camera, view, two_colours(), unlit()));
    EXPECT_EQ(fb.colour(8, 8), background);
    const std::vector<TriangleIndices> bad{{0, 1, 4}, {0, 2, 3}};
    view = square.view();
    view.triangles = bad;
    EXPECT_TRUE(draw_mesh(fb, camera, view, two_colours(), unlit()));
    EXPECT_EQ(fb.colour(5, 5), to_rgba8(two_colours().front_colour));  // upper left: {0, 2, 3}
    EXPECT_EQ(fb.colour(11, 11), background);                          // lower right: skipped
}

TEST(MeshRenderer, ScissorTilesAndBandViewsReproduceTheWholeImage) {
    const TriangleMesh sphere = make_uv_sphere(24, 12);
    const Camera camera = make_camera({0.5f, 0.8f, 2.2f}, {0, 0, 0}, 50.0f);
    SurfaceStyle style;
    style.pattern = SurfacePattern::checker;
    Framebuffer whole(71, 50), tiled(71, 50), banded(71, 50);
    whole.clear(background);
    tiled.clear(background);
    ASSERT_TRUE(draw_mesh(whole, camera, sphere.view(), style, Lighting{}));
    ASSERT_LT(*std::min_element(whole.depths().begin(), whole.depths().end()), 1.0f);
    for (int y = 0; y < 50; y += 16) {
        for (int x = 0; x < 71; x += 16) {
            ASSERT_TRUE(draw_mesh(tiled, camera, sphere.view(), style, Lighting{},
                                  PixelRect{x, y, x + 16, y + 16}));
        }
    }
    // Each band drawn through a view with depths of its own, given no scissor: the view's
    // bounds keep the triangles inside its rows, and its depths go back to the frame.
    banded.clear(Rgba8{1, 2, 3, 4}, 0.0f);  // anything the bands fail to draw shows
    std::vector<float> depth_storage;
    for (int y = 0; y < 50; y += 13) {
        Framebuffer band = Framebuffer::band_view(banded, y, std::min(y + 13, 50), depth_storage);
        EXPECT_EQ(band.bounds(), (PixelRect{0, y, 71, std::min(y + 13, 50)}));
        band.clear(background);
        ASSERT_TRUE(draw_mesh(band, camera, sphere.view(), style, Lighting{}));
        band.write_back_depths();
    }
    for (const Framebuffer* drawn : {&tiled, &banded}) {
        EXPECT_TRUE(
            std::equal(whole.colours().begin(), whole.colours().end(), drawn->colours().begin()));
        EXPECT_TRUE(
            std::equal(whole.depths().begin(), whole.depths().end(), drawn->depths().begin()));
    }
}

TEST(Sphere, SilhouetteMatchesTheAnalyticDiscAndNormalsPointOutwards) {
    const int size = 96;
    Framebuffer fb(size, size);
    fb.clear(background);
    const Camera camera = make_camera({0.0f, 0.0f, 4.0f}, {0.0f, 0.0f, 0.0f}, 40.0f);
    const glm::vec3 centre(0.2f, -0.1f, 0.0f);
    const float radius = 1.0f;
    const TriangleMesh sphere = make_uv_sphere(96, 48);
    SurfaceStyle style = two_colours();
    ASSERT_TRUE(draw_sphere(fb, camera, sphere, centre, radius, style, unlit()));
    // The tessellation is inscribed in the sphere: it may miss pixels whose centres are within
    // a fraction of a pixel of the true silhouette, never anything else.
    int covered = 0;
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const auto ray = testing::reference_ray(
                camera, size, size, static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
            const glm::vec3 to_centre = centre - ray.origin;
            const float along = glm::dot(to_centre, ray.direction);
            const float miss_distance =
                std::sqrt(std::max(0.0f, glm::dot(to_centre, to_centre) - along * along));
            const bool drawn = fb.colour(x, y) != background;
            covered += drawn;
            // One pixel at the sphere's distance is about 2·4·tan 20° / 96 ≈ 0.03 m.
            if (miss_distance < radius - 0.03f) {
                EXPECT_TRUE(drawn) << "pixel (" << x << ", " << y << ")";
                // Outward normals, counter-clockwise from outside: the front colour shows.
                EXPECT_EQ(fb.colour(x, y), to_rgba8(style.front_colour))
                    << "pixel (" << x << ", " << y << ")";
            } else if (miss_distance > radius) {
                EXPECT_FALSE(drawn) << "pixel (" << x << ", " << y << ")";
            }
        }
    }
    EXPECT_GT(covered, 1500);
    const TriangleMesh coarse = make_uv_sphere(8, 4);
    for (std::size_t i = 0; i < coarse.positions.size(); ++i) {
        EXPECT_NEAR(glm::length(coarse.positions[i]), 1.0f, 1e-6f);
        EXPECT_EQ(coarse.normals[i], coarse.positions[i]);
    }
    EXPECT_EQ(coarse.triangles.size(), 8u * 4u * 2u - 2u * 8u);  // pole rows: one per cell
}

// A mesh drawn band by band from its binned triangles lands on exactly the pixels and depths
// of one whole draw: for bands of several heights, binned on one thread and on two, with
// triangles crossing the near plane (binned into every band), triangles off screen, and a
// folded sheet finer than the pixels (its tiny triangles binned as the pixels they cover,
// where the two sides and the layers in front and behind meet), with and without the AVX2
// classification.
TEST(MeshRenderer, BandsOfBinnedTrianglesDrawWhatOneWholeDrawDraws) {
    const TriangleMesh sphere = make_uv_sphere(96, 48);  // 9 000 triangles: binned in threads
    const Camera camera = make_camera({0.3f, 0.2f, 3.0f}, {0.0f, 0.0f, 0.0f}, 60.0f);
    SurfaceStyle style;
    style.pattern = SurfacePattern::checker;
    const Lighting lighting;
    const int width = 203, height = 157;
    // A wall 2 cm beside the eye, from behind the camera to far ahead: its triangles around
    // the camera cut the near plane, and their visible parts cover much of the frame.
    TriangleMesh wall;
    const int cells = 20;
    for (int j = 0; j <= cells; ++j) {
        for (int i = 0; i <= cells; ++i) {
            const float u = static_cast<float>(i) / cells, v = static_cast<float>(j) / cells;
            wall.positions.push_back({0.32f, -2.0f + 4.0f * v, -5.0f + 10.0f * u});
            wall.normals.push_back({-1.0f, 0.0f, 0.0f});
            wall.uvs.push_back({u, v});
        }
    }
    for (std::uint32_t j = 0; j < cells; ++j) {
        for (std::uint32_t i = 0; i < cells; ++i) {
            const std::uint32_t corner = j * (cells + 1) + i;
            wall.triangles.push_back({corner, corner + 1, corner + cells + 1});
            wall.triangles.push_back({corner + 1, corner + cells + 2, corner + cells + 1});
        }
    }
    const TriangleMesh spiral = testing::spiral_sheet(300);
    const MeshView views[] = {sphere_view(sphere, {0.2f, -0.1f, 0.0f}, 1.0f), wall.view(),
                              spiral.view()};
    for (const MeshView& view : views) {
        PreparedMesh prepared;
        ASSERT_TRUE(prepare_mesh(camera, width, height, view, style, prepared));
        Framebuffer whole(width, height);
        whole.clear(Rgba8{10, 20, 30, 255});
        draw_prepared_mesh(whole, prepared, style, lighting);
        ASSERT_GT(std::count_if(whole.depths().begin(), whole.depths().end(),
                                [](float depth) { return depth < 1.0f; }),
                  width * height / 10);
        for (int band_height : {1, 7, 32, 400}) {
            for (int threads : {1, 2}) {
                for (bool avx2 : {false, true}) {
                    WorkerPool pool(threads);
                    TriangleBands bands;
                    bin_triangles(prepared, band_height, bands, &pool, avx2);
                    if (view.triangles.data() == spiral.triangles.data()) {
                        std::size_t fragments = 0;
                        for (const std::vector<BinnedFragment>& list : bands.fragments)
                            fragments += list.size();
                        EXPECT_GT(fragments, static_cast<std::size_t>(width * height / 4));
                    }
                    Framebuffer banded(width, height);
                    banded.clear(Rgba8{10, 20, 30, 255});
                    for (int band = bands.band_count - 1; band >= 0; --band)  // any order
                        draw_prepared_band(banded, prepared, bands, band, style, lighting);
                    EXPECT_TRUE(testing::same_frame(whole, banded))
                        << band_height << " rows, " << threads << " threads, AVX2 " << avx2;
                }
            }
        }
    }
}

}  // namespace
}  // namespace weft::raster
