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

namespace weft::raster {

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

  private:
    int rows_ = 0, cols_ = 0;
    std::vector<float> x_, y_, z_;  // m, one per particle
    // The face normals of each cell's first (a) and second (b) triangle, per component,
    // (rows - 1) × (cols - 1): twice the triangle's area long.
    std::vector<float> a_[3], b_[3];
};

}  // namespace weft::raster
