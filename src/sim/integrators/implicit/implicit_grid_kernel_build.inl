// One build of the structured implicit solve's row kernels: the body (internal linkage) and
// its entry points, named with the build's suffix. Each implicit_grid_kernel_<suffix>.cpp
// defines WEFT_KERNEL_SUFFIX and includes this file; CMake compiles each with its own
// instruction set and -ffp-contract=off, so every build rounds every operation alike.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "sim/integrators/implicit/implicit_coarse_rows.h"
#include "sim/integrators/implicit/implicit_grid_kernel.h"

#define WEFT_KERNEL_JOIN(name, suffix) name##_##suffix
#define WEFT_KERNEL_NAME(name, suffix) WEFT_KERNEL_JOIN(name, suffix)

namespace weft::implicit_kernel {
namespace {
#include "sim/integrators/implicit/implicit_coarse_rows_kernel.inl"
#include "sim/integrators/implicit/implicit_grid_kernel.inl"
}  // namespace

void WEFT_KERNEL_NAME(setup_rows, WEFT_KERNEL_SUFFIX)(const Job& job, int begin, int end,
                                                      double warm_start) {
    setup_rows(job, begin, end, warm_start);
}

void WEFT_KERNEL_NAME(residual_rows, WEFT_KERNEL_SUFFIX)(const Job& job, int begin, int end,
                                                         RowSums sums) {
    residual_rows(job, begin, end, sums);
}

void WEFT_KERNEL_NAME(direction_rows, WEFT_KERNEL_SUFFIX)(const Job& job, int begin, int end,
                                                          float beta, RowSums sums) {
    direction_rows(job, begin, end, beta, sums);
}

void WEFT_KERNEL_NAME(update_rows, WEFT_KERNEL_SUFFIX)(const Job& job, int begin, int end,
                                                       float alpha, RowSums sums) {
    update_rows(job, begin, end, alpha, sums);
}

void WEFT_KERNEL_NAME(smooth_rows, WEFT_KERNEL_SUFFIX)(const Job& job, int begin, int end,
                                                       float omega) {
    smooth_rows(job, begin, end, omega);
}

void WEFT_KERNEL_NAME(unfiltered_product_rows, WEFT_KERNEL_SUFFIX)(const Job& job, int begin,
                                                                   int end) {
    unfiltered_product_rows(job, begin, end);
}

void WEFT_KERNEL_NAME(multiply_coarse_row,
                      WEFT_KERNEL_SUFFIX)(const CoarseRows& matrix, int row, CoarseVectorRow above,
                                          CoarseVectorRow here, CoarseVectorRow below, float* out_x,
                                          float* out_y, float* out_z) {
    multiply_coarse_row_in_build(matrix, row, above, here, below, out_x, out_y, out_z);
}

}  // namespace weft::implicit_kernel
