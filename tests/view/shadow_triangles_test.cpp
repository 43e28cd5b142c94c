// The coarse triangles a grid's shadow is drawn from (view/shadow_triangles.h): on a flat
// sheet they cover exactly the sheet, whole or torn, with fewer triangles; a mesh keeps its own.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "sim/build/cloth_builder.h"
#include "sim/scene_io/scene_loader.h"
#include "view/shadow_triangles.h"

namespace weft::view {
namespace {

Cloth flat_sheet(Layout layout, int rows, int cols) {
    Scene scene;
    scene.cloth.rows = rows;
    scene.cloth.cols = cols;
    scene.cloth.layout = layout;
    scene.cloth.orientation = Orientation::horizontal;
    return build_cloth(scene);
}

// The area the triangles cover on a flat sheet, m² (they do not overlap there).
double area(const Cloth& cloth, std::span<const raster::TriangleIndices> triangles) {
    double sum = 0.0;
    for (const raster::TriangleIndices& t : triangles) {
        const Vec3 a = cloth.positions[t[0]], b = cloth.positions[t[1]], c = cloth.positions[t[2]];
        sum += 0.5 * glm::length(glm::cross(b - a, c - a));
    }
    return sum;
}

std::vector<raster::TriangleIndices> intact(const Cloth& cloth) {
    std::vector<raster::TriangleIndices> triangles;
    for (const Triangle& t : cloth.topology().triangles) triangles.push_back({t.a, t.b, t.c});
    return triangles;
}

TEST(ShadowTriangles, AWholeSheetIsCoveredExactlyByFewerTriangles) {
    struct Case {
        Layout layout;
        int rows, cols;  // particles
        std::size_t shadow_triangles;
    };
    // Blocks of 4 cells. 12 x 9 cells: 3 block rows, and 2 block columns and one of the
    // column left over. 11 x 9 cells: the 3 rows left over make a block of their own on a
    // grid; an offset grid keeps its blocks' heights even, a block of 2 rows and the last
    // row's 9 cells as they are.
    for (const Case& c :
         {Case{Layout::grid, 13, 10, 2 * 3 * 3}, Case{Layout::offset, 13, 10, 2 * 3 * 3},
          Case{Layout::grid, 12, 10, 2 * 3 * 3}, Case{Layout::offset, 12, 10, 2 * 3 * 3 + 2 * 9}}) {
        const Cloth cloth = flat_sheet(c.layout, c.rows, c.cols);
        const auto triangles = intact(cloth);
        std::vector<raster::TriangleIndices> shadow;
        std::vector<std::uint32_t> used;
        find_shadow_triangles(cloth, triangles, 4, shadow, used);
        const std::string name =
            std::to_string(static_cast<int>(c.layout)) + ", " + std::to_string(c.rows) + " rows";
        EXPECT_EQ(shadow.size(), c.shadow_triangles) << name;
        EXPECT_NEAR(area(cloth, shadow), area(cloth, triangles), 1e-9) << name;
        // Every vertex the shadow names, once, ascending.
        EXPECT_TRUE(std::is_sorted(used.begin(), used.end()));
        EXPECT_EQ(std::adjacent_find(used.begin(), used.end()), used.end());
        for (const raster::TriangleIndices& t : shadow)
            for (std::uint32_t v : t) EXPECT_TRUE(std::binary_search(used.begin(), used.end(), v));
        EXPECT_LT(used.size(), cloth.positions.size());
    }
}

TEST(ShadowTriangles, ATornCellLeavesItsHoleInTheShadow) {
    const Cloth cloth = flat_sheet(Layout::grid, 9, 9);
    auto triangles = intact(cloth);
    // Remove one triangle in the middle of the first block (2 x 2 cells).
    const raster::TriangleIndices torn = triangles[2 * (1 * 8 + 1)];
    triangles.erase(triangles.begin() + 2 * (1 * 8 + 1));
    std::vector<raster::TriangleIndices> shadow;
    std::vector<std::uint32_t> used;
    find_shadow_triangles(cloth, triangles, 2, shadow, used);
    // 15 whole blocks of two triangles, and the broken block's 7 own triangles.
    EXPECT_EQ(shadow.size(), 15u * 2u + 7u);
    EXPECT_NEAR(area(cloth, shadow), area(cloth, intact(cloth)) - area(cloth, {&torn, 1}), 1e-9);
    EXPECT_EQ(std::count(shadow.begin(), shadow.end(), torn), 0);
}

TEST(ShadowTriangles, BlocksAreEvenAndOnlyOnLargeGrids) {
    EXPECT_EQ(shadow_block_cells(flat_sheet(Layout::grid, 40, 40)), 1);
    EXPECT_EQ(shadow_block_cells(flat_sheet(Layout::grid, 128, 128)), 4);
    EXPECT_EQ(shadow_block_cells(flat_sheet(Layout::offset, 100, 40)), 2);
    SceneLoadResult loaded = load_scene_file(WEFT_SOURCE_DIR "/assets/scenes/skirt.toml");
    ASSERT_TRUE(loaded.ok());
    const Cloth mesh = build_cloth(*loaded.scene);
    EXPECT_EQ(shadow_block_cells(mesh), 1);
    std::vector<raster::TriangleIndices> shadow;
    std::vector<std::uint32_t> used;
    const auto triangles = intact(mesh);
    find_shadow_triangles(mesh, triangles, 4, shadow, used);
    EXPECT_EQ(shadow, triangles);
}

}  // namespace
}  // namespace weft::view
