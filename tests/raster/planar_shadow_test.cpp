// Planar shadows (raster/planar_shadow.h): the projection puts every point on the floor along
// the light, and the drawn shadow of a square is the square moved along the light onto the
// floor, drawn flat.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "parallel/worker_pool.h"
#include "raster/framebuffer.h"
#include "raster/mesh.h"
#include "raster/planar_shadow.h"
#include "raster_test_support.h"

namespace weft::raster {
namespace {

TEST(PlanarShadow, EveryPointLandsOnTheFloorAlongTheLight) {
    for (const glm::vec3 light : {glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(0.36f, 0.8f, 0.48f),
                                  glm::vec3(-2.0f, 1.0f, 0.5f)}) {
        const float floor = -0.7f;
        const auto projection = shadow_projection(light, floor);
        ASSERT_TRUE(projection.has_value());
        for (const glm::vec3 point : {glm::vec3(0.3f, 1.2f, -0.4f), glm::vec3(-1.0f, -0.7f, 2.0f),
                                      glm::vec3(2.0f, -1.5f, 0.0f)}) {
            const glm::vec3 shadow = glm::vec3(*projection * glm::vec4(point, 1.0f));
            EXPECT_NEAR(shadow.y, floor, 1e-5f);
            // Moved along the light: the move is parallel to it.
            const glm::vec3 moved = point - shadow;
            EXPECT_NEAR(glm::length(glm::cross(moved, glm::normalize(light))), 0.0f, 1e-5f);
        }
    }
}

TEST(PlanarShadow, NoShadowFromALightAtTheHorizonOrBelowIt) {
    EXPECT_FALSE(shadow_projection({1.0f, 0.1f, 0.0f}, 0.0f).has_value());
    EXPECT_FALSE(shadow_projection({0.0f, -1.0f, 0.0f}, 0.0f).has_value());
    EXPECT_FALSE(shadow_projection({0.0f, 0.0f, 0.0f}, 0.0f).has_value());
    EXPECT_FALSE(shadow_projection({NAN, 1.0f, 0.0f}, 0.0f).has_value());
    EXPECT_TRUE(shadow_projection({1.0f, 0.2f, 0.0f}, 0.0f).has_value());
}

// A 1 m square at height `y`, centred on (x, z).
std::vector<glm::vec3> square_at(float x, float y, float z) {
    return {{x - 0.5f, y, z - 0.5f},
            {x + 0.5f, y, z - 0.5f},
            {x + 0.5f, y, z + 0.5f},
            {x - 0.5f, y, z + 0.5f}};
}

struct Coverage {
    int pixels = 0;
    double x = 0.0, y = 0.0;  // centroid, px
};

Coverage coverage(const Framebuffer& framebuffer, Rgba8 colour) {
    Coverage c;
    for (int y = 0; y < framebuffer.height(); ++y)
        for (int x = 0; x < framebuffer.width(); ++x)
            if (framebuffer.colour(x, y) == colour) {
                ++c.pixels;
                c.x += x;
                c.y += y;
            }
    if (c.pixels > 0) {
        c.x /= c.pixels;
        c.y /= c.pixels;
    }
    return c;
}

TEST(PlanarShadow, ASquaresShadowIsTheSquareMovedAlongTheLightOntoTheFloor) {
    const Camera camera = make_camera({0.0f, 6.0f, 0.01f}, {0.0f, 0.0f, 0.0f}, 50.0f);
    const std::vector<TriangleIndices> triangles{{0, 1, 2}, {0, 2, 3}};
    const Rgba8 dark{10, 20, 30, 255};
    const glm::vec3 light{1.0f, 2.0f, -0.5f};  // the shadow moves 0.5 m along -x, 0.25 m along z
    const std::vector<glm::vec3> square = square_at(0.2f, 1.0f, 0.1f);
    const std::vector<glm::vec3> moved = square_at(0.2f - 0.5f, 0.0f, 0.1f + 0.25f);
    const std::vector<glm::vec3> normals(4, glm::vec3(0.0f, 1.0f, 0.0f));

    Framebuffer shadow(320, 240), reference(320, 240);
    shadow.clear({0, 0, 0, 255});
    reference.clear({0, 0, 0, 255});
    MeshView caster{square, normals, triangles};
    caster.model = *shadow_projection(light, 0.0f);
    PreparedMesh prepared;
    prepare_flat_mesh(camera, 320, 240, caster, prepared);
    draw_flat_mesh(shadow, prepared, dark);
    prepare_flat_mesh(camera, 320, 240, MeshView{moved, normals, triangles}, prepared);
    draw_flat_mesh(reference, prepared, dark);

    const Coverage cast = coverage(shadow, dark), expected = coverage(reference, dark);
    ASSERT_GT(expected.pixels, 1000);
    // The same square up to rounding along its edges (about 4 × 40 px of them).
    EXPECT_NEAR(cast.pixels, expected.pixels, 40);
    EXPECT_NEAR(cast.x, expected.x, 0.5);
    EXPECT_NEAR(cast.y, expected.y, 0.5);
}

TEST(PlanarShadow, OverlappingLayersDrawOneColourNotADarkerOne) {
    // Two squares, one above the other: their shadows overlap; every covered pixel holds the
    // shadow's colour, never anything darker.
    const Camera camera = make_camera({0.0f, 6.0f, 0.01f}, {0.0f, 0.0f, 0.0f}, 50.0f);
    std::vector<glm::vec3> layers = square_at(0.0f, 1.0f, 0.0f);
    for (const glm::vec3& corner : square_at(0.3f, 1.5f, 0.0f)) layers.push_back(corner);
    const std::vector<TriangleIndices> triangles{{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}};
    const std::vector<glm::vec3> normals(8, glm::vec3(0.0f, 1.0f, 0.0f));
    MeshView caster{layers, normals, triangles};
    caster.model = *shadow_projection({0.0f, 1.0f, 0.0f}, 0.0f);
    PreparedMesh prepared;
    prepare_flat_mesh(camera, 320, 240, caster, prepared);
    Framebuffer framebuffer(320, 240);
    const Rgba8 background{40, 40, 40, 255}, dark{10, 10, 10, 255};
    framebuffer.clear(background);
    draw_flat_mesh(framebuffer, prepared, dark);
    int shadowed = 0;
    for (const Rgba8& pixel : framebuffer.colours()) {
        EXPECT_TRUE(pixel == background || pixel == dark);
        shadowed += pixel == dark;
    }
    EXPECT_GT(shadowed, 1000);
}

// Draws `caster` flat once whole and once band by band from its binned triangles, for each
// band height, thread count and with and without the AVX2 classification, and expects the
// same pixels and depths every time.
void expect_bands_cast_the_whole_shadow(const MeshView& caster, std::vector<int> band_heights,
                                        std::vector<int> thread_counts) {
    const Camera camera = make_camera({0.4f, 2.5f, 2.0f}, {0.0f, -1.0f, 0.0f}, 60.0f);
    const int width = 211, height = 163;
    PreparedMesh prepared;
    prepare_flat_mesh(camera, width, height, caster, prepared);
    const Rgba8 background{40, 40, 40, 255}, dark{10, 10, 10, 255};
    Framebuffer whole(width, height);
    whole.clear(background);
    draw_flat_mesh(whole, prepared, dark);
    ASSERT_GT(std::count(whole.colours().begin(), whole.colours().end(), dark), 2000);
    for (int band_height : band_heights) {
        for (int threads : thread_counts) {
            for (bool avx2 : {false, true}) {
                WorkerPool pool(threads);
                TriangleBands bands;
                bin_triangles(prepared, band_height, bands, &pool, avx2);
                std::size_t fragments = 0;
                for (const std::vector<BinnedFragment>& list : bands.fragments)
                    fragments += list.size();
                EXPECT_GT(fragments, 2000u);
                Framebuffer banded(width, height);
                banded.clear(background);
                for (int band = 0; band < bands.band_count; ++band)
                    draw_flat_band(banded, prepared, bands, band, dark);
                EXPECT_TRUE(testing::same_frame(whole, banded))
                    << band_height << " rows, " << threads << " threads, AVX2 " << avx2;
            }
        }
    }
}

// A shadow drawn band by band from its binned triangles is the shadow one whole draw casts, to
// the pixel and the depth: a spiral sheet finer than the pixels, whose layers' shadows fall
// on one another (the first layer drawn keeps a pixel both reach at one depth), on one
// thread and on two, with and without the AVX2 classification.
TEST(PlanarShadow, BandsOfBinnedTrianglesCastWhatOneWholeDrawCasts) {
    const TriangleMesh spiral = testing::spiral_sheet(300);
    MeshView caster = spiral.view();
    caster.model = *shadow_projection({0.36f, 0.8f, 0.48f}, -1.0f);
    expect_bands_cast_the_whole_shadow(caster, {1, 7, 32}, {1, 2});
}

// The same for a caster marked as a whole grid (MeshView::grid_cols): flat preparation keeps
// no window corners for binning to load a grid's groups from, so its binning must gather
// each triangle's corners as for any other mesh.
TEST(PlanarShadow, ACasterMarkedAsAWholeGridIsBinnedAsAnyOther) {
    const int side = 121;
    const TriangleMesh spiral = testing::spiral_sheet(side - 1);
    const std::vector<TriangleIndices> grid = testing::whole_grid_triangles(side, side);
    MeshView caster{spiral.positions, spiral.normals, grid};
    caster.model = *shadow_projection({0.36f, 0.8f, 0.48f}, -1.0f);
    caster.grid_cols = side;
    expect_bands_cast_the_whole_shadow(caster, {7}, {1});
}

}  // namespace
}  // namespace weft::raster
