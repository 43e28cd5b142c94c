#include "sim/integrators/implicit_coarse_rows.h"

#include <algorithm>

#include "sim/grid_force_pass.h"
#include "sim/integrators/implicit_multilevel.h"

namespace weft {

void CoarseRows::size_for(int level_rows, int level_cols) {
    // Every build stores every node of every row (store_row); the row above row 0 and the end
    // columns are never written, so a level of the same shape keeps its zeros.
    if (level_rows == rows && level_cols == cols && !storage.empty()) return;
    rows = level_rows;
    cols = level_cols;
    row_floats = static_cast<std::size_t>(cols) + 2;
    storage.assign(
        static_cast<std::size_t>(blocks) * 6 * (static_cast<std::size_t>(rows) + 1) * row_floats,
        0.0f);
}

void CoarseRows::store_row(const ImplicitCoarseLevel& level, int row) {
    const std::size_t first_node = static_cast<std::size_t>(row) * static_cast<std::size_t>(cols);
    for (int block = 0; block < blocks; ++block)
        for (int e = 0; e < 6; ++e) {
            float* out = const_cast<float*>(entry(block, e, row));
            for (int c = 0; c < cols; ++c) {
                const std::size_t n = first_node + static_cast<std::size_t>(c);
                out[c] = static_cast<float>(
                    block == 0
                        ? level.diagonal[6 * n + static_cast<std::size_t>(e)]
                        : level.neighbours[(n * 4 + static_cast<std::size_t>(block - 1)) * 6 +
                                           static_cast<std::size_t>(e)]);
            }
        }
}

void multiply_coarse_row(const CoarseRows& matrix, int row, CoarseVectorRow above,
                         CoarseVectorRow here, CoarseVectorRow below, float* __restrict out_x,
                         float* __restrict out_y, float* __restrict out_z) {
    const auto multiply = kernel_of(implicit_kernel::multiply_coarse_row_baseline,
                                    implicit_kernel::multiply_coarse_row_avx2,
                                    implicit_kernel::multiply_coarse_row_avx512);
    multiply(matrix, row, above, here, below, out_x, out_y, out_z);
}

}  // namespace weft
