// The first coarse level's matrix as rows of floats, for the products of its V-cycle
// (implicit_multilevel.h): y = A_c v, one row of nodes at a time.
//
// The level is built in double, node by node (six numbers per symmetric 3x3 block: its own
// block and the four forward couplings (0,1) (1,-1) (1,0) (1,1)). A product over it visits
// nine blocks a node, 81 multiply-adds; laid out as one array per block entry and per row,
// with a zero column either side, the loop over a row's nodes has no branch and vectorises.
// The backward couplings are the forward ones of the neighbours (A_JI = A_IJ, each block being
// symmetric), read from the row above and the node to the left.
#pragma once

#include <cstddef>
#include <vector>

#include "sim/grid/kernel_build.h"

namespace weft {

struct CoarseRows {
    static constexpr int blocks = 5;  // own, then the forward slots (0,1) (1,-1) (1,0) (1,1)
    int rows = 0, cols = 0;
    std::size_t row_floats = 0;  // cols + 2: a zero column either side
    // Per block, per entry (xx yy zz xy xz yz): rows + 1 rows of row_floats, the first all
    // zeros (the row above row 0).
    std::vector<float> storage;
    SimdLevel kernel_build = supported_simd_level();  // of multiply_coarse_row

    void size_for(int level_rows, int level_cols);
    // Entry e of block b at node (row, -1 .. cols); row may be -1 (zeros).
    const float* entry(int block, int e, int row) const {
        return storage.data() +
               ((static_cast<std::size_t>(block) * 6 + static_cast<std::size_t>(e)) *
                    (static_cast<std::size_t>(rows) + 1) +
                static_cast<std::size_t>(row + 1)) *
                   row_floats +
               1;
    }
};

// Three rows of a vector field (x, y, z), each of row_floats with zero end columns, indexed
// from column -1.
struct CoarseVectorRow {
    const float* x;
    const float* y;
    const float* z;
};

// out[c] = (A_c v)[row, c] for every column, given v's rows above, at and below `row` (zero
// rows where off the level).
void multiply_coarse_row(const CoarseRows& matrix, int row, CoarseVectorRow above,
                         CoarseVectorRow here, CoarseVectorRow below, float* __restrict out_x,
                         float* __restrict out_y, float* __restrict out_z);

namespace implicit_kernel {
// Its builds (implicit_grid_kernel_build.inl); multiply_coarse_row picks the matrix's kernel_build.
void multiply_coarse_row_baseline(const CoarseRows& matrix, int row, CoarseVectorRow above,
                                  CoarseVectorRow here, CoarseVectorRow below, float* out_x,
                                  float* out_y, float* out_z);
void multiply_coarse_row_avx2(const CoarseRows& matrix, int row, CoarseVectorRow above,
                              CoarseVectorRow here, CoarseVectorRow below, float* out_x,
                              float* out_y, float* out_z);
void multiply_coarse_row_avx512(const CoarseRows& matrix, int row, CoarseVectorRow above,
                                CoarseVectorRow here, CoarseVectorRow below, float* out_x,
                                float* out_y, float* out_z);
}  // namespace implicit_kernel

}  // namespace weft
