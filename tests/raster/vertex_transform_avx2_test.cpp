// The vertex transform's AVX2 lanes (vertex_transform_avx2.h) against the scalar transform,
// through prepare_mesh: the same clip positions, outcodes, window vertices and varyings to
// the bit, for vertices in view, off screen, beyond the guard band, behind the eye and not
// finite, with and without a model matrix, uvs and colours, and vertex counts that leave a
// partial group of eight.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "raster/camera.h"
#include "raster/clipping.h"
#include "raster/mesh.h"
#include "raster/mesh_renderer.h"
#include "raster/vector_isa.h"

namespace weft::raster {
namespace {

template <class T>
bool same_bits(const T& a, const T& b) {
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

// `count` vertices scattered around and behind the camera, near and far, a few not finite.
TriangleMesh scattered_vertices(std::size_t count, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> near(-1.5f, 1.5f), far(-400.0f, 400.0f), unit(0.0f, 1.0f);
    TriangleMesh mesh;
    for (std::size_t i = 0; i < count; ++i) {
        const bool wide = i % 5 == 0;
        glm::vec3 p = wide ? glm::vec3(far(rng), far(rng), far(rng))
                           : glm::vec3(near(rng), near(rng), near(rng) * 3.0f);
        if (i % 97 == 13) p.y = std::numeric_limits<float>::quiet_NaN();
        if (i % 89 == 7) p.x = std::numeric_limits<float>::infinity();
        mesh.positions.push_back(p);
        mesh.normals.push_back(glm::vec3(near(rng), near(rng), near(rng)));
        mesh.uvs.push_back({unit(rng), unit(rng)});
    }
    for (std::uint32_t i = 0; i + 2 < count; i += 3) mesh.triangles.push_back({i, i + 1, i + 2});
    return mesh;
}

TEST(VertexTransformAvx2, GivesTheScalarTransformsBits) {
    if (!avx2_supported()) GTEST_SKIP() << "no AVX2 on this CPU";
    const Camera camera = make_camera({0.3f, 0.4f, 3.0f}, {0.0f, 0.0f, 0.0f}, 55.0f);
    const int width = 641, height = 359;
    SurfaceStyle checker;
    checker.pattern = SurfacePattern::checker;
    SurfaceStyle plain;
    std::size_t in_view = 0, clipped = 0, not_finite_seen = 0;
    for (std::size_t count : {1u, 7u, 8u, 9u, 23u, 1003u}) {
        const TriangleMesh mesh = scattered_vertices(count, static_cast<unsigned>(count));
        std::vector<glm::vec3> colours(count, glm::vec3(0.25f, 0.5f, 0.75f));
        const glm::mat4 turned =
            glm::mat4(glm::vec4(0.8f, 0.6f, 0.0f, 0.0f), glm::vec4(-0.6f, 0.8f, 0.0f, 0.0f),
                      glm::vec4(0.0f, 0.0f, 1.5f, 0.0f), glm::vec4(0.1f, -0.2f, 0.3f, 1.0f));
        MeshView with_colours = mesh.view();
        with_colours.colours = colours;
        const MeshView views[] = {mesh.view(), mesh.view(turned), with_colours};
        for (const MeshView& view : views) {
            for (const SurfaceStyle* style : {&checker, &plain}) {
                PreparedMesh scalar, lanes;
                ASSERT_TRUE(
                    prepare_mesh(camera, width, height, view, *style, scalar, nullptr, false));
                ASSERT_TRUE(
                    prepare_mesh(camera, width, height, view, *style, lanes, nullptr, true));
                ASSERT_EQ(scalar.varying_stride, lanes.varying_stride);
                const auto stride = static_cast<std::size_t>(scalar.varying_stride);
                for (std::size_t i = 0; i < count; ++i) {
                    ASSERT_TRUE(same_bits(scalar.clip[i], lanes.clip[i])) << count << ": " << i;
                    ASSERT_EQ(scalar.outcodes[i], lanes.outcodes[i]) << count << ": " << i;
                    not_finite_seen += (scalar.outcodes[i] & not_finite) != 0;
                    if ((scalar.outcodes[i] & clipping_planes) != 0) {
                        ++clipped;
                        continue;  // window and varyings are not computed for it
                    }
                    ++in_view;
                    const WindowVertex &a = scalar.window[i], &b = lanes.window[i];
                    ASSERT_EQ(a.x, b.x) << count << ": " << i;
                    ASSERT_EQ(a.y, b.y) << count << ": " << i;
                    ASSERT_TRUE(same_bits(a.depth, b.depth)) << count << ": " << i;
                    ASSERT_TRUE(same_bits(a.inverse_w, b.inverse_w)) << count << ": " << i;
                    ASSERT_EQ(
                        std::memcmp(&scalar.varyings_over_w[i * stride],
                                    &lanes.varyings_over_w[i * stride], stride * sizeof(float)),
                        0)
                        << count << ": " << i;
                }
            }
        }
    }
    // Every kind of vertex was there.
    EXPECT_GT(in_view, 1000u);
    EXPECT_GT(clipped, 500u);
    EXPECT_GT(not_finite_seen, 50u);
}

}  // namespace
}  // namespace weft::raster
