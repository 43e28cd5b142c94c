// The row kernel of the structured force pass, as plain data in and plain data out, so it
// can be compiled three times — for baseline x86-64, AVX2 and AVX-512 — and picked at run
// time (grid_force_pass.cpp). Nothing here knows Cloth or glm: the builds must not share any
// inline function, or the linker could hand the baseline build the AVX2 copy.
#pragma once

#include <cstddef>
#include <cstdint>

namespace weft::grid_kernel {

inline constexpr int max_directions = 6;
// Columns of zeros on either side of every spring-force row, so the gather reads the spring
// that ends at (r, c) from (r - dr, c - dc) without a bounds test (|dc| <= 2).
inline constexpr int row_padding = 2;

struct Direction {
    int row_step;                     // dr
    int col_step;                     // dc
    double stiffness;                 // N/m
    double damping;                   // N·s/m
    const double* rest_lengths;       // m, per start particle; negative: no live spring there
    const float* rest_lengths_float;  // the same rounded to float (for float springs)
};

struct Job {
    int rows = 0, cols = 0;
    const double* positions = nullptr;   // m, x y z per particle (Vec3 array)
    const double* velocities = nullptr;  // m/s
    double* forces = nullptr;            // N, written: x y z per particle
    const double* masses = nullptr;      // kg
    double gravity[3] = {};              // m/s²
    double air_drag = 0.0;               // N·s/m
    double wind[3] = {};                 // m/s
    int direction_count = 0;
    Direction directions[max_directions] = {};
    // The fused symplectic Euler step (grid_force_pass.h), when `next_positions` is set: the
    // force is not stored but used at once, v' = v + (dt m⁻¹) f, x' = x + dt v', written to
    // next_velocities and next_positions (never the arrays read above, so no band reads a
    // row another has already advanced).
    double dt = 0.0;                         // s
    const double* inverse_masses = nullptr;  // 1/kg, 0 for a pinned particle
    double* next_positions = nullptr;        // m, x y z per particle
    double* next_velocities = nullptr;       // m/s
    // The spring forces and their sums in float instead of double (grid_force_kernel.inl):
    // about twice the springs a vector instruction holds, and a cheaper square root and
    // division. The state, the external forces and the update stay in double.
    bool single_precision_springs = false;
    // And, when `reference_positions` is set, the divergence guard's sweep of the new state
    // (as sweep_particles below) in the same pass.
    const double* reference_positions = nullptr;  // m
    double moved_limit_squared = 0.0;             // m²
};

// What the guard's sweep found: a non-finite value, a particle far from its reference.
struct SweepFlags {
    bool non_finite = false;
    bool moved = false;
};

// Doubles of scratch one thread needs for a cloth `cols` wide.
inline std::size_t scratch_doubles(int cols) {
    const auto padded = static_cast<std::size_t>(cols + 2 * row_padding);
    // Three rows of x, v (6 components), three rows of spring forces (3 per direction), one
    // row of force sums (3 components), a row of zeros, and for float springs three rows of
    // v in float (9 float rows, in the room of 5 double rows).
    return 3 * 6 * padded + 3 * max_directions * 3 * padded + 3 * padded + padded + 5 * padded;
}

// Writes the total force on every particle of rows [row_begin, row_end) — or, for a fused
// step, advances them. Reads positions and velocities of rows up to row_end + 1 and
// recomputes the springs of the two rows above the band, so bands are independent and the
// result does not depend on how rows are split. Returns the fused sweep's findings.
SweepFlags force_rows_baseline(const Job& job, int row_begin, int row_end, double* scratch);
SweepFlags force_rows_avx2(const Job& job, int row_begin, int row_end, double* scratch);
SweepFlags force_rows_avx512(const Job& job, int row_begin, int row_end, double* scratch);

// True if some live spring starting on rows [row_begin, row_end) may be longer than
// sqrt(ratio_squared) rest lengths: |d|² > ratio_squared L² (the divergence guard's test).
bool rows_maybe_overstretched_baseline(const Job& job, double ratio_squared, int row_begin,
                                       int row_end);
bool rows_maybe_overstretched_avx2(const Job& job, double ratio_squared, int row_begin,
                                   int row_end);
bool rows_maybe_overstretched_avx512(const Job& job, double ratio_squared, int row_begin,
                                     int row_end);

// rows_maybe_overstretched's test, and the least headroom min (ratio L - |d|) and the largest
// ratio L over the live springs starting on rows [row_begin, row_end): the divergence
// guard's next reference (divergence.cpp) from the same pass.
struct StretchHeadroom {
    bool maybe_longer = false;  // |d|² > ratio_squared L² for some spring
    double headroom = 0.0;      // m; +infinity without a live spring
    double scale = 0.0;         // m
};
StretchHeadroom rows_stretch_headroom_baseline(const Job& job, double ratio, double ratio_squared,
                                               int row_begin, int row_end);
StretchHeadroom rows_stretch_headroom_avx2(const Job& job, double ratio, double ratio_squared,
                                           int row_begin, int row_end);
StretchHeadroom rows_stretch_headroom_avx512(const Job& job, double ratio, double ratio_squared,
                                             int row_begin, int row_end);

// The largest error of a linearised step (implicit_euler.cpp) over the live springs starting
// on rows [row_begin, row_end) that end it longer than `ratio` rest lengths, in rest lengths:
// how far each one's force at the end, k (|d1| - L) d1 / |d1| with d1 from job.positions, is
// from what the step assumed when linearised at `start` (x y z per particle), over k L; 0
// without such a spring. Each spring's error in the general pass's operations (the same
// double), found by a vectorised test of |d1|² against ratio_squared L², a superset.
double rows_linearisation_error_baseline(const Job& job, const double* start, double ratio,
                                         double ratio_squared, int row_begin, int row_end);
double rows_linearisation_error_avx2(const Job& job, const double* start, double ratio,
                                     double ratio_squared, int row_begin, int row_end);
double rows_linearisation_error_avx512(const Job& job, const double* start, double ratio,
                                       double ratio_squared, int row_begin, int row_end);

// The divergence guard's particle sweep over interleaved arrays (x y z per particle):
// whether a position or velocity is not finite, and whether some particle may have moved
// from its reference by |x - x_ref|² >= limit_squared: every such particle is flagged, and
// some that moved at least 1/√3 of that (each component is tested on its own).
void sweep_particles_baseline(const double* x, const double* reference, const double* v,
                              std::size_t count, double limit_squared, bool& non_finite,
                              bool& moved);
void sweep_particles_avx2(const double* x, const double* reference, const double* v,
                          std::size_t count, double limit_squared, bool& non_finite, bool& moved);
void sweep_particles_avx512(const double* x, const double* reference, const double* v,
                            std::size_t count, double limit_squared, bool& non_finite, bool& moved);

}  // namespace weft::grid_kernel
