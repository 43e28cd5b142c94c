#include "sim/integrators/implicit/implicit_multilevel.h"

#include <algorithm>
#include <atomic>
#include <cstdint>

namespace weft {
namespace {

#include "sim/collision/contact_filter.inl"
#include "sim/integrators/implicit/symmetric_block.inl"

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

// into[n] += scale from[2 n] over n nodes: a fine row's terms of one column parity into the
// row of coarse nodes they belong to.
void add_every_other(double* __restrict into, const float* __restrict from, double scale,
                     int nodes) {
    for (int n = 0; n < nodes; ++n) into[n] += scale * static_cast<double>(from[2 * n]);
}

// The first coarse level, from the fine stencil: A_c = Pᵀ F A F P over the free particles.
// A spring from fine (r, c) to (r + dr, c + dc) joins the aggregates (r/2, c/2) and
// ((r + dr)/2, (c + dc)/2): which of a node's slots it lands in depends only on the parity of
// r and c, so each direction has a table of four. Springs inside an aggregate cancel against
// their share of the fine diagonal blocks (twice -B); the others go to the forward slot, or,
// pointing back along the row, to the left node's (0, 1) slot. Coarse rows are built whole by
// one thread, fine rows and columns in order, so every sum is the same for any split.
// With `rows`, each finished row is also stored there in float (the V-cycle's products).
void build_from_fine(ImplicitCoarseLevel& level, const implicit_kernel::Job& job,
                     CoarseRows* float_rows, WorkerPool* pool) {
    size_level(level, (job.rows + 1) / 2, (job.cols + 1) / 2);
    if (float_rows) float_rows->size_for(level.rows, level.cols);
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
    const auto coarse_cols = static_cast<std::size_t>(level.cols);
    // A coarse row's blocks are summed in rows of doubles, one per block (own, then the
    // forward slots) and entry, with a column in front that takes the springs of slot -1 off
    // the grid's left edge: each sum then runs over a row's columns with a fixed stride, and
    // every node's terms still come in the order of fine row, direction and column.
    const std::size_t sum_row = coarse_cols + 1;
    over_rows(level.rows, job.rows * job.cols, pool, [&](int begin, int end) {
        thread_local std::vector<float> couplings;  // grown once: no step allocates
        thread_local std::vector<double> sums;
        couplings.resize(6 * static_cast<std::size_t>(cols));
        sums.resize(CoarseRows::blocks * 6 * sum_row);
        auto sum_of = [&](int block, int e) {
            return sums.data() + (static_cast<std::size_t>(block) * 6 + e) * sum_row + 1;
        };
        for (int row = begin; row < end; ++row) {
            std::fill(sums.begin(), sums.end(), 0.0);
            for (int r = 2 * row; r < std::min(2 * row + 2, job.rows); ++r) {
                const std::size_t base = job.pad + static_cast<std::size_t>(r) * cols;
                for (int e = 0; e < 6; ++e) {
                    add_every_other(sum_of(0, e), job.diagonal[e] + base, 1.0, (cols + 1) / 2);
                    add_every_other(sum_of(0, e), job.diagonal[e] + base + 1, 1.0, cols / 2);
                }
                for (int k = 0; k < job.direction_count; ++k) {
                    fine_couplings(job, job.directions[k], r, couplings.data());
                    for (int parity = 0; parity < 2; ++parity) {
                        const int slot = slots[k][r % 2][parity];
                        // Slot -2: inside the aggregate, twice into its own block; -1: the
                        // left node's (0, 1) coupling; else the node's forward slot.
                        const int block = slot == -2 ? 0 : slot == -1 ? 1 : slot + 1;
                        const int shift = slot == -1 ? -1 : 0;
                        const double scale = slot == -2 ? 2.0 : 1.0;
                        const int nodes = (cols - parity + 1) / 2;
                        for (int e = 0; e < 6; ++e)
                            add_every_other(
                                sum_of(block, e) + shift,
                                couplings.data() + static_cast<std::size_t>(e) * cols + parity,
                                scale, nodes);
                    }
                }
            }
            const std::size_t first_node = static_cast<std::size_t>(row) * coarse_cols;
            for (std::size_t n = 0; n < coarse_cols; ++n) {
                double* diagonal = &level.diagonal[6 * (first_node + n)];
                double* neighbours = &level.neighbours[24 * (first_node + n)];
                for (int e = 0; e < 6; ++e) {
                    diagonal[e] = sum_of(0, e)[n];
                    for (int slot = 0; slot < 4; ++slot)
                        neighbours[6 * slot + e] = sum_of(slot + 1, e)[n];
                }
                invert_symmetric_block(diagonal, &level.inverse[6 * (first_node + n)]);
            }
            if (float_rows)
                for (int block = 0; block < CoarseRows::blocks; ++block)
                    for (int e = 0; e < 6; ++e) {
                        float* out = const_cast<float*>(float_rows->entry(block, e, row));
                        const double* from = sum_of(block, e);
                        for (std::size_t n = 0; n < coarse_cols; ++n)
                            out[n] = static_cast<float>(from[n]);
                    }
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

// The V-cycle's vectors on the rows of the first level around a pair of rows (pair 2Q, 2Q+1
// needs 2Q - 1 .. 2Q + 2), in float with the zero end columns CoarseRows' products read.
// Each thread keeps its own; rows off the level are zeros. A thread's pairs come in order, so
// the two rows the next pair shares with this one are kept, not filled again.
struct SmoothingRows {
    std::vector<float> floats;  // 4 slots × 3 components × row_floats
    std::size_t row_floats = 0;
    int first_row = 0;
    int slot_of_row[4] = {0, 1, 2, 3};  // rows first_row .. first_row + 3 live in these slots
    std::uint64_t pass = 0;             // which pass filled them (a new pass starts over)

    // Fills the four rows around pair `pair` by row_value(row, out_x, out_y, out_z), which
    // writes a row's cols floats (rows off the level stay zero).
    template <class RowValue>
    void fill(const CoarseRows& matrix, int pair, std::uint64_t pass_id, RowValue&& row_value) {
        const int new_first = 2 * pair - 1;
        int kept = 0;
        if (pass == pass_id && row_floats == matrix.row_floats && new_first == first_row + 2) {
            std::swap(slot_of_row[0], slot_of_row[2]);
            std::swap(slot_of_row[1], slot_of_row[3]);
            kept = 2;
        } else {
            row_floats = matrix.row_floats;
            floats.assign(12 * row_floats, 0.0f);  // grown once: no step allocates
        }
        pass = pass_id;
        first_row = new_first;
        for (int k = kept; k < 4; ++k) {
            float* base = slot(k);
            const int row = first_row + k;
            if (row < 0 || row >= matrix.rows)
                std::fill(base, base + 3 * row_floats, 0.0f);
            else
                row_value(row, base + 1, base + row_floats + 1, base + 2 * row_floats + 1);
        }
    }
    float* slot(int k) {
        return &floats[3 * static_cast<std::size_t>(slot_of_row[k]) * row_floats];
    }
    CoarseVectorRow row(int level_row) const {
        const auto k = static_cast<std::size_t>(slot_of_row[level_row - first_row]);
        const float* base = &floats[3 * k * row_floats + 1];
        return {base, base + row_floats, base + 2 * row_floats};
    }
};

thread_local SmoothingRows smoothing_rows;

// Every pass that fills smoothing rows, of any solver on any thread, has its own number, so
// no thread mistakes rows it kept from another pass (or another solver's) for this one's.
std::atomic<std::uint64_t> smoothing_passes{0};
std::uint64_t next_smoothing_pass() {
    return smoothing_passes.fetch_add(1, std::memory_order_relaxed) + 1;
}

// The V-cycle's first smoothing and its restriction, by rows of the second level: with
// x = ω D_1⁻¹ b (the correction pass 1 or the update passes left), the second level's
// residual is the sum over each aggregate of b - A_1 x, in a fixed order.
void restrict_smoothed_residual(std::vector<ImplicitCoarseLevel>& levels, const CoarseRows& matrix,
                                double smoothing, int fine_particles, WorkerPool* pool) {
    const ImplicitCoarseLevel& first = levels[0];
    ImplicitCoarseLevel& second = levels[1];
    const std::uint64_t pass_id = next_smoothing_pass();
    over_rows(second.rows, fine_particles, pool, [&](int begin, int end) {
        thread_local std::vector<float> product;  // grown once
        product.resize(3 * static_cast<std::size_t>(first.cols));
        float* px = product.data();
        float* py = px + first.cols;
        float* pz = py + first.cols;
        for (int pair = begin; pair < end; ++pair) {
            smoothing_rows.fill(matrix, pair, pass_id, [&](int row, float* x, float* y, float* z) {
                const double* c = &first.correction[3 * static_cast<std::size_t>(row) * first.cols];
                for (int col = 0; col < first.cols; ++col) {
                    x[col] = static_cast<float>(smoothing * c[3 * col]);
                    y[col] = static_cast<float>(smoothing * c[3 * col + 1]);
                    z[col] = static_cast<float>(smoothing * c[3 * col + 2]);
                }
            });
            double* restricted = &second.residual[3 * static_cast<std::size_t>(pair) * second.cols];
            std::fill(restricted, restricted + 3 * static_cast<std::size_t>(second.cols), 0.0);
            for (int row = 2 * pair; row < std::min(2 * pair + 2, first.rows); ++row) {
                multiply_coarse_row(matrix, row, smoothing_rows.row(row - 1),
                                    smoothing_rows.row(row), smoothing_rows.row(row + 1), px, py,
                                    pz);
                const double* b = &first.residual[3 * static_cast<std::size_t>(row) * first.cols];
                for (int c = 0; c < first.cols; ++c) {
                    double* into = restricted + 3 * static_cast<std::size_t>(c / 2);
                    into[0] += b[3 * c] - static_cast<double>(px[c]);
                    into[1] += b[3 * c + 1] - static_cast<double>(py[c]);
                    into[2] += b[3 * c + 2] - static_cast<double>(pz[c]);
                }
            }
        }
    });
}

// The V-cycle's second smoothing on first-level row `row` of the pair smoothing_rows holds
// (y = ω D_1⁻¹ b + P x_2): corrections = y + ω D_1⁻¹ (b - A_1 y), 3 per node.
void finish_smoothing(const ImplicitCoarseLevel& first, const CoarseRows& matrix, double smoothing,
                      int row, double* corrections) {
    thread_local std::vector<float> product;  // grown once
    product.resize(3 * static_cast<std::size_t>(first.cols));
    float* px = product.data();
    float* py = px + first.cols;
    float* pz = py + first.cols;
    const CoarseVectorRow y = smoothing_rows.row(row);
    multiply_coarse_row(matrix, row, smoothing_rows.row(row - 1), y, smoothing_rows.row(row + 1),
                        px, py, pz);
    const std::size_t nodes = static_cast<std::size_t>(row) * first.cols;
    for (int c = 0; c < first.cols; ++c) {
        const std::size_t n = nodes + static_cast<std::size_t>(c);
        const double left[3] = {first.residual[3 * n] - static_cast<double>(px[c]),
                                first.residual[3 * n + 1] - static_cast<double>(py[c]),
                                first.residual[3 * n + 2] - static_cast<double>(pz[c])};
        double step[3];
        multiply_symmetric_block(&first.inverse[6 * n], left, step);
        double* out = corrections + 3 * static_cast<std::size_t>(c);
        out[0] = static_cast<double>(y.x[c]) + smoothing * step[0];
        out[1] = static_cast<double>(y.y[c]) + smoothing * step[1];
        out[2] = static_cast<double>(y.z[c]) + smoothing * step[2];
    }
}
}  // namespace

void ImplicitMultilevel::build(const implicit_kernel::Job& job, const ImplicitCycleShape& cycle,
                               WorkerPool* pool, SimdLevel level) {
    shape = cycle;
    first_rows.kernel_build = level;
    // Down to a level of at most coarsest_side nodes a side, solved exactly.
    std::size_t count = 0;
    for (int rows = job.rows, cols = job.cols; rows > coarsest_side || cols > coarsest_side;
         rows = (rows + 1) / 2, cols = (cols + 1) / 2)
        ++count;
    levels.resize(count);
    if (count == 0) return;
    build_from_fine(levels[0], job, count > 1 && cycle.smoothing > 0.0 ? &first_rows : nullptr,
                    pool);
    for (std::size_t l = 1; l < count; ++l) build_from_coarse(levels[l], levels[l - 1]);
    factor_exactly(levels.back(), exact);
    uses_k_cycle = cycle.smoothing > 0.0 && ImplicitKCycle::worth(levels, cycle.k_cycle_nodes);
    if (uses_k_cycle) k_cycle.build(levels, level);
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
    const double smoothing = shape.smoothing, weight = shape.weight;
    ImplicitCoarseLevel& first = levels[0];
    const int fine_particles = job.rows * job.cols;
    // Pass 1, by rows of the first coarse level: its residual, the sum of its 2x2 fine
    // residuals in a fixed order (pinned particles' are zero), and its own D⁻¹ correction;
    // unless the update pass has done it on the way (implicit_grid_kernel.h).
    if (!restricted)
        over_rows(first.rows, fine_particles, pool, [&](int begin, int end) {
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
    // The V-cycle's first smoothing runs on the threads, by pairs of first-level rows. The
    // second level and the coarser ones are small (a quarter of the first and less): one
    // thread. The second's correction (its own and the coarser levels') is prolonged into
    // the first's in pass 2, split between the threads.
    const bool v_cycle = smoothing > 0.0 && levels.size() > 1;
    if (levels.size() == 1) {  // the first level is the coarsest: exact, not D⁻¹
        first.correction = first.residual;
        exact.solve(first.correction.data());
    } else {
        if (v_cycle)
            restrict_smoothed_residual(levels, first_rows, smoothing, fine_particles, pool);
        else
            restrict_to_coarser(levels, 0);
        if (uses_k_cycle)
            k_cycle.apply(levels, exact, smoothing, pool);
        else
            apply_level(levels, exact, 1, weight);
    }
    // Pass 2, by pairs of rows of the first level: its correction (the V-cycle's second
    // smoothing, or D_1⁻¹ r_1 plus the second level's), r · P x_c = (Pᵀ r) · x_c per row of
    // nodes (summed in row order below), the correction spread along the row's fine columns
    // in single precision, then z += P x_c on the free particles of the row's two fine rows.
    const auto cols = static_cast<std::size_t>(job.cols);
    spread.resize(3 * static_cast<std::size_t>(first.rows) * cols);
    added_by_row.resize(static_cast<std::size_t>(first.rows));
    const int pairs = (first.rows + 1) / 2;
    const std::uint64_t finish_pass = v_cycle ? next_smoothing_pass() : 0;
    over_rows(pairs, fine_particles, pool, [&](int begin, int end) {
        thread_local std::vector<double> corrections;  // grown once: no step allocates
        corrections.resize(3 * static_cast<std::size_t>(first.cols));
        for (int pair = begin; pair < end; ++pair) {
            if (v_cycle) {
                const ImplicitCoarseLevel& second = levels[1];
                smoothing_rows.fill(
                    first_rows, pair, finish_pass, [&](int row, float* x, float* y, float* z) {
                        const double* c =
                            &first.correction[3 * static_cast<std::size_t>(row) * first.cols];
                        const double* coarse =
                            &second.correction[3 * static_cast<std::size_t>(row / 2) * second.cols];
                        for (int col = 0; col < first.cols; ++col) {
                            const double* below = coarse + 3 * (col / 2);
                            x[col] = static_cast<float>(smoothing * c[3 * col] + below[0]);
                            y[col] = static_cast<float>(smoothing * c[3 * col + 1] + below[1]);
                            z[col] = static_cast<float>(smoothing * c[3 * col + 2] + below[2]);
                        }
                    });
            }
            for (int row = 2 * pair; row < std::min(2 * pair + 2, first.rows); ++row) {
                const std::size_t nodes = static_cast<std::size_t>(row) * first.cols;
                if (v_cycle)
                    finish_smoothing(first, first_rows, smoothing, row, corrections.data());
                else
                    for (int col = 0; col < first.cols; ++col) {
                        const std::size_t n = nodes + static_cast<std::size_t>(col);
                        for (int a = 0; a < 3; ++a) {
                            double value = first.correction[3 * n + a];
                            if (levels.size() > 1)
                                value +=
                                    weight *
                                    levels[1].correction[3 * static_cast<std::size_t>(aggregate(
                                                                 row, col, levels[1].cols)) +
                                                         a];
                            corrections[3 * static_cast<std::size_t>(col) + a] = value;
                        }
                    }
                double added_here = 0.0;
                for (std::size_t k = 0; k < 3 * static_cast<std::size_t>(first.cols); ++k)
                    added_here += weight * first.residual[3 * nodes + k] * corrections[k];
                added_by_row[static_cast<std::size_t>(row)] = added_here;
                // Each node's correction rounded once and written to both its fine columns
                // (the last node of an odd row has one).
                float* x = &spread[3 * static_cast<std::size_t>(row) * cols];
                for (std::size_t c = 0; c < cols; c += 2) {
                    const double* correction = &corrections[3 * (c / 2)];
                    const auto along_x = static_cast<float>(weight * correction[0]);
                    const auto along_y = static_cast<float>(weight * correction[1]);
                    const auto along_z = static_cast<float>(weight * correction[2]);
                    x[c] = along_x;
                    x[cols + c] = along_y;
                    x[2 * cols + c] = along_z;
                    if (c + 1 == cols) break;
                    x[c + 1] = along_x;
                    x[cols + c + 1] = along_y;
                    x[2 * cols + c + 1] = along_z;
                }
                for (int r = 2 * row; r < std::min(2 * row + 2, job.rows); ++r) {
                    const std::size_t base = job.pad + static_cast<std::size_t>(r) * cols;
                    add_masked(job.preconditioned.x + base, job.free + base, x, job.cols);
                    add_masked(job.preconditioned.y + base, job.free + base, x + cols, job.cols);
                    add_masked(job.preconditioned.z + base, job.free + base, x + 2 * cols,
                               job.cols);
                    // z stays in the filtered space: S P x_c at particles held on a surface.
                    // (r · S P x_c = r · P x_c, r being filtered: the sum above holds.)
                    if (job.has_contacts)
                        filter_contacts_row(
                            job.contact_normal.x + base, job.contact_normal.y + base,
                            job.contact_normal.z + base, job.preconditioned.x + base,
                            job.preconditioned.y + base, job.preconditioned.z + base, job.cols);
                }
            }
        }
    });
    double added = 0.0;
    for (double value : added_by_row) added += value;
    return added;
}

}  // namespace weft
