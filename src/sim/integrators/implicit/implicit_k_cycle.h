// The second coarse level of the implicit solve's preconditioner as a K-cycle (Notay and
// Vassilevski, "Recursive Krylov-based multigrid cycles", 2008), on large sheets.
//
// The coarse levels aggregate 2x2 nodes into one, piecewise constant. Such aggregates
// approximate the smooth modes poorly, and each level loses a little: with a V-cycle on the
// first coarse level and block Jacobi below, conjugate gradient takes more iterations the
// larger the sheet (docs/performance.md has the counts). The K-cycle's remedy is to solve the
// second level better than one V-cycle does: two steps of flexible conjugate gradient on that
// level, preconditioned by a symmetric V-cycle there (whose own coarse solve is a V-cycle on the
// next level, and so on down to the exact coarsest). The two steps choose the best
// combination of the two V-cycle corrections in the level's energy norm, which undoes the
// aggregates' poor scaling without a tuned weight. The preconditioner then depends on the
// residual, so the outer solve uses flexible conjugate gradient (β by Polak and Ribière).
//
// Everything here runs in single precision on the levels' matrices in float rows
// (implicit_coarse_rows.h), by rows and split between threads where a level is large, with
// every sum in double and per row, so the result is the same bits for any thread count.
//
// It pays only where the second level is large: it adds six products on it an iteration
// (and two a V-cycle on each level below), which a small level's few nodes do not repay
// (ImplicitCycleShape::k_cycle_nodes).
#pragma once

#include <cstddef>
#include <vector>

#include "parallel/worker_pool.h"
#include "sim/grid/kernel_build.h"
#include "sim/integrators/implicit/banded_cholesky.h"
#include "sim/integrators/implicit/implicit_coarse_rows.h"

namespace weft {

struct ImplicitCoarseLevel;

// A vector on a coarse level as float rows: three planes (x, y, z) of rows + 2 rows of
// row_floats, zeros around (a row above and below, a column either side), which is how
// multiply_coarse_row reads it. Passes write only the level's own nodes.
struct CoarseField {
    std::vector<float> floats;
    std::size_t row_floats = 0;
    std::size_t plane = 0;

    void size_for(int rows, std::size_t level_row_floats);
    // Component a (0 x, 1 y, 2 z) of row `row` (-1 .. rows), from column 0.
    float* at(int a, int row) {
        return floats.data() + static_cast<std::size_t>(a) * plane +
               static_cast<std::size_t>(row + 1) * row_floats + 1;
    }
    const float* at(int a, int row) const {
        return floats.data() + static_cast<std::size_t>(a) * plane +
               static_cast<std::size_t>(row + 1) * row_floats + 1;
    }
    CoarseVectorRow row(int r) const { return {at(0, r), at(1, r), at(2, r)}; }
};

// One coarse level below the first, in float: its matrix, its inverse diagonal blocks and
// the V-cycle's vectors there.
struct KCycleLevel {
    CoarseRows matrix;
    std::vector<float> inverse;  // 6 planes (xx yy zz xy xz yz) of rows × cols; 0 where pinned
    CoarseField rhs;             // b: the residual restricted from the level above
    CoarseField iterate;         // the V-cycle's x
    CoarseField result;          // what the V-cycle returns

    int rows() const { return matrix.rows; }
    int cols() const { return matrix.cols; }
};

class ImplicitKCycle {
  public:
    // The second level's nodes from which a sheet gets the K-cycle by default: a 256²
    // sheet's (ImplicitCycleShape::k_cycle_nodes).
    static constexpr int default_min_nodes = 4096;

    // Whether `levels` (the multilevel's, finest coarse level first) get the K-cycle: a
    // second level of at least `min_nodes` that is not the coarsest (solved exactly).
    static bool worth(const std::vector<ImplicitCoarseLevel>& levels, int min_nodes);

    // The float copies of levels 1 .. count - 2 (the coarsest stays exact, in double).
    void build(const std::vector<ImplicitCoarseLevel>& levels, SimdLevel simd);
    // levels[1].correction ≈ A_1⁻¹ levels[1].residual by the K-cycle; `smoothing` is ω of
    // the V-cycles' block-Jacobi steps.
    void apply(std::vector<ImplicitCoarseLevel>& levels, const BandedCholesky& exact,
               double smoothing, WorkerPool* pool);

  private:
    void v_cycle(std::size_t k, const CoarseField& rhs, CoarseField& out, bool start_done,
                 const BandedCholesky& exact, WorkerPool* pool);

    std::vector<KCycleLevel> levels_;         // the multilevel's levels 1 .. count - 2
    std::vector<double> exact_values;         // the coarsest level's right-hand side, then solution
    CoarseField first_result, second_result;  // c1, c2: the two V-cycles' corrections
    CoarseField first_product, second_product;  // A c1, A c2
    CoarseField second_rhs;                     // b - (c1·b / c1·A c1) A c1
    std::vector<double> row_sums;               // 3 per row of the K-cycle's level
    float omega = 0.8f;
};

}  // namespace weft
