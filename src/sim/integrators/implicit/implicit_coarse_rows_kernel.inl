// The first coarse level's row product (integrators/implicit_coarse_rows.h), included inside
// an anonymous namespace by each build of the implicit solve's kernels
// (implicit_grid_kernel_build.inl), so it runs eight floats at a time where the CPU allows,
// with the same rounding in every build.

// out += B v over a row of n nodes, B symmetric with entries e (xx yy zz xy xz yz), each
// pointer already at the row's first node. One term of the product at a time: each loop is
// short and vectorises, and every node's sum is taken in the same order.
void add_block_times(const float* const* e, const float* __restrict vx, const float* __restrict vy,
                     const float* __restrict vz, int n, float* __restrict out_x,
                     float* __restrict out_y, float* __restrict out_z) {
    const float* __restrict xx = e[0];
    const float* __restrict yy = e[1];
    const float* __restrict zz = e[2];
    const float* __restrict xy = e[3];
    const float* __restrict xz = e[4];
    const float* __restrict yz = e[5];
    for (int c = 0; c < n; ++c) {
        out_x[c] += xx[c] * vx[c] + xy[c] * vy[c] + xz[c] * vz[c];
        out_y[c] += xy[c] * vx[c] + yy[c] * vy[c] + yz[c] * vz[c];
        out_z[c] += xz[c] * vx[c] + yz[c] * vy[c] + zz[c] * vz[c];
    }
}

void multiply_coarse_row_in_build(const CoarseRows& matrix, int row, CoarseVectorRow above,
                                  CoarseVectorRow here, CoarseVectorRow below,
                                  float* __restrict out_x, float* __restrict out_y,
                                  float* __restrict out_z) {
    const int n = matrix.cols;
    for (int c = 0; c < n; ++c) out_x[c] = out_y[c] = out_z[c] = 0.0f;
    // Block `block` of node (block_row, c + block_col) times v at (c + v_col) of `v`.
    auto term = [&](int block, int block_row, int block_col, CoarseVectorRow v, int v_col) {
        const float* e[6];
        for (int k = 0; k < 6; ++k) e[k] = matrix.entry(block, k, block_row) + block_col;
        add_block_times(e, v.x + v_col, v.y + v_col, v.z + v_col, n, out_x, out_y, out_z);
    };
    constexpr int own = 0, east = 1, south_west = 2, south = 3, south_east = 4;
    term(own, row, 0, here, 0);
    term(east, row, 0, here, 1);
    term(east, row, -1, here, -1);  // the left node's coupling to this one
    term(south_west, row, 0, below, -1);
    term(south, row, 0, below, 0);
    term(south_east, row, 0, below, 1);
    // The row above's couplings down to this row.
    term(south_west, row - 1, 1, above, 1);
    term(south, row - 1, 0, above, 0);
    term(south_east, row - 1, -1, above, -1);
}
