// The coarse levels of the structured implicit solve's preconditioner: an additive
// multilevel (BPX-like) correction over 2x2 aggregates of particles.
//
// Block Jacobi alone sees one particle at a time, so conjugate gradient must carry
// information across the sheet one spring per iteration: the long, smooth stretch modes of
// a large stiff sheet take hundreds of iterations. Each coarse level here lumps 2x2 nodes of
// the level below into one node (piecewise-constant aggregation) with the Galerkin operator
// A_c = Pᵀ A P, which on a spring network is again a spring network of 3x3 blocks between
// neighbouring aggregates (springs inside an aggregate drop out). The preconditioner is
//   M⁻¹ r = D⁻¹ r + P (D_1⁻¹ + P (D_2⁻¹ + …) Pᵀ) Pᵀ r,
// each level's block diagonal inverse on the residual restricted to it, summed back up,
// except the coarsest (at most coarsest_side nodes a side), which is solved exactly by a
// banded Cholesky factor: the sheet-wide modes are what one aggregate at a time cannot see
// (27 iterations a step on the 128² cloth with D⁻¹ there, 17.5 exact). No fine matrix
// products, so it costs a few passes over the particles. It is symmetric and positive
// definite, as conjugate gradient needs.
//
// With `smoothing` ω > 0 (the default), the first coarse level's D_1⁻¹ is replaced by a
// symmetric V-cycle on that level: x = ω D_1⁻¹ b, then x += P (the levels below, additive,
// on the residual b - A_1 x restricted), then x += ω D_1⁻¹ (b - A_1 x). Block Jacobi alone
// smooths one aggregate at a time and the additive sum weakens with every level added; the
// two products on the first level (a quarter of the fine nodes) make the whole correction
// about as strong as a solve there. Measured on the cloth material: 18.4 → 12.0 iterations
// a step at 128², 33.4 → 20.4 at 256² (docs/performance.md). The pre- and post-smoothing
// being each other's transpose, it stays symmetric; it stays positive definite for
// ω λ_max(D_1⁻¹ A_1) < 2, and λ_max ≤ 2 for a sum of positive semi-definite spring blocks
// (x_i - x_j)ᵀ B (x_i - x_j) ≤ 2 (x_iᵀ B x_i + x_jᵀ B x_j) plus the mass.
//
// On large sheets (ImplicitCycleShape::k_cycle_nodes) the V-cycle's coarse solve, the
// second level, is a K-cycle (implicit_k_cycle.h) instead of block Jacobi and the additive
// levels below: the iteration count then grows less with the sheet's size. The
// preconditioner then depends on the residual, and the outer solve is flexible.
#pragma once

#include <cstddef>
#include <vector>

#include "parallel/worker_pool.h"
#include "sim/integrators/implicit/banded_cholesky.h"
#include "sim/integrators/implicit/implicit_coarse_rows.h"
#include "sim/integrators/implicit/implicit_grid_kernel.h"
#include "sim/integrators/implicit/implicit_k_cycle.h"

namespace weft {

struct ImplicitCoarseLevel {
    int rows = 0, cols = 0;          // nodes: (rows, cols) of the level below, halved up
    std::vector<double> diagonal;    // 6 per node: A_II, symmetric (xx yy zz xy xz yz)
    std::vector<double> neighbours;  // 4 × 6 per node: A_IJ to (0,1) (1,-1) (1,0) (1,1)
    std::vector<double> inverse;     // 6 per node: A_II⁻¹ (0 where singular: pinned)
    std::vector<double> residual;    // 3 per node
    std::vector<double> correction;  // 3 per node
};

// How the coarse levels correct.
struct ImplicitCycleShape {
    double weight = 1.0;     // scale of each coarse correction
    double smoothing = 0.8;  // ω of the first level's V-cycle (0: additive)
    // The second level is solved by a K-cycle (implicit_k_cycle.h) from this many nodes (a
    // 256² sheet's has 4096); below, its additive correction stays. Negative: never.
    int k_cycle_nodes = ImplicitKCycle::default_min_nodes;
};

struct ImplicitMultilevel {
    // The coarsest level has at most this many nodes a side and is solved exactly.
    static constexpr int coarsest_side = 8;
    std::vector<ImplicitCoarseLevel> levels;  // finest coarse level first
    BandedCholesky exact;                     // the coarsest level's factor
    ImplicitCycleShape shape;                 // as given to the last build()
    CoarseRows first_rows;                    // the first level's matrix in float, for it
    std::vector<double> added_by_row;         // r · P x_c per row of the first level
    std::vector<float> spread;  // the first level's correction along fine columns (x, y, z rows)
    // On large sheets the second level is solved by a K-cycle (implicit_k_cycle.h), not
    // by its block Jacobi and the additive levels below.
    ImplicitKCycle k_cycle;
    bool uses_k_cycle = false;

    // Builds every coarse level from the fine system of `job` (its direction terms, the
    // diagonal blocks and the free mask of the setup and residual passes); the first level's
    // products run the kernel build `level` (kernel_build.h).
    void build(const implicit_kernel::Job& job, const ImplicitCycleShape& cycle, WorkerPool* pool,
               SimdLevel level);
    // z += P (coarse correction of Pᵀ r) over the whole fine grid; returns r · (what it
    // added to z), so the caller's r · z stays exact without another pass. `restricted`:
    // the fine passes have already summed r into the first level (attach() below).
    double apply(const implicit_kernel::Job& job, bool restricted, WorkerPool* pool);
    // Points the job's coarse fields at the first level, so the update passes restrict on
    // the way; detach() before a pass whose residual must not be restricted.
    void attach(implicit_kernel::Job& job);
    static void detach(implicit_kernel::Job& job) { job.coarse_cols = 0; }
};

}  // namespace weft
