// The body of the structured force pass's row kernel, included by grid_force_kernel_*.cpp
// inside an anonymous namespace (internal linkage, see grid_force_kernel.h).
//
// Gather formulation. For every direction k and every particle p the force on p from the
// spring that starts at p, F_k[p] (zero where there is none or it is dead), is computed
// once; the force on a particle is then
//     f[p] = m g - air_drag (v - wind) + Σ_k F_k[p] - Σ_k F_k[p - o_k]
// summed in that fixed order (o_k: the direction's index offset). No particle is written by
// two springs, so rows can be split between threads freely: the arithmetic of every
// particle is the same whatever the split, hence bit-identical results for any thread count.
//
// Rows are streamed: a ring of three rows of positions and velocities in per-component
// arrays (x[], y[], z[] — the loops over columns vectorise), and a ring of three rows of
// spring forces, since a spring reaches at most two rows down.
//
// The spring force is the general pass's (force_pass.cpp): d = x_j - x_i, l = sqrt(d·d),
// u = d / l, t = k (l - L) + c ((v_j - v_i)·u), F = t u, except that u is d times 1/l (an ulp
// apart) and each particle's spring forces are summed in another order: the two passes agree
// to rounding (tested), and this one agrees with itself bit for bit however rows are split.
//
// The spring forces and their sums are of type Real: double, or float for the fused step's
// single-precision forces (Job::single_precision_springs). In float the differences of the
// ends' positions are still taken in double and only then rounded, so a spring's length keeps
// float's relative precision (about 6e-8 of the length) wherever the sheet is, rather than
// float's precision of a coordinate a metre from the origin. The dashpot's velocities are
// rounded to float once a row and their differences taken in float: that rounding is
// relative to the velocities, and moves the damping force by far less than the tension's
// own float rounding. The state and the update stay in double. With Real = double every
// operation is the one it always was.

template <class T>
T* ring_row(T* base, std::size_t row_stride, int row) {
    return base + static_cast<std::size_t>(row % 3) * row_stride;
}

#include "sim/grid/deinterleave.inl"

// Per-component rows: component k of row slot s starts at state + (s * 6 + k) * padded.
void load_state_row(const Job& job, int row, double* state_ring, std::size_t padded) {
    double* slot = ring_row(state_ring, 6 * padded, row) + row_padding;
    const std::size_t cols = static_cast<std::size_t>(job.cols);
    const double* x = job.positions + static_cast<std::size_t>(row) * cols * 3;
    const double* v = job.velocities + static_cast<std::size_t>(row) * cols * 3;
    deinterleave(x, slot, slot + padded, slot + 2 * padded, cols);
    deinterleave(v, slot + 3 * padded, slot + 4 * padded, slot + 5 * padded, cols);
}

// The row's velocities rounded to float, for the float springs' dashpots: component k of row
// slot s at velocity_ring + (s * 3 + k) * padded, laid out as the state ring's doubles.
void round_velocity_row(int row, const double* state_ring, float* velocity_ring,
                        std::size_t padded) {
    const double* __restrict from = ring_row(state_ring, 6 * padded, row) + 3 * padded;
    float* __restrict to = ring_row(velocity_ring, 3 * padded, row);
    for (std::size_t c = 0; c < 3 * padded; ++c) to[c] = static_cast<float>(from[c]);
}

// A spring pushes along its length when l² is above this: any positive double; in float,
// above the least normal float, so that 1/l² is finite.
template <class Real>
constexpr Real shortest_length_squared = std::is_same_v<Real, float>
                                             ? std::numeric_limits<float>::min()
                                             : Real(0);

// Spring forces of the springs of direction `direction` that start on row `row`, into
// out[0..3][padded) (padding and columns without a spring left at zero).
template <class Real>
void spring_row(const Job& job, const Direction& direction, int row, double* state_ring,
                const float* velocity_ring, std::size_t padded, Real* __restrict out_x,
                Real* __restrict out_y, Real* __restrict out_z) {
    const int cols = job.cols;
    const int other_row = row + direction.row_step;
    const int dc = direction.col_step;
    const int c_begin = dc < 0 ? -dc : 0;
    const int c_end = other_row >= job.rows ? c_begin : (dc > 0 ? cols - dc : cols);
    // Zeros where no spring starts: the padding, the columns the direction leaves the grid
    // from, and whole rows near the bottom edge.
    const auto zero_from =
        static_cast<std::size_t>(c_end > c_begin ? c_end : c_begin) + row_padding;
    for (std::size_t c = 0; c < static_cast<std::size_t>(c_begin) + row_padding; ++c)
        out_x[c] = out_y[c] = out_z[c] = Real(0);
    for (std::size_t c = zero_from; c < padded; ++c) out_x[c] = out_y[c] = out_z[c] = Real(0);
    if (c_begin >= c_end) return;
    const double* a = ring_row(state_ring, 6 * padded, row) + row_padding;
    const double* b = ring_row(state_ring, 6 * padded, other_row) + row_padding + dc;
    const double* __restrict xa = a;
    const double* __restrict ya = a + padded;
    const double* __restrict za = a + 2 * padded;
    // The dashpot's velocities: the state's doubles, or for float springs their float copy
    // (round_velocity_row), so that no difference of velocities is converted spring by spring.
    using Velocity = std::conditional_t<std::is_same_v<Real, float>, float, double>;
    const Velocity* velocity_a;
    const Velocity* velocity_b;
    if constexpr (std::is_same_v<Real, float>) {
        velocity_a = ring_row(velocity_ring, 3 * padded, row) + row_padding;
        velocity_b = ring_row(velocity_ring, 3 * padded, other_row) + row_padding + dc;
    } else {
        velocity_a = a + 3 * padded;
        velocity_b = b + 3 * padded;
    }
    const Velocity* __restrict ua = velocity_a;
    const Velocity* __restrict va = velocity_a + padded;
    const Velocity* __restrict wa = velocity_a + 2 * padded;
    const double* __restrict xb = b;
    const double* __restrict yb = b + padded;
    const double* __restrict zb = b + 2 * padded;
    const Velocity* __restrict ub = velocity_b;
    const Velocity* __restrict vb = velocity_b + padded;
    const Velocity* __restrict wb = velocity_b + 2 * padded;
    const std::size_t first = static_cast<std::size_t>(row) * static_cast<std::size_t>(cols);
    // The rest lengths in Real: float springs read their float copy (the same values as
    // rounding each double here).
    const Real* __restrict rest;
    if constexpr (std::is_same_v<Real, float>)
        rest = direction.rest_lengths_float + first;
    else
        rest = direction.rest_lengths + first;
    const auto k = static_cast<Real>(direction.stiffness);
    const auto damping = static_cast<Real>(direction.damping);
    Real* __restrict fx = out_x + row_padding;
    Real* __restrict fy = out_y + row_padding;
    Real* __restrict fz = out_z + row_padding;
    for (int c = c_begin; c < c_end; ++c) {
        const auto dx = static_cast<Real>(xb[c] - xa[c]), dy = static_cast<Real>(yb[c] - ya[c]),
                   dz = static_cast<Real>(zb[c] - za[c]);
        const auto rest_length = static_cast<Real>(rest[c]);
        const Real length_squared = dx * dx + dy * dy + dz * dz;
        const Real length = std::sqrt(length_squared);
        // A dead spring, or coincident ends (no direction to push along): no force. Written
        // without a branch so the loop vectorises: `none` is exactly 0 or 1, so for an acting
        // spring the divisor is l (or l²) and the mask the live factor, to the last bit, and a
        // masked lane divides by 1 and never makes a NaN of its own. (l > 0 exactly when
        // l² > 0: the square root of a positive number is positive.) In float, a spring
        // shorter than about 1e-19 m counts as coincident ends, so that 1/l² stays finite.
        const Real none = length_squared > shortest_length_squared<Real> ? Real(0) : Real(1);
        const Real live = rest_length >= Real(0) ? Real(1) : Real(0);
        const Real mask = live * (Real(1) - none);
        // u = d · (1/l): one division instead of three. The divider is this loop's
        // bottleneck (with the square root); u differs from the general pass's d / l by at
        // most an ulp per component. In float, 1/l is l · (1/l²) (another ulp or so), so the
        // division need not wait for the square root.
        Real inverse_length;
        if constexpr (std::is_same_v<Real, float>)
            inverse_length = length * (Real(1) / (length_squared + none));
        else
            inverse_length = Real(1) / (length + none);
        const Real ux = dx * inverse_length, uy = dy * inverse_length, uz = dz * inverse_length;
        // Hooke's law plus a dashpot on the rate of change of length, (v_j - v_i) · u.
        const Real tension =
            k * (length - rest_length) + damping * (static_cast<Real>(ub[c] - ua[c]) * ux +
                                                    static_cast<Real>(vb[c] - va[c]) * uy +
                                                    static_cast<Real>(wb[c] - wa[c]) * uz);
        const Real masked_tension = mask * tension;
        fx[c] = masked_tension * ux;
        fy[c] = masked_tension * uy;
        fz[c] = masked_tension * uz;
    }
}

// One component of one row of the gather, in one pass:
//     sum = m g [- drag (v - wind)] + F_0 + ... + F_5 - G_0 - ... - G_5
// with F_k the springs of direction k starting at each particle and G_k those ending there
// (a row of zeros for a direction the cloth does not have: adding 0 changes nothing).
// The external force is taken in double and rounded once to Real.
template <bool WithDrag, class Real>
void gather_row(Real* __restrict sum, const double* __restrict mass,
                const double* __restrict velocity, double gravity, double drag, double wind,
                const Real* const (&starting)[max_directions],
                const Real* const (&ending)[max_directions], std::size_t count) {
    const Real* __restrict f0 = starting[0];
    const Real* __restrict f1 = starting[1];
    const Real* __restrict f2 = starting[2];
    const Real* __restrict f3 = starting[3];
    const Real* __restrict f4 = starting[4];
    const Real* __restrict f5 = starting[5];
    const Real* __restrict g0 = ending[0];
    const Real* __restrict g1 = ending[1];
    const Real* __restrict g2 = ending[2];
    const Real* __restrict g3 = ending[3];
    const Real* __restrict g4 = ending[4];
    const Real* __restrict g5 = ending[5];
    for (std::size_t c = 0; c < count; ++c) {
        double external = mass[c] * gravity;  // exactly m g without drag, as the general pass
        if constexpr (WithDrag) external = external - drag * (velocity[c] - wind);
        auto total = static_cast<Real>(external);
        total += f0[c];
        total += f1[c];
        total += f2[c];
        total += f3[c];
        total += f4[c];
        total += f5[c];
        total -= g0[c];
        total -= g1[c];
        total -= g2[c];
        total -= g3[c];
        total -= g4[c];
        total -= g5[c];
        sum[c] = total;
    }
}

template <class Real>
void store_forces(const Real* __restrict sum_x, const Real* __restrict sum_y,
                  const Real* __restrict sum_z, double* __restrict f, std::size_t count) {
    for (std::size_t c = 0; c < count; ++c) {
        f[3 * c] = sum_x[c];
        f[3 * c + 1] = sum_y[c];
        f[3 * c + 2] = sum_z[c];
    }
}

// Symplectic Euler on one row, with the force f still in registers' reach:
//     v' = v + (dt m⁻¹) f,   x' = x + dt v'
// in the same operations, in the same order, as step_symplectic_euler's loop over Vec3, so
// the fused step and the separate one give the same bits. `state` is the row's slot in the
// state ring (x, y, z, then the velocity's three components, `padded` apart).
template <class Real>
void advance_row(const Real* __restrict sum_x, const Real* __restrict sum_y,
                 const Real* __restrict sum_z, const double* state, std::size_t padded,
                 const double* __restrict inverse_mass, double dt, double* __restrict next_x,
                 double* __restrict next_v, std::size_t count) {
    const double* __restrict x = state;
    const double* __restrict y = state + padded;
    const double* __restrict z = state + 2 * padded;
    const double* __restrict u = state + 3 * padded;
    const double* __restrict v = state + 4 * padded;
    const double* __restrict w = state + 5 * padded;
    for (std::size_t c = 0; c < count; ++c) {
        const double scale = dt * inverse_mass[c];  // s/kg
        const double vx = u[c] + scale * static_cast<double>(sum_x[c]);
        const double vy = v[c] + scale * static_cast<double>(sum_y[c]);
        const double vz = w[c] + scale * static_cast<double>(sum_z[c]);
        next_v[3 * c] = vx;
        next_v[3 * c + 1] = vy;
        next_v[3 * c + 2] = vz;
        next_x[3 * c] = x[c] + dt * vx;
        next_x[3 * c + 1] = y[c] + dt * vy;
        next_x[3 * c + 2] = z[c] + dt * vz;
    }
}

void sweep_particles(const double* __restrict x, const double* __restrict reference,
                     const double* __restrict v, std::size_t count, double limit_squared,
                     bool& non_finite, bool& moved);

template <class Real>
SweepFlags force_rows_of(const Job& job, int row_begin, int row_end, double* scratch) {
    SweepFlags flags;
    const std::size_t padded = static_cast<std::size_t>(job.cols + 2 * row_padding);
    const std::size_t cols = static_cast<std::size_t>(job.cols);
    double* state_ring = scratch;  // 3 rows × 6 components
    // 3 rows × directions × 3 components; in float, the doubles' room holds them with some
    // to spare (Real is never wider than double).
    static_assert(sizeof(Real) <= sizeof(double));
    Real* spring_ring = reinterpret_cast<Real*>(scratch + 3 * 6 * padded);
    const std::size_t spring_row_stride = static_cast<std::size_t>(max_directions) * 3 * padded;
    Real* sum_rows = spring_ring + 3 * spring_row_stride;  // 3 components of one row
    Real* zero_row = sum_rows + 3 * padded;                // stays all zeros
    for (std::size_t c = 0; c < padded; ++c) zero_row[c] = Real(0);
    // For float springs, 3 rows of the velocities in float, after the zeros.
    float* velocity_ring = reinterpret_cast<float*>(zero_row + padded);
    auto load_row = [&](int r) {
        load_state_row(job, r, state_ring, padded);
        if constexpr (std::is_same_v<Real, float>)
            round_velocity_row(r, state_ring, velocity_ring, padded);
    };
    auto spring_force = [&](int row, int k, int component) {
        return ring_row(spring_ring, spring_row_stride, row) +
               (static_cast<std::size_t>(k) * 3 + static_cast<std::size_t>(component)) * padded;
    };

    // Springs reach two rows down: the band's particles also receive the springs that start
    // on the two rows above it, recomputed here rather than shared between threads.
    const int first_spring_row = row_begin >= 2 ? row_begin - 2 : 0;
    for (int r = first_spring_row; r < first_spring_row + 2 && r < job.rows; ++r) load_row(r);
    for (int row = first_spring_row; row < row_end; ++row) {
        if (row + 2 < job.rows) load_row(row + 2);
        for (int k = 0; k < job.direction_count; ++k)
            spring_row(job, job.directions[k], row, state_ring, velocity_ring, padded,
                       spring_force(row, k, 0), spring_force(row, k, 1), spring_force(row, k, 2));
        if (row < row_begin) continue;

        // Gather, per component in rows of the scratch: external forces, the springs
        // starting here, minus those ending here; then one interleaved store.
        const double* state = ring_row(state_ring, 6 * padded, row) + row_padding;
        const double* mass = job.masses + static_cast<std::size_t>(row) * cols;
        Real* sum[3] = {sum_rows, sum_rows + padded, sum_rows + 2 * padded};
        for (int a = 0; a < 3; ++a) {
            const Real* starting[max_directions];
            const Real* ending[max_directions];
            for (int k = 0; k < max_directions; ++k) {
                starting[k] = ending[k] = zero_row;
                if (k >= job.direction_count) continue;
                const Direction& direction = job.directions[k];
                starting[k] = spring_force(row, k, a) + row_padding;
                const int from_row = row - direction.row_step;
                if (from_row >= 0)
                    ending[k] = spring_force(from_row, k, a) +
                                static_cast<std::size_t>(row_padding - direction.col_step);
            }
            const double* velocity = state + (3 + a) * padded;
            if (job.air_drag != 0.0)
                gather_row<true>(sum[a], mass, velocity, job.gravity[a], job.air_drag, job.wind[a],
                                 starting, ending, cols);
            else
                gather_row<false>(sum[a], mass, velocity, job.gravity[a], 0.0, 0.0, starting,
                                  ending, cols);
        }
        const std::size_t first = static_cast<std::size_t>(row) * cols;
        if (!job.next_positions) {
            store_forces(sum[0], sum[1], sum[2], job.forces + 3 * first, cols);
            continue;
        }
        double* next_x = job.next_positions + 3 * first;
        double* next_v = job.next_velocities + 3 * first;
        advance_row(sum[0], sum[1], sum[2], state, padded, job.inverse_masses + first, job.dt,
                    next_x, next_v, cols);
        if (job.reference_positions) {
            bool non_finite = false, moved = false;
            sweep_particles(next_x, job.reference_positions + 3 * first, next_v, cols,
                            job.moved_limit_squared, non_finite, moved);
            flags.non_finite = flags.non_finite || non_finite;
            flags.moved = flags.moved || moved;
        }
    }
    return flags;
}

SweepFlags force_rows(const Job& job, int row_begin, int row_end, double* scratch) {
    return job.single_precision_springs ? force_rows_of<float>(job, row_begin, row_end, scratch)
                                        : force_rows_of<double>(job, row_begin, row_end, scratch);
}

// Runs body(a, b, rest, c_begin, c_end) for every direction's springs that start on each of
// rows [row_begin, row_end): a and b point at the two ends' positions (interleaved x y z) of
// column 0, rest at the rest lengths (negative: no spring), columns [c_begin, c_end) being
// those whose spring stays on the grid. The spring passes of the divergence guard below.
template <class Body>
void over_spring_rows(const Job& job, int row_begin, int row_end, Body&& body) {
    const auto cols = static_cast<std::size_t>(job.cols);
    for (int row = row_begin; row < row_end; ++row) {
        for (int k = 0; k < job.direction_count; ++k) {
            const Direction& direction = job.directions[k];
            if (row + direction.row_step >= job.rows) continue;
            const int dc = direction.col_step;
            const auto c_begin = static_cast<std::size_t>(dc < 0 ? -dc : 0);
            // A sheet narrower than the direction's reach (one column, bend springs) has no
            // spring of it on a row: the range is empty, not negative.
            const auto c_end =
                static_cast<std::size_t>(std::max(dc > 0 ? job.cols - dc : job.cols, 0));
            const std::size_t first = static_cast<std::size_t>(row) * cols;
            const std::ptrdiff_t offset = direction.row_step * job.cols + dc;
            body(job.positions + 3 * first,
                 job.positions + 3 * (static_cast<std::ptrdiff_t>(first) + offset),
                 direction.rest_lengths + first, c_begin, c_end);
        }
    }
}

// Whether some live spring of one row's run (over_spring_rows' a, b, rest and columns) has
// |d|² > ratio_squared L². Reads positions in place (interleaved x y z); no square root, no
// early exit, so the loop vectorises.
bool row_maybe_overstretched(const double* __restrict a, const double* __restrict b,
                             const double* __restrict rest, std::size_t c_begin, std::size_t c_end,
                             double ratio_squared) {
    unsigned suspect = 0;
    for (std::size_t c = c_begin; c < c_end; ++c) {
        const double dx = b[3 * c] - a[3 * c], dy = b[3 * c + 1] - a[3 * c + 1],
                     dz = b[3 * c + 2] - a[3 * c + 2];
        const double limit = ratio_squared * rest[c] * rest[c];
        const double live = rest[c] >= 0.0 ? 1.0 : 0.0;
        suspect |= live * (dx * dx + dy * dy + dz * dz) > limit ? 1u : 0u;
    }
    return suspect != 0;
}

// The divergence guard's stretch test on rows [row_begin, row_end): true if some live spring
// starting there has |d|² > ratio_squared L².
bool rows_maybe_overstretched(const Job& job, double ratio_squared, int row_begin, int row_end) {
    bool suspect = false;
    over_spring_rows(job, row_begin, row_end,
                     [&](const double* a, const double* b, const double* rest, std::size_t c_begin,
                         std::size_t c_end) {
                         if (row_maybe_overstretched(a, b, rest, c_begin, c_end, ratio_squared))
                             suspect = true;
                     });
    return suspect;
}

// The divergence guard's pass over the springs after a step that moved particles far
// (divergence.cpp): the runaway test of rows_maybe_overstretched and, for the next reference,
// the headroom min (ratio L - |d|) and the scale max (ratio L) over live springs, each |d| as
// glm::length computes it, so the same numbers as the scan spring by spring.
StretchHeadroom rows_stretch_headroom(const Job& job, double ratio, double ratio_squared,
                                      int row_begin, int row_end) {
    unsigned suspect = 0;
    double headroom = std::numeric_limits<double>::infinity();
    double scale = 0.0;
    over_spring_rows(
        job, row_begin, row_end,
        [&](const double* __restrict a, const double* __restrict b, const double* __restrict rest,
            std::size_t c_begin, std::size_t c_end) {
            for (std::size_t c = c_begin; c < c_end; ++c) {
                const double dx = b[3 * c] - a[3 * c], dy = b[3 * c + 1] - a[3 * c + 1],
                             dz = b[3 * c + 2] - a[3 * c + 2];
                const double length_squared = dx * dx + dy * dy + dz * dz;
                const bool live = rest[c] >= 0.0;
                suspect |= live && length_squared > ratio_squared * rest[c] * rest[c] ? 1u : 0u;
                const double limit = ratio * rest[c];
                const double left = limit - std::sqrt(length_squared);
                headroom = live && left < headroom ? left : headroom;
                scale = live && limit > scale ? limit : scale;
            }
        });
    return {suspect != 0, headroom, scale};
}

// One spring's error of linearisation in rest lengths, or 0 if it does not end the step
// longer than ratio L (implicit_euler.cpp's largest_linearisation_error, operation for
// operation: glm's dot sums x, then y, then z). d0, d1: the spring at the linearisation
// point and at the end.
double spring_linearisation_error(const double (&d0)[3], const double (&d1)[3], double rest,
                                  double ratio) {
    const double l0 = std::sqrt(d0[0] * d0[0] + d0[1] * d0[1] + d0[2] * d0[2]);
    const double l1 = std::sqrt(d1[0] * d1[0] + d1[1] * d1[1] + d1[2] * d1[2]);
    if (!(l0 > 0.0) || !(l1 > ratio * rest)) return 0.0;
    double u[3], change[3];
    for (int k = 0; k < 3; ++k) {
        u[k] = d0[k] / l0;
        change[k] = d1[k] - d0[k];
    }
    const double along = u[0] * change[0] + u[1] * change[1] + u[2] * change[2];
    const double transverse = std::max(0.0, 1.0 - rest / l0);
    const double scale = (l1 - rest) / l1;
    double miss[3];
    for (int k = 0; k < 3; ++k) {
        const double assumed =
            (l0 - rest) * u[k] + along * u[k] + transverse * (change[k] - along * u[k]);
        miss[k] = scale * d1[k] - assumed;
    }
    return std::sqrt(miss[0] * miss[0] + miss[1] * miss[1] + miss[2] * miss[2]) / rest;
}

double rows_linearisation_error(const Job& job, const double* start, double ratio,
                                double ratio_squared, int row_begin, int row_end) {
    double largest = 0.0;
    over_spring_rows(
        job, row_begin, row_end,
        [&](const double* __restrict a, const double* __restrict b, const double* __restrict rest,
            std::size_t c_begin, std::size_t c_end) {
            // Almost every row of a sheet has no spring that long: a pass without a branch
            // tells, and only a row that may have one is looked at spring by spring.
            if (!row_maybe_overstretched(a, b, rest, c_begin, c_end, ratio_squared)) return;
            const double* a0 = start + (a - job.positions);
            const double* b0 = start + (b - job.positions);
            for (std::size_t c = c_begin; c < c_end; ++c) {
                if (!(rest[c] >= 0.0)) continue;
                const double d0[3] = {b0[3 * c] - a0[3 * c], b0[3 * c + 1] - a0[3 * c + 1],
                                      b0[3 * c + 2] - a0[3 * c + 2]};
                const double d1[3] = {b[3 * c] - a[3 * c], b[3 * c + 1] - a[3 * c + 1],
                                      b[3 * c + 2] - a[3 * c + 2]};
                largest = std::max(largest, spring_linearisation_error(d0, d1, rest[c], ratio));
            }
        });
    return largest;
}

// The divergence guard's sweep over particles (divergence.cpp): flags a non-finite position
// or velocity, and whether some particle has moved from its reference position by
// |x - x_ref|² >= limit_squared. Branch-free, so it vectorises.
void sweep_particles(const double* __restrict x, const double* __restrict reference,
                     const double* __restrict v, std::size_t count, double limit_squared,
                     bool& non_finite, bool& moved) {
    // Over the 3 count coordinates as one flat array, so no shuffles gather a particle's
    // three components (they cost more than the test). A particle with |d|² >= limit² has
    // some component with d_c² >= limit² / 3: testing each component against a third of the
    // limit, less a margin far above rounding, flags every particle the test on |d| flags,
    // and some that moved less (at most √3 times less); the guard's exact scan then decides.
    const double component_limit_squared = limit_squared * (1.0 / 3.0) * (1.0 - 1e-9);
    unsigned bad = 0, far = 0;
    for (std::size_t i = 0; i < 3 * count; ++i) {
        const double d = x[i] - reference[i];
        // d - d is 0 for a finite d, NaN otherwise (an overflowing d too: the scan decides).
        bad |= ((d - d == 0.0) & (v[i] - v[i] == 0.0)) ? 0u : 1u;
        far |= d * d >= component_limit_squared ? 1u : 0u;
    }
    non_finite = bad != 0;
    moved = far != 0;
}
