#include "sim/integrators/implicit/implicit_k_cycle.h"

#include <algorithm>

#include "sim/integrators/implicit/implicit_multilevel.h"

namespace weft {
namespace {

// A level's passes are split between the threads from this many nodes; below it a hand-off
// costs about what the pass does.
constexpr int threaded_nodes = 1024;

// Runs pass(row) for every row of a level of `nodes` nodes, in slices of rows.
template <class Pass>
void over_level_rows(int rows, int nodes, WorkerPool* pool, Pass&& pass) {
    parallel_for_if(pool, nodes >= threaded_nodes, static_cast<std::size_t>(rows),
                    [&](std::size_t begin, std::size_t end) {
                        for (std::size_t r = begin; r < end; ++r) pass(static_cast<int>(r));
                    });
}

// A row of the level's product A v, written to three rows of cols floats.
struct ProductRow {
    float* x;
    float* y;
    float* z;
};
void multiply(const KCycleLevel& level, const CoarseField& v, int row, const ProductRow& out) {
    multiply_coarse_row(level.matrix, row, v.row(row - 1), v.row(row), v.row(row + 1), out.x, out.y,
                        out.z);
}

// out's row `row` = (A v) there.
void multiply_into(const KCycleLevel& level, const CoarseField& v, int row, CoarseField& out) {
    multiply(level, v, row, {out.at(0, row), out.at(1, row), out.at(2, row)});
}

// A row's product into a thread's scratch row (3 × cols floats).
ProductRow multiply_row(const KCycleLevel& level, const CoarseField& v, int row) {
    thread_local std::vector<float> scratch;  // grown once: no step allocates
    scratch.resize(3 * static_cast<std::size_t>(level.cols()));
    const ProductRow p{scratch.data(), scratch.data() + level.cols(),
                       scratch.data() + 2 * level.cols()};
    multiply(level, v, row, p);
    return p;
}

// out = scale D⁻¹ (bx, by, bz) over a row, D⁻¹ the level's inverse diagonal blocks.
void inverse_times(const KCycleLevel& level, int row, float scale, const float* __restrict bx,
                   const float* __restrict by, const float* __restrict bz, float* __restrict ox,
                   float* __restrict oy, float* __restrict oz) {
    const std::size_t plane = static_cast<std::size_t>(level.rows()) * level.cols();
    const float* inv = level.inverse.data() + static_cast<std::size_t>(row) * level.cols();
    const float* __restrict xx = inv;
    const float* __restrict yy = inv + plane;
    const float* __restrict zz = inv + 2 * plane;
    const float* __restrict xy = inv + 3 * plane;
    const float* __restrict xz = inv + 4 * plane;
    const float* __restrict yz = inv + 5 * plane;
    for (int c = 0; c < level.cols(); ++c) {
        const float x = bx[c], y = by[c], z = bz[c];
        ox[c] = scale * (xx[c] * x + xy[c] * y + xz[c] * z);
        oy[c] = scale * (xy[c] * x + yy[c] * y + yz[c] * z);
        oz[c] = scale * (xz[c] * x + yz[c] * y + zz[c] * z);
    }
}

void inverse_times(const KCycleLevel& level, int row, float scale, const CoarseField& b,
                   CoarseField& out) {
    inverse_times(level, row, scale, b.at(0, row), b.at(1, row), b.at(2, row), out.at(0, row),
                  out.at(1, row), out.at(2, row));
}

// u · v over a row, in double, in column order.
double row_dot(const CoarseField& u, const CoarseField& v, int row, int cols) {
    double sum = 0.0;
    for (int a = 0; a < 3; ++a) {
        const float* p = u.at(a, row);
        const float* q = v.at(a, row);
        for (int c = 0; c < cols; ++c) sum += static_cast<double>(p[c]) * static_cast<double>(q[c]);
    }
    return sum;
}

}  // namespace

void CoarseField::size_for(int rows, std::size_t level_row_floats) {
    const std::size_t new_plane = (static_cast<std::size_t>(rows) + 2) * level_row_floats;
    if (row_floats == level_row_floats && plane == new_plane) return;  // keeps its zeros
    row_floats = level_row_floats;
    plane = new_plane;
    floats.assign(3 * plane, 0.0f);
}

bool ImplicitKCycle::worth(const std::vector<ImplicitCoarseLevel>& levels, int min_nodes) {
    return min_nodes >= 0 && levels.size() >= 3 && levels[1].rows * levels[1].cols >= min_nodes;
}

void ImplicitKCycle::build(const std::vector<ImplicitCoarseLevel>& levels, SimdLevel simd) {
    levels_.resize(levels.size() - 2);
    for (std::size_t k = 0; k < levels_.size(); ++k) {
        const ImplicitCoarseLevel& from = levels[k + 1];
        KCycleLevel& level = levels_[k];
        level.matrix.kernel_build = simd;
        level.matrix.size_for(from.rows, from.cols);
        const auto plane = static_cast<std::size_t>(from.rows) * from.cols;
        level.inverse.resize(6 * plane);
        for (int r = 0; r < from.rows; ++r)
            for (int c = 0; c < from.cols; ++c) {
                const std::size_t n = static_cast<std::size_t>(r) * from.cols + c;
                for (int e = 0; e < 6; ++e) {
                    const_cast<float*>(level.matrix.entry(0, e, r))[c] =
                        static_cast<float>(from.diagonal[6 * n + e]);
                    for (int slot = 0; slot < 4; ++slot)
                        const_cast<float*>(level.matrix.entry(slot + 1, e, r))[c] =
                            static_cast<float>(from.neighbours[24 * n + 6 * slot + e]);
                    level.inverse[e * plane + n] = static_cast<float>(from.inverse[6 * n + e]);
                }
            }
        level.rhs.size_for(from.rows, level.matrix.row_floats);
        level.iterate.size_for(from.rows, level.matrix.row_floats);
        level.result.size_for(from.rows, level.matrix.row_floats);
    }
    const KCycleLevel& top = levels_[0];
    for (CoarseField* field :
         {&first_result, &second_result, &first_product, &second_product, &second_rhs})
        field->size_for(top.rows(), top.matrix.row_floats);
    row_sums.resize(3 * static_cast<std::size_t>(top.rows()));
    exact_values.resize(levels.back().residual.size());
}

// out ≈ A_k⁻¹ rhs by one symmetric V-cycle on level k: x = ω D⁻¹ b (already in the level's
// iterate when `start_done`), x += P (the coarser level's V-cycle, or its exact solve, on the
// restricted b - A x), out = x + ω D⁻¹ (b - A x).
void ImplicitKCycle::v_cycle(std::size_t k, const CoarseField& rhs, CoarseField& out,
                             bool start_done, const BandedCholesky& exact, WorkerPool* pool) {
    KCycleLevel& level = levels_[k];
    const int nodes = level.rows() * level.cols();
    if (!start_done)
        over_level_rows(level.rows(), nodes, pool,
                        [&](int row) { inverse_times(level, row, omega, rhs, level.iterate); });

    // The coarser level's right-hand side: b - A x summed over each aggregate, by rows of the
    // coarser level, its fine rows and columns in order.
    const bool coarsest_below = k + 1 == levels_.size();
    const int coarse_rows = (level.rows() + 1) / 2, coarse_cols = (level.cols() + 1) / 2;
    over_level_rows(coarse_rows, nodes, pool, [&](int coarse_row) {
        float* into[3] = {};
        if (!coarsest_below)
            for (int a = 0; a < 3; ++a) {
                into[a] = levels_[k + 1].rhs.at(a, coarse_row);
                std::fill(into[a], into[a] + coarse_cols, 0.0f);
            }
        double* exact_row =
            exact_values.data() + 3 * static_cast<std::size_t>(coarse_row) * coarse_cols;
        if (coarsest_below) std::fill(exact_row, exact_row + 3 * coarse_cols, 0.0);
        for (int row = 2 * coarse_row; row < std::min(2 * coarse_row + 2, level.rows()); ++row) {
            const ProductRow p = multiply_row(level, level.iterate, row);
            const float* product[3] = {p.x, p.y, p.z};
            for (int a = 0; a < 3; ++a) {
                const float* b = rhs.at(a, row);
                if (coarsest_below)
                    for (int c = 0; c < level.cols(); ++c)
                        exact_row[3 * (c / 2) + a] += static_cast<double>(b[c] - product[a][c]);
                else
                    for (int c = 0; c < level.cols(); ++c) into[a][c / 2] += b[c] - product[a][c];
            }
        }
    });

    // The coarser level's correction, prolonged into x.
    if (coarsest_below)
        exact.solve(exact_values.data());
    else
        v_cycle(k + 1, levels_[k + 1].rhs, levels_[k + 1].result, false, exact, pool);
    over_level_rows(level.rows(), nodes, pool, [&](int row) {
        for (int a = 0; a < 3; ++a) {
            float* x = level.iterate.at(a, row);
            if (coarsest_below) {
                const double* below =
                    exact_values.data() + 3 * static_cast<std::size_t>(row / 2) * coarse_cols;
                for (int c = 0; c < level.cols(); ++c)
                    x[c] += static_cast<float>(below[3 * (c / 2) + a]);
            } else {
                const float* below = levels_[k + 1].result.at(a, row / 2);
                for (int c = 0; c < level.cols(); ++c) x[c] += below[c / 2];
            }
        }
    });

    // out = x + ω D⁻¹ (b - A x).
    over_level_rows(level.rows(), nodes, pool, [&](int row) {
        const ProductRow p = multiply_row(level, level.iterate, row);
        float* product[3] = {p.x, p.y, p.z};
        for (int a = 0; a < 3; ++a) {
            const float* b = rhs.at(a, row);
            for (int c = 0; c < level.cols(); ++c) product[a][c] = b[c] - product[a][c];
        }
        inverse_times(level, row, omega, p.x, p.y, p.z, out.at(0, row), out.at(1, row),
                      out.at(2, row));
        for (int a = 0; a < 3; ++a) {
            float* o = out.at(a, row);
            const float* x = level.iterate.at(a, row);
            for (int c = 0; c < level.cols(); ++c) o[c] += x[c];
        }
    });
}

void ImplicitKCycle::apply(std::vector<ImplicitCoarseLevel>& levels, const BandedCholesky& exact,
                           double smoothing, WorkerPool* pool) {
    omega = static_cast<float>(smoothing);
    ImplicitCoarseLevel& second = levels[1];
    KCycleLevel& top = levels_[0];
    const int rows = top.rows(), cols = top.cols(), nodes = rows * cols;
    auto sum_of = [&](int which) {
        double sum = 0.0;
        for (int r = 0; r < rows; ++r) sum += row_sums[3 * static_cast<std::size_t>(r) + which];
        return sum;
    };

    // b in float, and the first V-cycle's start x = ω D⁻¹ b on the way.
    over_level_rows(rows, nodes, pool, [&](int row) {
        const double* from = &second.residual[3 * static_cast<std::size_t>(row) * cols];
        for (int a = 0; a < 3; ++a) {
            float* b = top.rhs.at(a, row);
            for (int c = 0; c < cols; ++c) b[c] = static_cast<float>(from[3 * c + a]);
        }
        inverse_times(top, row, omega, top.rhs, top.iterate);
    });
    // c1 = B b, v1 = A c1; ρ1 = c1 · v1, α1 = c1 · b.
    v_cycle(0, top.rhs, first_result, true, exact, pool);
    over_level_rows(rows, nodes, pool, [&](int row) {
        multiply_into(top, first_result, row, first_product);
        double* sums = &row_sums[3 * static_cast<std::size_t>(row)];
        sums[0] = row_dot(first_result, first_product, row, cols);
        sums[1] = row_dot(first_result, top.rhs, row, cols);
    });
    const double rho1 = sum_of(0), alpha1 = sum_of(1);
    double first_weight = 0.0, second_weight = 0.0;
    if (rho1 > 0.0) {
        // The residual after the first step, r~ = b - (α1/ρ1) v1; c2 = B r~, v2 = A c2.
        first_weight = alpha1 / rho1;
        const auto step = static_cast<float>(first_weight);
        over_level_rows(rows, nodes, pool, [&](int row) {
            for (int a = 0; a < 3; ++a) {
                const float* b = top.rhs.at(a, row);
                const float* v = first_product.at(a, row);
                float* r = second_rhs.at(a, row);
                for (int c = 0; c < cols; ++c) r[c] = b[c] - step * v[c];
            }
            inverse_times(top, row, omega, second_rhs, top.iterate);
        });
        v_cycle(0, second_rhs, second_result, true, exact, pool);
        over_level_rows(rows, nodes, pool, [&](int row) {
            multiply_into(top, second_result, row, second_product);
            double* sums = &row_sums[3 * static_cast<std::size_t>(row)];
            sums[0] = row_dot(second_result, first_product, row, cols);
            sums[1] = row_dot(second_result, second_product, row, cols);
            sums[2] = row_dot(second_result, second_rhs, row, cols);
        });
        // The second step, A-orthogonal to the first: c2 - (γ/ρ1) c1 with γ = c2 · v1.
        const double gamma = sum_of(0), c2_v2 = sum_of(1), alpha2 = sum_of(2);
        const double curvature = c2_v2 - gamma * gamma / rho1;
        if (curvature > 0.0) {
            second_weight = alpha2 / curvature;
            first_weight -= gamma * second_weight / rho1;
        }
    } else {
        first_weight = 1.0;  // b = 0 (or not positive definite): c1 as it stands
    }
    // The level's correction, a1 c1 + a2 c2, in double for the first level's pass.
    over_level_rows(rows, nodes, pool, [&](int row) {
        double* into = &second.correction[3 * static_cast<std::size_t>(row) * cols];
        for (int a = 0; a < 3; ++a) {
            const float* c1 = first_result.at(a, row);
            const float* c2 = second_result.at(a, row);
            for (int c = 0; c < cols; ++c)
                into[3 * c + a] = first_weight * static_cast<double>(c1[c]) +
                                  second_weight * static_cast<double>(c2[c]);
        }
    });
}

}  // namespace weft
