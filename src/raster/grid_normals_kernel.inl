// The row loops of a whole grid's normals (grid_normals.h), as plain functions over
// per-component arrays: included by grid_normals.cpp into `baseline` and by
// grid_normals_avx2.cpp, built with AVX2 and no FMA, into `avx2`. Only sub, mul, add, sqrt and
// div, in the same order in both, so the same bits either way.
//
// Included inside namespace weft::raster::grid_normals_kernel::<build>.

// glm::cross(e, f), component by component, over a row of cells.
inline void cross_row(const float* __restrict ex, const float* __restrict ey,
                      const float* __restrict ez, const float* __restrict fx,
                      const float* __restrict fy, const float* __restrict fz, float* __restrict nx,
                      float* __restrict ny, float* __restrict nz, std::size_t count) {
    for (std::size_t c = 0; c < count; ++c) {
        nx[c] = ey[c] * fz[c] - fy[c] * ez[c];
        ny[c] = ez[c] * fx[c] - fz[c] * ex[c];
        nz[c] = ex[c] * fy[c] - fx[c] * ey[c];
    }
}

// One component of the edge vectors of a row of cells, from its top and bottom rows of
// vertices: a = (top left, bottom left, top right): e = BL - TL, f = TR - TL;
// b = (top right, bottom left, bottom right): g = BL - TR, h = BR - TR.
inline void edge_row(const float* __restrict top, const float* __restrict bottom,
                     float* __restrict e, float* __restrict f, float* __restrict g,
                     float* __restrict h, std::size_t cells) {
    for (std::size_t c = 0; c < cells; ++c) {
        e[c] = bottom[c] - top[c];
        f[c] = top[c + 1] - top[c];
        g[c] = bottom[c] - top[c + 1];
        h[c] = bottom[c + 1] - top[c + 1];
    }
}

void find_faces(const FaceJob& job, float* const (&a)[3], float* const (&b)[3],
                std::size_t row_begin, std::size_t row_end) {
    const auto cols = static_cast<std::size_t>(job.cols);
    const std::size_t cells = cols - 1;
    // Edge vectors of one cell row, per component: reused row after row, and kept by the
    // thread (the pool's are persistent), so no frame allocates once the first has run.
    thread_local std::vector<float> edges;
    if (edges.size() < 12 * cells) edges.resize(12 * cells);
    float* e[3] = {edges.data(), edges.data() + cells, edges.data() + 2 * cells};
    float* f[3] = {edges.data() + 3 * cells, edges.data() + 4 * cells, edges.data() + 5 * cells};
    float* g[3] = {edges.data() + 6 * cells, edges.data() + 7 * cells, edges.data() + 8 * cells};
    float* h[3] = {edges.data() + 9 * cells, edges.data() + 10 * cells, edges.data() + 11 * cells};
    for (std::size_t r = row_begin; r < row_end; ++r) {
        for (int k = 0; k < 3; ++k) {
            const float* top = job.position[k] + r * cols;
            edge_row(top, top + cols, e[k], f[k], g[k], h[k], cells);
        }
        const std::size_t first = r * cells;
        cross_row(e[0], e[1], e[2], f[0], f[1], f[2], a[0] + first, a[1] + first, a[2] + first,
                  cells);
        cross_row(g[0], g[1], g[2], h[0], h[1], h[2], b[0] + first, b[1] + first, b[2] + first,
                  cells);
    }
}

// One component of a row of vertices' sums, columns [1, cols - 1), in gather_vertex_normals'
// order: the cell above-left's b, the cell above's a and b, the cell left's a and b, the
// cell's own a (those above only below the first row, those below only above the last).
inline void sum_row(const float* __restrict above_a, const float* __restrict above_b,
                    const float* __restrict below_a, const float* __restrict below_b,
                    bool has_above, bool has_below, float* __restrict sum, std::size_t cells) {
    for (std::size_t c = 1; c < cells; ++c) {
        float total = 0.0f;
        if (has_above) {
            total += above_b[c - 1];
            total += above_a[c];
            total += above_b[c];
        }
        if (has_below) {
            total += below_a[c - 1];
            total += below_b[c - 1];
            total += below_a[c];
        }
        sum[c] = total;
    }
}

void gather(const FaceJob& job, glm::vec3* normals, std::size_t row_begin, std::size_t row_end) {
    const auto cols = static_cast<std::size_t>(job.cols);
    const std::size_t cells = cols - 1;
    thread_local std::vector<float> sums;  // as find_faces' edges
    if (sums.size() < 3 * cols) sums.resize(3 * cols);
    float* sum[3] = {sums.data(), sums.data() + cols, sums.data() + 2 * cols};
    for (std::size_t r = row_begin; r < row_end; ++r) {
        const bool has_above = r > 0, has_below = r + 1 < static_cast<std::size_t>(job.rows);
        // Cell rows r - 1 and r (a row that does not exist is never read).
        const std::size_t above = has_above ? (r - 1) * cells : 0;
        const std::size_t below = has_below ? r * cells : 0;
        for (int k = 0; k < 3; ++k) {
            const float* above_a = job.a[k] + above;
            const float* above_b = job.b[k] + above;
            const float* below_a = job.a[k] + below;
            const float* below_b = job.b[k] + below;
            if (has_above && has_below)
                sum_row(above_a, above_b, below_a, below_b, true, true, sum[k], cells);
            else
                sum_row(above_a, above_b, below_a, below_b, has_above, has_below, sum[k], cells);
            // The first and last columns: the cells on one side only.
            float first = 0.0f, last = 0.0f;
            if (has_above) {
                first += above_a[0];
                first += above_b[0];
                last += above_b[cells - 1];
            }
            if (has_below) {
                first += below_a[0];
                last += below_a[cells - 1];
                last += below_b[cells - 1];
            }
            sum[k][0] = first;
            sum[k][cells] = last;
        }
        // unit_or_zero: glm::length (x² + y² then + z², its square root), then each
        // component divided by it.
        for (std::size_t c = 0; c < cols; ++c) {
            const float x = sum[0][c], y = sum[1][c], z = sum[2][c];
            const float length = std::sqrt(x * x + y * y + z * z);
            normals[r * cols + c] =
                length > 0.0f ? glm::vec3(x / length, y / length, z / length) : glm::vec3(0.0f);
        }
    }
}
