// A whole grid's normals row by row (grid_normals.h) against the general passes over its
// triangles (compute_face_normals, gather_vertex_normals): the same bits, for crumpled grids
// of several shapes, flat ones (exact zeros and signed zeros in the sums), collapsed cells
// (zero normals) and any split of the rows; and only a whole grid, in order, counts as one.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "raster/grid_normals.h"
#include "raster/mesh.h"
#include "raster/vector_isa.h"
#include "raster_test_support.h"

namespace weft::raster {
namespace {

using testing::whole_grid_triangles;

std::vector<glm::vec3> general_normals(const std::vector<glm::vec3>& positions,
                                       const std::vector<TriangleIndices>& triangles) {
    std::vector<glm::vec3> faces(triangles.size()), normals(positions.size());
    VertexTriangles around;
    find_vertex_triangles(triangles, positions.size(), around);
    compute_face_normals(positions, triangles, faces, 0, triangles.size());
    gather_vertex_normals(faces, around, normals, 0, positions.size());
    return normals;
}

std::vector<glm::vec3> grid_normals(const std::vector<glm::vec3>& positions, int rows, int cols,
                                    std::size_t split, bool avx2) {
    GridNormals grid;
    grid.use_avx2(avx2);
    grid.resize(rows, cols);
    std::vector<glm::vec3> normals(positions.size(), glm::vec3(7.0f));
    const auto all_rows = static_cast<std::size_t>(rows);
    const std::size_t middle = std::min(split, all_rows - 1);
    grid.load_positions(positions, 0, 3);
    grid.load_positions(positions, 3, positions.size());
    grid.find_faces(middle, all_rows - 1);  // any order, any split
    grid.find_faces(0, middle);
    grid.gather(normals, std::min(split, all_rows), all_rows);
    grid.gather(normals, 0, std::min(split, all_rows));
    return normals;
}

TEST(GridNormals, GiveTheGeneralPassesBits) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> jitter(-0.02f, 0.02f);
    int cases = 0;
    for (const auto& [rows, cols] : {std::pair{2, 2}, {2, 7}, {6, 2}, {3, 3}, {17, 13}, {40, 41}}) {
        const std::vector<TriangleIndices> triangles = whole_grid_triangles(rows, cols);
        ASSERT_TRUE(is_whole_grid(triangles, rows, cols));
        for (int shape = 0; shape < 4; ++shape) {
            std::vector<glm::vec3> positions;
            for (int r = 0; r < rows; ++r) {
                for (int c = 0; c < cols; ++c) {
                    glm::vec3 p(0.05f * static_cast<float>(c), 0.0f, 0.05f * static_cast<float>(r));
                    if (shape == 1) p += glm::vec3(jitter(rng), jitter(rng), jitter(rng));
                    if (shape == 2) p.y = -0.3f * p.x * p.z;  // curved, mirrored normals
                    if (shape == 3 && (r + c) % 3 == 0) p = glm::vec3(0.1f, 0.2f, 0.3f);
                    positions.push_back(p);
                }
            }
            const std::vector<glm::vec3> expected = general_normals(positions, triangles);
            for (std::size_t split : {std::size_t{0}, std::size_t{1}, std::size_t(rows / 2)}) {
                // Both builds of the row loops, where the CPU runs the AVX2 one.
                for (const bool avx2 : {false, true}) {
                    const std::vector<glm::vec3> normals =
                        grid_normals(positions, rows, cols, split, avx2);
                    EXPECT_EQ(std::memcmp(normals.data(), expected.data(),
                                          normals.size() * sizeof(glm::vec3)),
                              0)
                        << rows << " x " << cols << ", shape " << shape << ", split " << split
                        << (avx2 ? ", AVX2" : ", baseline");
                }
                ++cases;
            }
        }
    }
    EXPECT_EQ(cases, 6 * 4 * 3);
}

TEST(GridNormals, UseTheirAvx2BuildOnlyWhereTheCpuRunsIt) {
    GridNormals grid;
    EXPECT_EQ(grid.avx2_in_use(), avx2_supported());
    grid.use_avx2(false);
    EXPECT_FALSE(grid.avx2_in_use());
    grid.use_avx2(true);
    EXPECT_EQ(grid.avx2_in_use(), avx2_supported());
}

TEST(GridNormals, OnlyAWholeGridInOrderIsOne) {
    std::vector<TriangleIndices> triangles = whole_grid_triangles(4, 5);
    EXPECT_TRUE(is_whole_grid(triangles, 4, 5));
    EXPECT_FALSE(is_whole_grid(triangles, 5, 4));
    EXPECT_FALSE(is_whole_grid(triangles, 1, 20));
    std::vector<TriangleIndices> torn = triangles;
    torn.erase(torn.begin() + 9);
    EXPECT_FALSE(is_whole_grid(torn, 4, 5));
    std::vector<TriangleIndices> swapped = triangles;
    std::swap(swapped[4], swapped[5]);
    EXPECT_FALSE(is_whole_grid(swapped, 4, 5));
    std::vector<TriangleIndices> turned = triangles;
    turned[7] = {turned[7][1], turned[7][2], turned[7][0]};  // the same face, other corner first
    EXPECT_FALSE(is_whole_grid(turned, 4, 5));
}

}  // namespace
}  // namespace weft::raster
