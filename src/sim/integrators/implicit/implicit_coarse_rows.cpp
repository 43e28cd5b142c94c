#include "sim/integrators/implicit/implicit_coarse_rows.h"

#include <algorithm>

#include "sim/grid/grid_force_pass.h"

namespace weft {

void CoarseRows::size_for(int level_rows, int level_cols) {
    // Every build stores every node of every row (build_from_fine); the row above row 0 and the end
    // columns are never written, so a level of the same shape keeps its zeros.
    if (level_rows == rows && level_cols == cols && !storage.empty()) return;
    rows = level_rows;
    cols = level_cols;
    row_floats = static_cast<std::size_t>(cols) + 2;
    storage.assign(
        static_cast<std::size_t>(blocks) * 6 * (static_cast<std::size_t>(rows) + 1) * row_floats,
        0.0f);
}

void multiply_coarse_row(const CoarseRows& matrix, int row, CoarseVectorRow above,
                         CoarseVectorRow here, CoarseVectorRow below, float* __restrict out_x,
                         float* __restrict out_y, float* __restrict out_z) {
    const auto multiply = kernel_of(
        matrix.kernel_build, implicit_kernel::multiply_coarse_row_baseline,
        implicit_kernel::multiply_coarse_row_avx2, implicit_kernel::multiply_coarse_row_avx512);
    multiply(matrix, row, above, here, below, out_x, out_y, out_z);
}

}  // namespace weft
