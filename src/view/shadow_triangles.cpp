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
    // Blocks of block_cells cells along each side, then one block of what is left at the far
    // edge, so that a side not a multiple of block_cells keeps no strip of fine triangles.
    // On an offset grid a block's height stays even: its left and right edges then join
    // corners of the same shift, and it covers its cells' area exactly; an odd row left over
    // keeps its own triangles.
    const bool even_heights = cloth.odd_row_shift != 0.0;
    auto block_edges = [&](int cells, bool even) {
        std::vector<int> edges{0};
        while (edges.back() + block_cells <= cells) edges.push_back(edges.back() + block_cells);
        int rest = cells - edges.back();
        if (even) rest -= rest % 2;
        if (rest > 0) edges.push_back(edges.back() + rest);
        return edges;  // block k spans [edges[k], edges[k + 1])
    };
    const std::vector<int> row_edges = block_edges(rows - 1, even_heights);
    const std::vector<int> col_edges = block_edges(cell_cols, false);
    const int block_rows = static_cast<int>(row_edges.size()) - 1;
    const int block_cols = static_cast<int>(col_edges.size()) - 1;
    // The block row (column) of each cell row (column), -1 past the last block.
    auto block_of_line = [](const std::vector<int>& edges, int line_count) {
        std::vector<int> block(static_cast<std::size_t>(line_count), -1);
        for (std::size_t k = 0; k + 1 < edges.size(); ++k)
            for (int line = edges[k]; line < edges[k + 1]; ++line)
                block[static_cast<std::size_t>(line)] = static_cast<int>(k);
        return block;
    };
    const std::vector<int> block_row_of = block_of_line(row_edges, rows - 1);
    const std::vector<int> block_col_of = block_of_line(col_edges, cell_cols);
    // A block is whole when each of its cells has both triangles.
    auto block_of_cell = [&](long cell) -> long {
        const int block_row = block_row_of[static_cast<std::size_t>(cell / cell_cols)];
        const int block_col = block_col_of[static_cast<std::size_t>(cell % cell_cols)];
        if (block_row < 0 || block_col < 0) return -1;
        return static_cast<long>(block_row) * block_cols + block_col;
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
            const int top = row_edges[static_cast<std::size_t>(block_row)];
            const int bottom = row_edges[static_cast<std::size_t>(block_row) + 1];
            const int left = col_edges[static_cast<std::size_t>(block_col)];
            const int right = col_edges[static_cast<std::size_t>(block_col) + 1];
            shadow.push_back({index(top, left), index(bottom, left), index(top, right)});
            shadow.push_back({index(top, right), index(bottom, left), index(bottom, right)});
        }
    }
    // Everything else as it is: triangles of broken blocks, of an offset grid's odd last row,
    // and any outside a cell.
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
