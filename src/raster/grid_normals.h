// Vertex normals of a mesh that is a whole regular grid: rows × cols vertices in row order,
// each cell (r, c) split into (top left, bottom left, top right) and (top right, bottom left,
// bottom right), cell by cell in row order (a cloth sheet before any tear). Computed row by
// row over per-component arrays, so the loops vectorise and need no index lookups; the same
// bits as compute_face_normals and gather_vertex_normals over those triangles: the same
// cross products, and each vertex's face normals summed in ascending triangle order.
#pragma once

#include <cstddef>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "raster/mesh.h"
#include "raster/vector_isa.h"

namespace weft::raster {

namespace grid_normals_kernel {

// The arrays the row loops read (grid_normals_kernel.inl).
struct FaceJob {
    int rows = 0, cols = 0;
    const float* position[3] = {};  // m, x y z per particle
    const float* a[3] = {};         // the cells' face normals (GridNormals::a_, b_)
    const float* b[3] = {};
};

// The row loops built with AVX2 (grid_normals_avx2.cpp); only where avx2_supported().
// find_faces writes the face normals into a and b, the arrays the job reads them from.
void find_faces_avx2(const FaceJob& job, float* const (&a)[3], float* const (&b)[3],
                     std::size_t row_begin, std::size_t row_end);
void gather_avx2(const FaceJob& job, glm::vec3* normals, std::size_t row_begin,
                 std::size_t row_end);

}  // namespace grid_normals_kernel

// Whether `triangles` are exactly that grid's for a rows × cols sheet (at least 2 × 2).
bool is_whole_grid(std::span<const TriangleIndices> triangles, int rows, int cols);

class GridNormals {
  public:
    void resize(int rows, int cols);
    int rows() const { return rows_; }
    int cols() const { return cols_; }

    // Takes particles [begin, end)'s positions (the mesh's, in row order).
    void load_positions(std::span<const glm::vec3> positions, std::size_t begin, std::size_t end);
    // The two face normals of every cell on cell rows [begin, end) (rows - 1 of them).
    void find_faces(std::size_t row_begin, std::size_t row_end);
    // The unit normal of every vertex on rows [begin, end), into normals (one per particle).
    void gather(std::span<glm::vec3> normals, std::size_t row_begin, std::size_t row_end) const;

    // Whether the row loops use their AVX2 build, where the CPU has it (vector_isa.h): the
    // same bits either way.
    void use_avx2(bool enabled) { avx2_ = enabled && avx2_supported(); }
    bool avx2_in_use() const { return avx2_; }

  private:
    grid_normals_kernel::FaceJob job() const;

    int rows_ = 0, cols_ = 0;
    bool avx2_ = avx2_supported();
    std::vector<float> x_, y_, z_;  // m, one per particle
    // The face normals of each cell's first (a) and second (b) triangle, per component,
    // (rows - 1) × (cols - 1): twice the triangle's area long.
    std::vector<float> a_[3], b_[3];
};

}  // namespace weft::raster
