// The row kernels of the structured implicit Euler solve (integrators/implicit_grid_solve.h),
// as plain data in and plain data out, so that, like the force pass's kernel
// (grid_force_kernel.h), they are compiled three times — baseline x86-64, AVX2, AVX-512 —
// and chosen at run time. Nothing here knows Cloth or glm.
//
// Every array is single precision, structure of arrays, and padded: particle p of the
// grid (row-major) lives at index `pad + p` of an array `pad + count + pad` long, with
// zeros in the padding, so a row reads its neighbours two rows up or down without a
// bounds test.
#pragma once

#include <cstddef>

namespace weft::implicit_kernel {

inline constexpr int max_directions = 6;

// One stencil direction's share of h² K + h C, per start particle p (the spring from p to
// p + offset): the block iso I + along u uᵀ, stored as iso and the axial vector
// a = √along u (along ≥ 0: the transverse term never exceeds k), so that along u uᵀ = a aᵀ:
// four floats a spring instead of five, for a product that streams them from memory every
// iteration. Zero where no live spring starts.
struct DirectionTerms {
    int row_step = 0;            // dr
    int col_step = 0;            // dc
    double stiffness = 0.0;      // N/m
    double damping = 0.0;        // N·s/m
    const double* rest_lengths;  // m, per start particle, unpadded; negative: no spring
    float* iso;                  // kg: h² k max(0, 1 - L/l), padded
    float* axial_x;              // √kg: √(h² (k - k max(0, 1 - L/l)) + h c) u, padded
    float* axial_y;
    float* axial_z;
};

// Three padded components.
struct Field3 {
    float* x;
    float* y;
    float* z;
};

struct Job {
    int rows = 0, cols = 0;
    std::size_t pad = 0;    // padding before and after every array, in floats
    double dt = 0.0;        // s
    double air_drag = 0.0;  // N·s/m
    int direction_count = 0;
    DirectionTerms directions[max_directions] = {};

    // Inputs of the setup pass (unpadded, interleaved doubles): the state the step is
    // linearised at, x_k = x0 + h v_k (a Newton iterate of the backward Euler system; the
    // first is v_k = v0), and the step's start.
    const double* positions = nullptr;           // m, x_k
    const double* velocities = nullptr;          // m/s, v_k
    const double* initial_velocities = nullptr;  // m/s, v0
    const double* start_velocities = nullptr;    // m/s, v_s: v_k, or v0 where v_k = 0
    // Whether v_s = v_k (b = g + A v_s), or the step is linearised at x0 with v_k = 0 for
    // every free particle and v_s = v0 (b = g).
    bool linearised_at_start = true;
    const double* forces = nullptr;          // N, f(x_k, v_k), the dampers' included
    const double* masses = nullptr;          // kg
    const double* inverse_masses = nullptr;  // 1/kg; 0 marks a pinned particle

    float* mass_diagonal = nullptr;  // padded: m + h air_drag
    float* free = nullptr;           // padded: 1 for a free particle, 0 for a pinned one
    // Each particle's 3x3 diagonal block of A (zero for a pinned one), symmetric: xx yy zz
    // xy xz yz; what the coarse levels of the preconditioner are built from.
    float* diagonal[6] = {};
    // The preconditioner, the inverse of each particle's 3x3 diagonal block of A, symmetric:
    // xx yy zz xy xz yz.
    float* inverse_diagonal[6] = {};

    // The first coarse level of the preconditioner (integrators/implicit_multilevel.h), when
    // attached: the passes that finish a pair of rows' residual sum it into the pair's coarse
    // nodes (3 doubles each) and multiply by the nodes' inverse diagonal blocks.
    int coarse_cols = 0;  // 0: not attached
    // The preconditioner depends on the residual (the K-cycle, implicit_k_cycle.h): the
    // update pass also sums r_new · z_old, for flexible conjugate gradient's β.
    bool flexible = false;
    double* coarse_residual = nullptr;       // 3 per node
    double* coarse_correction = nullptr;     // 3 per node
    const double* coarse_inverse = nullptr;  // 6 per node

    // Particles held on a solid's surface (integrators/implicit_contacts.h): the unit normal
    // along which each one's velocity is prescribed, zero for every other particle. Every
    // residual, product and preconditioned vector is filtered by S = I - n nᵀ there.
    bool has_contacts = false;
    Field3 contact_normal;

    Field3 rhs_change;      // g = h f(x_k, v_k) - M (v_k - v0), filtered where a particle is held
    Field3 rhs;             // b = g + A v_k (the residual pass forms it)
    Field3 start;           // v_s, where the solve starts and its residual's scale is taken
    Field3 guess_change;    // the previous step's v1 - v0 (the warm start), kept between steps
    Field3 solution;        // v1, the iterate
    Field3 residual;        // r = b - A v1
    Field3 preconditioned;  // z = P r
    Field3 direction;       // d = z + β d
    Field3 applied;         // A z; after the solve, with contacts, A (v1 - v_k) unfiltered
    Field3 product;         // q = A d = A z + β q
};

// Sums one per row, in double, each row's own sum taken in a fixed lane order, so they do
// not depend on how rows are split or on the vector width.
struct RowSums {
    double* first = nullptr;
    double* second = nullptr;
    double* third = nullptr;
    // The largest |P_J r|² of each row (P_J: the block-Jacobi part of the preconditioner), an
    // estimate of the largest velocity error the solve leaves at a particle: a maximum, so it
    // is exact whatever the order.
    double* largest = nullptr;
};

// Pass 1, rows [begin, end): the direction terms of the springs that start on these rows,
// g, v_s, the mass diagonal and the free mask, and the guess v_s + warm_start · (previous
// change) into `solution`.
void setup_rows_baseline(const Job& job, int begin, int end, double warm_start);
void setup_rows_avx2(const Job& job, int begin, int end, double warm_start);
void setup_rows_avx512(const Job& job, int begin, int end, double warm_start);

// The row passes are handed whole pairs of rows (begin even), so that the passes that
// finish the residual can sum each pair into the first coarse level.
//
// Pass 2: the preconditioner; b, r = b - A v1, z = P r; sums r·z, r·r, and |b - A v_s|²
// (the scale of the residual: the right-hand side of the Δv form from v_s).
void residual_rows_baseline(const Job& job, int begin, int end, RowSums sums);
void residual_rows_avx2(const Job& job, int begin, int end, RowSums sums);
void residual_rows_avx512(const Job& job, int begin, int end, RowSums sums);

// Pass 3 (every iteration): d = z + β d, q = A z + β q; sums d·q.
void direction_rows_baseline(const Job& job, int begin, int end, float beta, RowSums sums);
void direction_rows_avx2(const Job& job, int begin, int end, float beta, RowSums sums);
void direction_rows_avx512(const Job& job, int begin, int end, float beta, RowSums sums);

// Pass 4 (every iteration): v1 += α d, r -= α q, z = P r; sums r·z, r·r, and when the job is
// flexible, r · (z before this pass) in third.
void update_rows_baseline(const Job& job, int begin, int end, float alpha, RowSums sums);
void update_rows_avx2(const Job& job, int begin, int end, float alpha, RowSums sums);
void update_rows_avx512(const Job& job, int begin, int end, float alpha, RowSums sums);

// After the iterations: one damped block-Jacobi step on the residual they left,
// v1 += ω P_J r (P_J: the block-Jacobi part of the preconditioner, zero at fixed particles).
// Writes z = P_J r on the way; r is left as it was.
void smooth_rows_baseline(const Job& job, int begin, int end, float omega);
void smooth_rows_avx2(const Job& job, int begin, int end, float omega);
void smooth_rows_avx512(const Job& job, int begin, int end, float omega);

// After the solve, with contacts and `direction` = v1 - v_k: applied = A (v1 - v_k) without
// the contact filter, so that A (v1 - v_k) - g = A v1 - b at a held particle is the impulse
// its surface gave it (g unfiltered).
void unfiltered_product_rows_baseline(const Job& job, int begin, int end);
void unfiltered_product_rows_avx2(const Job& job, int begin, int end);
void unfiltered_product_rows_avx512(const Job& job, int begin, int end);

}  // namespace weft::implicit_kernel
