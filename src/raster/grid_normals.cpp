#include "raster/grid_normals.h"

#include <cmath>
#include <vector>

#include "raster/vector_isa.h"

namespace weft::raster {

bool is_whole_grid(std::span<const TriangleIndices> triangles, int rows, int cols) {
    if (rows < 2 || cols < 2) return false;
    const auto cells = static_cast<std::size_t>(rows - 1) * static_cast<std::size_t>(cols - 1);
    if (triangles.size() != 2 * cells) return false;
    std::size_t index = 0;
    for (int r = 0; r + 1 < rows; ++r) {
        for (int c = 0; c + 1 < cols; ++c) {
            const auto top_left = static_cast<std::uint32_t>(r * cols + c);
            const std::uint32_t top_right = top_left + 1;
            const std::uint32_t bottom_left = top_left + static_cast<std::uint32_t>(cols);
            const std::uint32_t bottom_right = bottom_left + 1;
            if (triangles[index++] != TriangleIndices{top_left, bottom_left, top_right})
                return false;
            if (triangles[index++] != TriangleIndices{top_right, bottom_left, bottom_right})
                return false;
        }
    }
    return true;
}

void GridNormals::resize(int rows, int cols) {
    rows_ = rows;
    cols_ = cols;
    const auto particles = static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols);
    const auto cells = static_cast<std::size_t>(rows - 1) * static_cast<std::size_t>(cols - 1);
    for (std::vector<float>* component : {&x_, &y_, &z_}) component->resize(particles);
    for (int k = 0; k < 3; ++k) {
        a_[k].resize(cells);
        b_[k].resize(cells);
    }
}

void GridNormals::load_positions(std::span<const glm::vec3> positions, std::size_t begin,
                                 std::size_t end) {
    for (std::size_t p = begin; p < end; ++p) {
        x_[p] = positions[p].x;
        y_[p] = positions[p].y;
        z_[p] = positions[p].z;
    }
}

namespace grid_normals_kernel::baseline {
#include "raster/grid_normals_kernel.inl"
}  // namespace grid_normals_kernel::baseline

grid_normals_kernel::FaceJob GridNormals::job() const {
    grid_normals_kernel::FaceJob job;
    job.rows = rows_;
    job.cols = cols_;
    job.position[0] = x_.data();
    job.position[1] = y_.data();
    job.position[2] = z_.data();
    for (int k = 0; k < 3; ++k) {
        job.a[k] = a_[k].data();
        job.b[k] = b_[k].data();
    }
    return job;
}

void GridNormals::find_faces(std::size_t row_begin, std::size_t row_end) {
    float* const a[3] = {a_[0].data(), a_[1].data(), a_[2].data()};
    float* const b[3] = {b_[0].data(), b_[1].data(), b_[2].data()};
    if (avx2_)
        grid_normals_kernel::find_faces_avx2(job(), a, b, row_begin, row_end);
    else
        grid_normals_kernel::baseline::find_faces(job(), a, b, row_begin, row_end);
}

void GridNormals::gather(std::span<glm::vec3> normals, std::size_t row_begin,
                         std::size_t row_end) const {
    if (avx2_)
        grid_normals_kernel::gather_avx2(job(), normals.data(), row_begin, row_end);
    else
        grid_normals_kernel::baseline::gather(job(), normals.data(), row_begin, row_end);
}

}  // namespace weft::raster
