#include "sim/integrators/implicit_multilevel.h"

#include <algorithm>

namespace weft {
namespace {

#include "sim/contact_filter.inl"
#include "sim/symmetric_block.inl"

// The four forward neighbour offsets of a coarse node, (row, col).
constexpr int forward_rows[4] = {0, 1, 1, 1};
constexpr int forward_cols[4] = {1, -1, 0, 1};

// The forward slot of a coarse offset, or -1 for (0, -1), which belongs to the other node's
// (0, 1) slot, and -2 for (0, 0).
int slot_of(int row_step, int col_step) {
    if (row_step == 0) return col_step == 1 ? 0 : col_step == -1 ? -1 : -2;
    return col_step + 2;  // (1,-1) -> 1, (1,0) -> 2, (1,1) -> 3
}

void add_block(double* into, const double* block, double scale) {
    for (int e = 0; e < 6; ++e) into[e] += scale * block[e];
}

// Adds the coupling block A_IJ (from I to J = I + (row_step, col_step), J != I) to the level.
void add_coupling(ImplicitCoarseLevel& level, int i, int j, int row_step, int col_step,
                  const double* block, double scale) {
    const int slot = slot_of(row_step, col_step);
    if (slot >= 0)
        add_block(&level.neighbours[(static_cast<std::size_t>(i) * 4 + slot) * 6], block, scale);
    else
        add_block(&level.neighbours[(static_cast<std::size_t>(j) * 4 + 0) * 6], block, scale);
}

void size_level(ImplicitCoarseLevel& level, int rows, int cols) {
    level.rows = rows;
    level.cols = cols;
    const auto nodes = static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols);
    level.diagonal.assign(6 * nodes, 0.0);
    level.neighbours.assign(24 * nodes, 0.0);
    level.inverse.assign(6 * nodes, 0.0);
    level.residual.assign(3 * nodes, 0.0);
    level.correction.assign(3 * nodes, 0.0);
}

// Runs pass(begin, end) over `rows`, split between the pool's threads when the fine grid has
// enough particles to pay for the hand-off.
template <class Pass>
void over_rows(int rows, int fine_particles, WorkerPool* pool, Pass&& pass) {
    if (pool && pool->thread_count() > 1 && fine_particles >= 4096)
        pool->parallel_for(static_cast<std::size_t>(rows), [&](std::size_t begin, std::size_t end) {
            pass(static_cast<int>(begin), static_cast<int>(end));
        });
    else
        pass(0, rows);
}

// out += mask · add over n floats.
void add_masked(float* __restrict out, const float* __restrict mask, const float* __restrict add,
                int n) {
    for (int c = 0; c < n; ++c) out[c] += mask[c] * add[c];
}

int aggregate(int row, int col, int coarse_cols) {
    return (row / 2) * coarse_cols + col / 2;
}

void invert_level(ImplicitCoarseLevel& level) {
    const std::size_t nodes = level.diagonal.size() / 6;
    for (std::size_t n = 0; n < nodes; ++n)
        invert_symmetric_block(&level.diagonal[6 * n], &level.inverse[6 * n]);
}

// The coupling blocks A_pq = -B, B = iso I + a aᵀ, of one direction's springs that start on
// fine row `row`, as six rows of `cols` floats (xx yy zz xy xz yz): zero where the spring is
// missing or an end is pinned (the filtered system has no coupling there). Off the grid, the
// padding's zero free mask does that; across a column edge, the zero terms.
void fine_couplings(const implicit_kernel::Job& job, const implicit_kernel::DirectionTerms& d,
                    int row, float* __restrict out) {
    const int cols = job.cols;
    const std::size_t base = job.pad + static_cast<std::size_t>(row) * cols;
    const std::ptrdiff_t o = static_cast<std::ptrdiff_t>(d.row_step) * cols + d.col_step;
    const float* __restrict iso = d.iso + base;
    const float* __restrict ax = d.axial_x + base;
    const float* __restrict ay = d.axial_y + base;
    const float* __restrict az = d.axial_z + base;
    const float* __restrict free_here = job.free + base;
    const float* __restrict free_there = job.free + base + o;
    for (int c = 0; c < cols; ++c) {
        const float minus_mask = -(free_here[c] * free_there[c]);
        const float i = minus_mask * iso[c];
        const float x = ax[c], y = ay[c], z = az[c];
        out[c] = i + minus_mask * (x * x);
        out[cols + c] = i + minus_mask * (y * y);
        out[2 * cols + c] = i + minus_mask * (z * z);
        out[3 * cols + c] = minus_mask * (x * y);
        out[4 * cols + c] = minus_mask * (x * z);
        out[5 * cols + c] = minus_mask * (y * z);
    }
}

// The first coarse level, from the fine stencil: A_c = Pᵀ F A F P over the free particles.
// A spring from fine (r, c) to (r + dr, c + dc) joins the aggregates (r/2, c/2) and
// ((r + dr)/2, (c + dc)/2): which of a node's slots it lands in depends only on the parity of
// r and c, so each direction has a table of four. Springs inside an aggregate cancel against
// their share of the fine diagonal blocks (twice -B); the others go to the forward slot, or,
// pointing back along the row, to the left node's (0, 1) slot. Coarse rows are built whole by
// one thread, fine rows and columns in order, so every sum is the same for any split.
void build_from_fine(ImplicitCoarseLevel& level, const implicit_kernel::Job& job,
                     WorkerPool* pool) {
    size_level(level, (job.rows + 1) / 2, (job.cols + 1) / 2);
    int slots[implicit_kernel::max_directions][2][2];
    for (int k = 0; k < job.direction_count; ++k)
        for (int row_parity = 0; row_parity < 2; ++row_parity)
            for (int col_parity = 0; col_parity < 2; ++col_parity) {
                const implicit_kernel::DirectionTerms& d = job.directions[k];
                // Floor division: a column step of -1 from an even column is a node back.
                const int row_step = (row_parity + d.row_step + 2) / 2 - 1;
                const int col_step = (col_parity + d.col_step + 2) / 2 - 1;
                slots[k][row_parity][col_parity] = slot_of(row_step, col_step);
            }
    const int cols = job.cols;
    over_rows(level.rows, job.rows * job.cols, pool, [&](int begin, int end) {
        thread_local std::vector<float> couplings;  // grown once: no step allocates
        couplings.resize(6 * static_cast<std::size_t>(cols));
        for (int row = begin; row < end; ++row) {
            const std::size_t first_node = static_cast<std::size_t>(row) * level.cols;
            for (int r = 2 * row; r < std::min(2 * row + 2, job.rows); ++r) {
                const std::size_t base = job.pad + static_cast<std::size_t>(r) * cols;
                for (int c = 0; c < cols; ++c) {
                    double* diagonal = &level.diagonal[6 * (first_node + c / 2)];
                    for (int e = 0; e < 6; ++e) diagonal[e] += job.diagonal[e][base + c];
                }
                for (int k = 0; k < job.direction_count; ++k) {
                    fine_couplings(job, job.directions[k], r, couplings.data());
                    const int* slot_by_parity = slots[k][r % 2];
                    for (int c = 0; c < cols; ++c) {
                        const int slot = slot_by_parity[c % 2];
                        if (slot == -1 && c < 2) continue;  // off the grid: no spring
                        const std::size_t node = first_node + c / 2;
                        double* into = slot == -2   ? &level.diagonal[6 * node]
                                       : slot == -1 ? &level.neighbours[(node - 1) * 24]
                                                    : &level.neighbours[(node * 4 + slot) * 6];
                        const double scale = slot == -2 ? 2.0 : 1.0;
                        for (int e = 0; e < 6; ++e)
                            into[e] += scale * couplings[static_cast<std::size_t>(e) * cols + c];
                    }
                }
            }
            for (int col = 0; col < level.cols; ++col)
                invert_symmetric_block(&level.diagonal[6 * (first_node + col)],
                                       &level.inverse[6 * (first_node + col)]);
        }
    });
}

// The next coarse level from a coarse one, by the same aggregation.
void build_from_coarse(ImplicitCoarseLevel& level, const ImplicitCoarseLevel& finer) {
    size_level(level, (finer.rows + 1) / 2, (finer.cols + 1) / 2);
    for (int r = 0; r < finer.rows; ++r) {
        for (int c = 0; c < finer.cols; ++c) {
            const std::size_t n = static_cast<std::size_t>(r) * finer.cols + c;
            const int node = aggregate(r, c, level.cols);
            add_block(&level.diagonal[6 * static_cast<std::size_t>(node)], &finer.diagonal[6 * n],
                      1.0);
            for (int slot = 0; slot < 4; ++slot) {
                const int r2 = r + forward_rows[slot], c2 = c + forward_cols[slot];
                if (r2 >= finer.rows || c2 < 0 || c2 >= finer.cols) continue;
                const double* coupling = &finer.neighbours[(n * 4 + slot) * 6];
                const int other = aggregate(r2, c2, level.cols);
                if (other == node)
                    add_block(&level.diagonal[6 * static_cast<std::size_t>(node)], coupling, 2.0);
                else
                    add_coupling(level, node, other, r2 / 2 - r / 2, c2 / 2 - c / 2, coupling, 1.0);
            }
        }
    }
    invert_level(level);
}

// The levels below `index` add their correction into this level's: restrict the residual,
// correct there (recursively), prolong back.
void add_coarser_corrections(std::vector<ImplicitCoarseLevel>& levels, const BandedCholesky& exact,
                             std::size_t index, double weight);

// The coarsest level's matrix into its banded factor (banded_cholesky.h). Node n's
// unknowns are 3n .. 3n + 2 and its forward neighbours are later nodes, at most cols + 1
// on, so the band reaches 3 (cols + 1) + 2 unknowns right of the diagonal.
void factor_exactly(ImplicitCoarseLevel& level, BandedCholesky& exact) {
    const std::size_t nodes = static_cast<std::size_t>(level.rows) * level.cols;
    exact.reset(3 * nodes, 3 * static_cast<std::size_t>(level.cols) + 5);
    // Where each of the six stored entries of a symmetric block sits, (row, column).
    constexpr int entry_row[6] = {0, 1, 2, 0, 0, 1};
    constexpr int entry_col[6] = {0, 1, 2, 1, 2, 2};
    for (int r = 0; r < level.rows; ++r)
        for (int c = 0; c < level.cols; ++c) {
            const std::size_t n = static_cast<std::size_t>(r) * level.cols + c;
            for (int e = 0; e < 6; ++e)
                exact.add(3 * n + entry_row[e], 3 * n + entry_col[e], level.diagonal[6 * n + e]);
            for (int slot = 0; slot < 4; ++slot) {
                const int r2 = r + forward_rows[slot], c2 = c + forward_cols[slot];
                if (r2 >= level.rows || c2 < 0 || c2 >= level.cols) continue;
                const std::size_t m = static_cast<std::size_t>(r2) * level.cols + c2;
                const double* block = &level.neighbours[(n * 4 + slot) * 6];
                for (int e = 0; e < 6; ++e) {
                    exact.add(3 * n + entry_row[e], 3 * m + entry_col[e], block[e]);
                    if (entry_row[e] != entry_col[e])
                        exact.add(3 * n + entry_col[e], 3 * m + entry_row[e], block[e]);
                }
            }
        }
    exact.factor();
}

// correction = D⁻¹ residual at this level, plus the levels below it; on the coarsest level,
// correction = A⁻¹ residual exactly.
void apply_level(std::vector<ImplicitCoarseLevel>& levels, const BandedCholesky& exact,
                 std::size_t index, double weight) {
    ImplicitCoarseLevel& level = levels[index];
    if (index + 1 == levels.size()) {
        level.correction = level.residual;
        exact.solve(level.correction.data());
        return;
    }
    const std::size_t nodes = level.diagonal.size() / 6;
    for (std::size_t n = 0; n < nodes; ++n)
        multiply_symmetric_block(&level.inverse[6 * n], &level.residual[3 * n],
                                 &level.correction[3 * n]);
    add_coarser_corrections(levels, exact, index, weight);
}

// The residual of level index + 1, the sums of level index's over each aggregate.
void restrict_to_coarser(std::vector<ImplicitCoarseLevel>& levels, std::size_t index) {
    const ImplicitCoarseLevel& level = levels[index];
    ImplicitCoarseLevel& coarser = levels[index + 1];
    std::fill(coarser.residual.begin(), coarser.residual.end(), 0.0);
    for (int r = 0; r < level.rows; ++r)
        for (int c = 0; c < level.cols; ++c) {
            const std::size_t n = static_cast<std::size_t>(r) * level.cols + c;
            const std::size_t m = static_cast<std::size_t>(aggregate(r, c, coarser.cols));
            for (int a = 0; a < 3; ++a) coarser.residual[3 * m + a] += level.residual[3 * n + a];
        }
}

void add_coarser_corrections(std::vector<ImplicitCoarseLevel>& levels, const BandedCholesky& exact,
                             std::size_t index, double weight) {
    if (index + 1 == levels.size()) return;
    ImplicitCoarseLevel& level = levels[index];
    const ImplicitCoarseLevel& coarser = levels[index + 1];
    restrict_to_coarser(levels, index);
    apply_level(levels, exact, index + 1, weight);
    for (int r = 0; r < level.rows; ++r)
        for (int c = 0; c < level.cols; ++c) {
            const std::size_t n = static_cast<std::size_t>(r) * level.cols + c;
            const std::size_t m = static_cast<std::size_t>(aggregate(r, c, coarser.cols));
            for (int a = 0; a < 3; ++a)
                level.correction[3 * n + a] += weight * coarser.correction[3 * m + a];
        }
}

}  // namespace

void ImplicitMultilevel::build(const implicit_kernel::Job& job, WorkerPool* pool) {
    // Down to a level of at most coarsest_side nodes a side, solved exactly.
    std::size_t count = 0;
    for (int rows = job.rows, cols = job.cols; rows > coarsest_side || cols > coarsest_side;
         rows = (rows + 1) / 2, cols = (cols + 1) / 2)
        ++count;
    levels.resize(count);
    if (count == 0) return;
    build_from_fine(levels[0], job, pool);
    for (std::size_t l = 1; l < count; ++l) build_from_coarse(levels[l], levels[l - 1]);
    factor_exactly(levels.back(), exact);
}

void ImplicitMultilevel::attach(implicit_kernel::Job& job) {
    if (levels.empty()) return detach(job);
    ImplicitCoarseLevel& first = levels[0];
    job.coarse_cols = first.cols;
    job.coarse_residual = first.residual.data();
    job.coarse_correction = first.correction.data();
    job.coarse_inverse = first.inverse.data();
}

double ImplicitMultilevel::apply(const implicit_kernel::Job& job, bool restricted,
                                 WorkerPool* pool) {
    if (levels.empty()) return 0.0;
    ImplicitCoarseLevel& first = levels[0];
    // Pass 1, by rows of the first coarse level: its residual, the sum of its 2x2 fine
    // residuals in a fixed order (pinned particles' are zero), and its own D⁻¹ correction;
    // unless the update pass has done it on the way (implicit_grid_kernel.h).
    if (!restricted)
        over_rows(first.rows, job.rows * job.cols, pool, [&](int begin, int end) {
            for (int row = begin; row < end; ++row)
                for (int col = 0; col < first.cols; ++col) {
                    const std::size_t n = static_cast<std::size_t>(row) * first.cols + col;
                    double sum[3] = {0.0, 0.0, 0.0};
                    for (int r = 2 * row; r < std::min(2 * row + 2, job.rows); ++r)
                        for (int c = 2 * col; c < std::min(2 * col + 2, job.cols); ++c) {
                            const std::size_t i =
                                job.pad + static_cast<std::size_t>(r) * job.cols + c;
                            sum[0] += static_cast<double>(job.residual.x[i]);
                            sum[1] += static_cast<double>(job.residual.y[i]);
                            sum[2] += static_cast<double>(job.residual.z[i]);
                        }
                    for (int a = 0; a < 3; ++a) first.residual[3 * n + a] = sum[a];
                    multiply_symmetric_block(&first.inverse[6 * n], sum, &first.correction[3 * n]);
                }
        });
    // The second level and the coarser ones are small (a quarter of the first and less): one
    // thread. The second's correction (its own and the coarser levels') is prolonged into
    // the first's in pass 2, split between the threads.
    if (levels.size() == 1) {  // the first level is the coarsest: exact, not D⁻¹
        first.correction = first.residual;
        exact.solve(first.correction.data());
    } else {
        restrict_to_coarser(levels, 0);
        apply_level(levels, exact, 1, weight);
    }
    // Pass 2, by rows of the first level: its correction plus the second's, r · P x_c =
    // (Pᵀ r) · x_c per row of nodes (summed in row order below), the correction spread along
    // the row's fine columns in single precision, then z += P x_c on the free particles of
    // the row's two fine rows.
    const auto cols = static_cast<std::size_t>(job.cols);
    spread.resize(3 * static_cast<std::size_t>(first.rows) * cols);
    added_by_row.resize(static_cast<std::size_t>(first.rows));
    over_rows(first.rows, job.rows * job.cols, pool, [&](int begin, int end) {
        for (int row = begin; row < end; ++row) {
            const std::size_t nodes = static_cast<std::size_t>(row) * first.cols;
            if (levels.size() > 1) {
                const ImplicitCoarseLevel& second = levels[1];
                for (int col = 0; col < first.cols; ++col) {
                    const std::size_t n = nodes + static_cast<std::size_t>(col);
                    const auto m = static_cast<std::size_t>(aggregate(row, col, second.cols));
                    for (int a = 0; a < 3; ++a)
                        first.correction[3 * n + a] += weight * second.correction[3 * m + a];
                }
            }
            double added_here = 0.0;
            for (std::size_t n = 3 * nodes; n < 3 * (nodes + first.cols); ++n)
                added_here += weight * first.residual[n] * first.correction[n];
            added_by_row[static_cast<std::size_t>(row)] = added_here;
            float* x = &spread[3 * static_cast<std::size_t>(row) * cols];
            for (std::size_t c = 0; c < cols; ++c) {
                const double* correction = &first.correction[3 * (nodes + c / 2)];
                x[c] = static_cast<float>(weight * correction[0]);
                x[cols + c] = static_cast<float>(weight * correction[1]);
                x[2 * cols + c] = static_cast<float>(weight * correction[2]);
            }
            for (int r = 2 * row; r < std::min(2 * row + 2, job.rows); ++r) {
                const std::size_t base = job.pad + static_cast<std::size_t>(r) * cols;
                add_masked(job.preconditioned.x + base, job.free + base, x, job.cols);
                add_masked(job.preconditioned.y + base, job.free + base, x + cols, job.cols);
                add_masked(job.preconditioned.z + base, job.free + base, x + 2 * cols, job.cols);
                // z stays in the filtered space: S P x_c at particles held on a surface.
                // (r · S P x_c = r · P x_c, r being filtered: the sum above holds.)
                if (job.has_contacts)
                    filter_contacts_row(job.contact_normal.x + base, job.contact_normal.y + base,
                                        job.contact_normal.z + base, job.preconditioned.x + base,
                                        job.preconditioned.y + base, job.preconditioned.z + base,
                                        job.cols);
            }
        }
    });
    double added = 0.0;
    for (double value : added_by_row) added += value;
    return added;
}

}  // namespace weft
