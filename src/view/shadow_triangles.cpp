#include "view/shadow_triangles.h"

#include <algorithm>
#include <cstdint>

namespace weft::view {

int shadow_block_cells(const Cloth& cloth) {
    if (cloth.is_mesh()) return 1;
    // Even, so that an offset grid's half-spacing shifts cancel across a block.
    const int cells = std::max(cloth.rows, cloth.cols) / 32;
    return cells < 2 ? 1 : cells - cells % 2;
}

namespace {

void find_used(std::size_t particle_count, std::span<const raster::TriangleIndices> triangles,
               std::vector<std::uint32_t>& used) {
    std::vector<std::uint8_t> named(particle_count, 0);
    for (const raster::TriangleIndices& t : triangles)
        for (std::uint32_t v : t)
            if (v < particle_count) named[v] = 1;
    used.clear();
    for (std::size_t p = 0; p < particle_count; ++p)
        if (named[p]) used.push_back(static_cast<std::uint32_t>(p));
}

void find_coarse_triangles(const Cloth& cloth, std::span<const raster::TriangleIndices> intact,
                           int block_cells, std::vector<raster::TriangleIndices>& shadow) {
    shadow.clear();
    const int rows = cloth.rows, cols = cloth.cols;
    if (block_cells <= 1 || cloth.is_mesh() || rows < 2 || cols < 2) {
        shadow.assign(intact.begin(), intact.end());
        return;
    }
    const int cell_cols = cols - 1;
    const auto cell_count = static_cast<std::size_t>((rows - 1) * cell_cols);
    // Each intact triangle's cell: the one whose four corners hold its three vertices.
    auto cell_of = [&](const raster::TriangleIndices& t) -> long {
        const std::uint32_t low = std::min({t[0], t[1], t[2]});
        const int row = static_cast<int>(low / static_cast<std::uint32_t>(cols));
        int col = static_cast<int>(low % static_cast<std::uint32_t>(cols));
        // The lowest index is on the cell's top row: its top-left corner, or its top-right
        // for a triangle that leaves the top-left out, whose cell starts a column further left.
        auto in_cell = [&](int r, int c) {
            if (r < 0 || c < 0 || r + 1 >= rows || c + 1 >= cols) return false;
            for (std::uint32_t v : t) {
                const int vr = static_cast<int>(v / static_cast<std::uint32_t>(cols));
                const int vc = static_cast<int>(v % static_cast<std::uint32_t>(cols));
                if (vr < r || vr > r + 1 || vc < c || vc > c + 1) return false;
            }
            return true;
        };
        if (in_cell(row, col)) return static_cast<long>(row) * cell_cols + col;
        if (in_cell(row, col - 1)) return static_cast<long>(row) * cell_cols + col - 1;
        return -1;
    };
    std::vector<std::uint8_t> triangles_in_cell(cell_count, 0);
    for (const raster::TriangleIndices& t : intact) {
        const long cell = cell_of(t);
        if (cell >= 0 && triangles_in_cell[static_cast<std::size_t>(cell)] < 255)
            ++triangles_in_cell[static_cast<std::size_t>(cell)];
    }
    // A block is whole when it lies inside the grid and each of its cells has both triangles.
    const int block_rows = (rows - 1) / block_cells, block_cols = cell_cols / block_cells;
    auto block_of_cell = [&](long cell) -> long {
        const long row = cell / cell_cols, col = cell % cell_cols;
        const long block_row = row / block_cells, block_col = col / block_cells;
        if (block_row >= block_rows || block_col >= block_cols) return -1;
        return block_row * block_cols + block_col;
    };
    std::vector<std::uint8_t> block_whole(static_cast<std::size_t>(block_rows * block_cols), 1);
    for (long cell = 0; cell < static_cast<long>(cell_count); ++cell) {
        const long block = block_of_cell(cell);
        if (block >= 0 && triangles_in_cell[static_cast<std::size_t>(cell)] != 2)
            block_whole[static_cast<std::size_t>(block)] = 0;
    }
    auto index = [&](int r, int c) { return static_cast<std::uint32_t>(r * cols + c); };
    for (int block_row = 0; block_row < block_rows; ++block_row) {
        for (int block_col = 0; block_col < block_cols; ++block_col) {
            if (!block_whole[static_cast<std::size_t>(block_row * block_cols + block_col)])
                continue;
            const int top = block_row * block_cells, left = block_col * block_cells;
            const int bottom = top + block_cells, right = left + block_cells;
            shadow.push_back({index(top, left), index(bottom, left), index(top, right)});
            shadow.push_back({index(top, right), index(bottom, left), index(bottom, right)});
        }
    }
    // Everything else as it is: triangles of broken or edge blocks, and any outside a cell.
    for (const raster::TriangleIndices& t : intact) {
        const long cell = cell_of(t);
        const long block = cell >= 0 ? block_of_cell(cell) : -1;
        if (block < 0 || !block_whole[static_cast<std::size_t>(block)]) shadow.push_back(t);
    }
}

}  // namespace

void find_shadow_triangles(const Cloth& cloth, std::span<const raster::TriangleIndices> intact,
                           int block_cells, std::vector<raster::TriangleIndices>& shadow,
                           std::vector<std::uint32_t>& used) {
    find_coarse_triangles(cloth, intact, block_cells, shadow);
    find_used(cloth.positions.size(), shadow, used);
}

}  // namespace weft::view
