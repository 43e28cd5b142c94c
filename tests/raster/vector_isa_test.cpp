// The AVX-512 and AVX2 code of the rasterizer (vector_isa.h: the block traversal of small
// triangles and the batched lighting) against the baseline build: the truth is the frame the
// scalar pixel loop and the baseline lighting draw, which must come out the same to the byte —
// colours and depths — with AVX-512 or AVX2 in use.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "raster/camera.h"
#include "raster/framebuffer.h"
#include "raster/mesh.h"
#include "raster/mesh_renderer.h"
#include "raster/vector_isa.h"

namespace weft::raster {
namespace {

// A crumpled sheet of `cells`² quads with jittered corners: triangles of a fraction of a
// pixel to several pixels across, slivers among them, folds that hide parts of the sheet
// behind others (so depth tests fail inside one draw) and both sides in view.
TriangleMesh crumpled_sheet(int cells, float size, std::uint32_t seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> jitter(-0.45f, 0.45f);
    TriangleMesh mesh;
    const float spacing = size / static_cast<float>(cells);
    for (int j = 0; j <= cells; ++j) {
        for (int i = 0; i <= cells; ++i) {
            const float x = (static_cast<float>(i) + jitter(random)) * spacing - 0.5f * size;
            const float y = (static_cast<float>(j) + jitter(random)) * spacing - 0.5f * size;
            const float z =
                0.15f * std::sin(9.0f * x) * std::cos(7.0f * y) + 0.5f * spacing * jitter(random);
            mesh.positions.push_back({x, y, z});
            mesh.uvs.push_back({static_cast<float>(i) / static_cast<float>(cells),
                                static_cast<float>(j) / static_cast<float>(cells)});
        }
    }
    const auto row = static_cast<std::uint32_t>(cells + 1);
    for (std::uint32_t j = 0; j < static_cast<std::uint32_t>(cells); ++j) {
        for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(cells); ++i) {
            const std::uint32_t corner = j * row + i;
            mesh.triangles.push_back({corner, corner + 1, corner + row});
            mesh.triangles.push_back({corner + 1, corner + row + 1, corner + row});
        }
    }
    mesh.normals = compute_vertex_normals(mesh.positions, mesh.triangles);
    return mesh;
}

enum class Isa { avx512, avx2 };

struct Frames {
    Framebuffer vector, baseline;
};

// The same draw with AVX-512 (or only AVX2) in use and with neither.
template <class Draw>
Frames draw_both_ways(int width, int height, Isa isa, Draw&& draw) {
    Frames frames{Framebuffer(width, height), Framebuffer(width, height)};
    frames.vector.use_avx512(isa == Isa::avx512);
    frames.baseline.use_avx512(false);
    frames.baseline.use_avx2(false);
    frames.vector.clear(Rgba8{10, 20, 30, 255});
    draw(frames.vector);
    frames.baseline.clear(Rgba8{10, 20, 30, 255});
    draw(frames.baseline);
    return frames;
}

void expect_same(const Frames& frames, const char* what) {
    const Framebuffer &a = frames.vector, &b = frames.baseline;
    std::size_t covered = 0, differing = 0;
    for (std::size_t i = 0; i < a.depths().size(); ++i) {
        if (b.depths()[i] < 1.0f) ++covered;
        if (!(a.colours()[i] == b.colours()[i]) || a.depths()[i] != b.depths()[i]) ++differing;
    }
    // The frame must show enough of the sheet for the comparison to mean something.
    EXPECT_GT(covered, a.depths().size() / 4) << what;
    EXPECT_EQ(differing, 0u) << what << ": pixels that differ between the two builds";
}

void expect_each_draw_the_same(Isa isa) {
    // Odd sizes so that blocks hang over the right and bottom edges of the frame, and a
    // sheet larger than the view so that it is cut there.
    const int width = 203, height = 157;
    const Camera camera = make_camera({0.1f, 0.3f, 1.6f}, {0.0f, 0.0f, 0.0f}, 60.0f);
    const TriangleMesh small = crumpled_sheet(150, 2.2f, 7);  // about 1–3 pixels a cell
    const TriangleMesh large = crumpled_sheet(12, 1.2f, 8);   // several pixels: scalar path
    Lighting lighting;
    lighting.direction_to_light = {0.3f, 0.8f, 0.5f};

    SurfaceStyle plain;
    SurfaceStyle glossy;  // a shininess that is not a whole number: std::pow, not squaring
    glossy.shininess = 7.5f;
    glossy.specular_strength = 0.6f;
    SurfaceStyle checker;
    checker.pattern = SurfacePattern::checker;
    checker.pattern_frequency = 40.0f;
    std::vector<glm::vec3> vertex_colours(small.positions.size());
    for (std::size_t i = 0; i < vertex_colours.size(); ++i)
        vertex_colours[i] = {static_cast<float>(i % 7) / 7.0f, static_cast<float>(i % 5) / 5.0f,
                             0.5f};
    MeshView coloured = small.view();
    coloured.colours = vertex_colours;

    // Each varying layout the mesh shader has; two meshes in one frame (blocks and the
    // scalar loop share the shader's queue, and each tests depths the other wrote); and one
    // sheet drawn twice, whose second draw meets depths equal to its own and must fail them.
    expect_same(draw_both_ways(width, height, isa,
                               [&](Framebuffer& frame) {
                                   draw_mesh(frame, camera, small.view(), plain, lighting);
                               }),
                "plain");
    expect_same(draw_both_ways(width, height, isa,
                               [&](Framebuffer& frame) {
                                   draw_mesh(frame, camera, small.view(), checker, lighting);
                                   draw_mesh(frame, camera, large.view(), checker, lighting);
                               }),
                "checker, two meshes");
    expect_same(draw_both_ways(width, height, isa,
                               [&](Framebuffer& frame) {
                                   draw_mesh(frame, camera, small.view(), plain, lighting);
                                   draw_mesh(frame, camera, small.view(), checker, lighting);
                               }),
                "one sheet twice");
    expect_same(draw_both_ways(width, height, isa,
                               [&](Framebuffer& frame) {
                                   draw_mesh(frame, camera, coloured, glossy, lighting);
                               }),
                "vertex colours, glossy");
    expect_same(draw_both_ways(width, height, isa,
                               [&](Framebuffer& frame) {
                                   draw_mesh(frame, camera, coloured, checker, lighting);
                               }),
                "vertex colours and checker");

    // Drawn band by band, whose edges cut through blocks.
    PreparedMesh prepared;
    ASSERT_TRUE(prepare_mesh(camera, width, height, small.view(), checker, prepared));
    TriangleBands bands;
    bin_triangles(prepared, 7, bands);
    expect_same(draw_both_ways(width, height, isa,
                               [&](Framebuffer& frame) {
                                   for (int band = 0; band < bands.band_count; ++band)
                                       draw_prepared_band(frame, prepared, bands, band, checker,
                                                          lighting);
                               }),
                "bands of 7 rows");
}

TEST(Avx512, DrawsTheFrameTheBaselineBuildDraws) {
    if (!avx512_supported()) GTEST_SKIP() << "no AVX-512 on this CPU";
    expect_each_draw_the_same(Isa::avx512);
}

TEST(Avx2, DrawsTheFrameTheBaselineBuildDraws) {
    if (!avx2_supported()) GTEST_SKIP() << "no AVX2 on this CPU";
    expect_each_draw_the_same(Isa::avx2);
}

TEST(Avx512, EachFramebufferChoosesWithinWhatTheCpuRuns) {
    Framebuffer first(8, 8), second(8, 8);
    EXPECT_EQ(first.avx512_in_use(), avx512_supported());  // by default where it runs
    first.use_avx512(false);
    EXPECT_FALSE(first.avx512_in_use());
    EXPECT_EQ(second.avx512_in_use(), avx512_supported());  // the other keeps its own
    first.use_avx512(true);
    EXPECT_EQ(first.avx512_in_use(), avx512_supported());  // never past the CPU
    EXPECT_EQ(first.avx2_in_use(), avx2_supported());
    first.use_avx2(false);
    EXPECT_FALSE(first.avx2_in_use());
    EXPECT_EQ(second.avx2_in_use(), avx2_supported());
}

}  // namespace
}  // namespace weft::raster
