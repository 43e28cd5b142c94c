// The body of the structured implicit solve's row kernels, included by
// implicit_grid_kernel_*.cpp inside an anonymous namespace (internal linkage, see
// grid_force_kernel.h for why the builds must not share inline functions).
//
// The system is A v1 = b with A = M + h C + h² K (Baraff & Witkin 1998), linearised at the
// state x_k = x0 + h v_k (implicit_euler.cpp): b = g + A v_k with
// g = h f(x_k, v_k) - M (v_k - v0), the Δv form A (v1 - v_k) = g rewritten for v1. The
// setup pass forms g and the residual pass adds A v_k, which it multiplies anyway for the
// residual's scale.
//
// Gather formulation, as in the force pass: for every direction k (offset o_k) and particle
// p, the spring from p to p + o_k contributes B_k[p] (v_p - v_{p+o_k}) to (A v)_p and the
// spring from p - o_k to p contributes B_k[p - o_k] (v_p - v_{p-o_k}), with the block
// B = iso I + a aᵀ (a = √along u) stored per start particle (zero where no live spring starts).
// Every particle's sum is taken in the same order whatever the rows a thread owns, so the product
// is the same bit for bit for any split; sums over particles are taken per row in sixteen
// fixed lanes and then row by row, so they are too, and for every vector width.

#include "sim/collision/contact_filter.inl"
#include "sim/grid/deinterleave.inl"
#include "sim/integrators/implicit/symmetric_block.inl"

constexpr int sum_lanes = 16;

inline std::size_t at(const Job& job, int row) {
    return job.pad + static_cast<std::size_t>(row) * static_cast<std::size_t>(job.cols);
}

// Asks for one row of an array (cols floats from `row`) to be brought into the cache: a pass
// streams more arrays than the hardware prefetchers follow, and waited for them (below).
inline void prefetch_row(const float* row, int cols) {
    for (int c = 0; c < cols; c += 16) __builtin_prefetch(row + c);
}

// Σ a·b over one row's columns (three components), lanes fixed by column index mod 16.
double row_dot(const Field3& a, const Field3& b, std::size_t begin, int cols) {
    float lanes[sum_lanes] = {};
    const float* __restrict ax = a.x + begin;
    const float* __restrict ay = a.y + begin;
    const float* __restrict az = a.z + begin;
    const float* __restrict bx = b.x + begin;
    const float* __restrict by = b.y + begin;
    const float* __restrict bz = b.z + begin;
    int c = 0;
    for (; c + sum_lanes <= cols; c += sum_lanes)
        for (int k = 0; k < sum_lanes; ++k)
            lanes[k] += ax[c + k] * bx[c + k] + ay[c + k] * by[c + k] + az[c + k] * bz[c + k];
    for (int k = 0; c + k < cols; ++k)
        lanes[k] += ax[c + k] * bx[c + k] + ay[c + k] * by[c + k] + az[c + k] * bz[c + k];
    double sum = 0.0;
    for (int k = 0; k < sum_lanes; ++k) sum += static_cast<double>(lanes[k]);
    return sum;
}

// The largest |z|² over one row's particles (three components), in sixteen lanes as
// row_dot does, so the loop vectorises; a maximum is exact in any order.
double row_largest_square(const Field3& z, std::size_t begin, int cols) {
    float lanes[sum_lanes] = {};
    const float* __restrict x = z.x + begin;
    const float* __restrict y = z.y + begin;
    const float* __restrict w = z.z + begin;
    int c = 0;
    for (; c + sum_lanes <= cols; c += sum_lanes)
        for (int k = 0; k < sum_lanes; ++k) {
            const float square = x[c + k] * x[c + k] + y[c + k] * y[c + k] + w[c + k] * w[c + k];
            lanes[k] = square > lanes[k] ? square : lanes[k];
        }
    for (int k = 0; c + k < cols; ++k) {
        const float square = x[c + k] * x[c + k] + y[c + k] * y[c + k] + w[c + k] * w[c + k];
        lanes[k] = square > lanes[k] ? square : lanes[k];
    }
    float largest = 0.0f;
    for (float lane : lanes) largest = lane > largest ? lane : largest;
    return static_cast<double>(largest);
}

// The spring term of one direction over a row: w[p] = B[p] (v_p - v_{p+o}) for the spring
// that starts at each particle p (zero where none does: its block is zero), B = iso I + a aᵀ.
// Every stream is its own restrict pointer, so the loop vectorises.
void flux_row(const float* __restrict iso, const float* __restrict ax, const float* __restrict ay,
              const float* __restrict az, const float* __restrict x, const float* __restrict y,
              const float* __restrict z, std::ptrdiff_t o, float* __restrict wx,
              float* __restrict wy, float* __restrict wz, int cols) {
    for (int c = 0; c < cols; ++c) {
        const float fx = x[c] - x[c + o], fy = y[c] - y[c + o], fz = z[c] - z[c + o];
        const float f_axial = ax[c] * fx + ay[c] * fy + az[c] * fz;
        wx[c] = iso[c] * fx + f_axial * ax[c];
        wy[c] = iso[c] * fy + f_axial * ay[c];
        wz[c] = iso[c] * fz + f_axial * az[c];
    }
}

// y = mask (m v + Σ_k (w_k - w'_k)) over a row, for the K directions of the stencil: w_k the
// term of the spring that starts at each particle and w'_k that of the one that ends there
// (B[p - o] (v_p - v_{p-o}) is exactly -w_k[p - o], negation being exact). One loop writes y
// once, where a loop a direction read and wrote y again each time; each particle's sum is
// still taken m v first, then the directions in order, so the bits are the same.
template <int K>
void accumulate_row(const float* __restrict mass, const float* __restrict x,
                    const float* __restrict y, const float* __restrict z,
                    const float* const (&w)[3][max_directions],
                    const float* const (&w_end)[3][max_directions], const float* __restrict mask,
                    float* __restrict yx, float* __restrict yy, float* __restrict yz, int cols) {
    // The terms live in the band's ring and v, m and the mask in their own arrays, never in
    // y's: no iteration reads what another writes.
#pragma GCC ivdep
    for (int c = 0; c < cols; ++c) {
        float sx = mass[c] * x[c], sy = mass[c] * y[c], sz = mass[c] * z[c];
        for (int k = 0; k < K; ++k) {
            sx += w[0][k][c] - w_end[0][k][c];
            sy += w[1][k][c] - w_end[1][k][c];
            sz += w[2][k][c] - w_end[2][k][c];
        }
        yx[c] = sx * mask[c];
        yy[c] = sy * mask[c];
        yz[c] = sz * mask[c];
    }
}

// y = A v over the rows of a band, one row at a time, in order. Each spring's term is
// computed once, at its start row, and kept in a ring of the last three rows (a spring
// reaches at most two rows down) until the rows it ends on have used it; the band computes
// the two rows above it again, so bands are independent and the arithmetic of every
// particle is the same whatever the split.
class BandProduct;
float* band_scratch(int cols, int products);

class BandProduct {
  public:
    static constexpr int ring_rows = 3;
    static constexpr int column_padding = 2;  // |dc| <= 2: the ends of other rows read zeros

    // Floats of scratch one band product needs: the ring, and a row of zeros (three
    // components) for the springs that would start above the grid.
    static std::size_t scratch_floats(int cols) {
        return (static_cast<std::size_t>(ring_rows) * max_directions + 1) * 3 *
               (static_cast<std::size_t>(cols) + 2 * column_padding);
    }

    // `filtered`: the product of the filtered system, S A v (every pass of the solve); the
    // plain A v is for the contacts' impulses after it.
    BandProduct(const Job& job, const Field3& v, int begin, float* scratch, bool filtered = true)
        : job_(job),
          v_(v),
          ring_(scratch),
          padded_(static_cast<std::size_t>(job.cols) + 2 * column_padding),
          filter_contacts_(filtered && job.has_contacts) {
        std::fill(ring_, ring_ + scratch_floats(job.cols), 0.0f);
        zero_row_ = ring_ + static_cast<std::size_t>(ring_rows) * max_directions * 3 * padded_ +
                    column_padding;
        for (int row = std::max(0, begin - 2); row < begin; ++row) compute_fluxes(row);
    }

    // y over row `row` (the band's rows in order), masked to zero on pinned particles.
    void row(int row, const Field3& y) {
        compute_fluxes(row);
        const std::size_t base = at(job_, row);
        static_assert(max_directions == 6, "one case a direction count");
        switch (job_.direction_count) {
            case 0:
                accumulate<0>(row, base, y);
                break;
            case 1:
                accumulate<1>(row, base, y);
                break;
            case 2:
                accumulate<2>(row, base, y);
                break;
            case 3:
                accumulate<3>(row, base, y);
                break;
            case 4:
                accumulate<4>(row, base, y);
                break;
            case 5:
                accumulate<5>(row, base, y);
                break;
            default:
                accumulate<6>(row, base, y);
                break;
        }
        if (filter_contacts_)
            filter_contacts_row(job_.contact_normal.x + base, job_.contact_normal.y + base,
                                job_.contact_normal.z + base, y.x + base, y.y + base, y.z + base,
                                job_.cols);
    }

  private:
    // accumulate_row over the first K directions' terms for this row.
    template <int K>
    void accumulate(int row, std::size_t base, const Field3& y) const {
        const float* w[3][max_directions] = {};
        const float* w_end[3][max_directions] = {};
        for (int k = 0; k < K; ++k) {
            const DirectionTerms& d = job_.directions[k];
            // Springs that would start above the grid read the row of zeros.
            const int from_row = row - d.row_step;
            const float* here = flux(k, row);
            const float* there = (from_row >= 0 ? flux(k, from_row) : zero_row_) - d.col_step;
            for (std::size_t a = 0; a < 3; ++a) {
                w[a][k] = here + a * padded_;
                w_end[a][k] = there + a * padded_;
            }
        }
        accumulate_row<K>(job_.mass_diagonal + base, v_.x + base, v_.y + base, v_.z + base, w,
                          w_end, job_.free + base, y.x + base, y.y + base, y.z + base, job_.cols);
    }
    float* flux(int k, int row) const {
        return ring_ +
               (static_cast<std::size_t>(row % ring_rows) * max_directions + k) * 3 * padded_ +
               column_padding;
    }
    void compute_fluxes(int row) {
        const std::size_t base = at(job_, row);
        const std::size_t next = base + static_cast<std::size_t>(job_.cols);
        for (int k = 0; k < job_.direction_count; ++k) {
            const DirectionTerms& d = job_.directions[k];
            // The next row's terms, four streams a direction, are asked for from memory now:
            // the hardware prefetchers do not follow two dozen streams (same arithmetic).
            for (const float* terms : {d.iso, d.axial_x, d.axial_y, d.axial_z})
                prefetch_row(terms + next, job_.cols);
            const std::ptrdiff_t o =
                static_cast<std::ptrdiff_t>(d.row_step) * job_.cols + d.col_step;
            float* w = flux(k, row);
            flux_row(d.iso + base, d.axial_x + base, d.axial_y + base, d.axial_z + base,
                     v_.x + base, v_.y + base, v_.z + base, o, w, w + padded_, w + 2 * padded_,
                     job_.cols);
        }
    }

    const Job& job_;
    const Field3& v_;
    float* ring_;
    std::size_t padded_;
    const float* zero_row_ = nullptr;
    bool filter_contacts_;
};

// Scratch for `products` band products at once on this thread: grown on first use, so no
// step allocates once the first has run (the pool's threads are persistent).
float* band_scratch(int cols, int products) {
    thread_local std::vector<float> scratch;
    const std::size_t needed =
        BandProduct::scratch_floats(cols) * static_cast<std::size_t>(products);
    if (scratch.size() < needed) scratch.resize(needed);
    return scratch.data();
}

// z = P r over n particles: a symmetric 3x3 block (xx yy zz xy xz yz) times r per particle.
void multiply_blocks(const float* __restrict xx, const float* __restrict yy,
                     const float* __restrict zz, const float* __restrict xy,
                     const float* __restrict xz, const float* __restrict yz,
                     const float* __restrict rx, const float* __restrict ry,
                     const float* __restrict rz, float* __restrict zx, float* __restrict zy,
                     float* __restrict z_z, int n) {
    for (int c = 0; c < n; ++c) {
        zx[c] = xx[c] * rx[c] + xy[c] * ry[c] + xz[c] * rz[c];
        zy[c] = xy[c] * rx[c] + yy[c] * ry[c] + yz[c] * rz[c];
        z_z[c] = xz[c] * rx[c] + yz[c] * ry[c] + zz[c] * rz[c];
    }
}

// z = P r over one row.
void precondition_row(const Job& job, int row) {
    const std::size_t base = at(job, row);
    const auto& inverse = job.inverse_diagonal;
    multiply_blocks(inverse[0] + base, inverse[1] + base, inverse[2] + base, inverse[3] + base,
                    inverse[4] + base, inverse[5] + base, job.residual.x + base,
                    job.residual.y + base, job.residual.z + base, job.preconditioned.x + base,
                    job.preconditioned.y + base, job.preconditioned.z + base, job.cols);
}

// One direction's share of h² K + h C for the springs that start on a row, from the
// per-component positions of their two ends (here, there): each stream its own restrict
// pointer and no branch, so the loop vectorises.
void spring_terms_row(const double* __restrict rest, const double* __restrict hx,
                      const double* __restrict hy, const double* __restrict hz,
                      const double* __restrict tx, const double* __restrict ty,
                      const double* __restrict tz, double stiffness, double damping, double h,
                      float* __restrict iso, float* __restrict ax, float* __restrict ay,
                      float* __restrict az, int cols) {
    for (int c = 0; c < cols; ++c) {
        const double rest_length = rest[c];
        const double ex = tx[c] - hx[c], ey = ty[c] - hy[c], ez = tz[c] - hz[c];
        const double length = std::sqrt(ex * ex + ey * ey + ez * ez);
        // A dead spring or coincident ends: no terms. As in the force pass
        // (grid_force_kernel.inl), `none` is 0 or 1, so a live spring divides by l exactly
        // and a masked lane by 1.
        const double none = length > 0.0 ? 0.0 : 1.0;
        const double live = (rest_length >= 0.0 ? 1.0 : 0.0) * (1.0 - none);
        const double inverse_length = live / (length + none);
        // The transverse stiffness k (1 - L/l), clamped at 0 for a compressed spring
        // (negative, it would make A indefinite; see implicit_euler.cpp).
        const double stretch = 1.0 - rest_length * inverse_length;
        const double transverse = stiffness * (stretch > 0.0 ? stretch : 0.0);
        iso[c] = static_cast<float>(live * (h * h * transverse));
        // along = h² (k - transverse) + h c >= 0 (transverse <= k); a = √along u.
        const double along = live * (h * h * (stiffness - transverse) + h * damping);
        const double axial = std::sqrt(along > 0.0 ? along : 0.0) * inverse_length;
        ax[c] = static_cast<float>(ex * axial);
        ay[c] = static_cast<float>(ey * axial);
        az[c] = static_cast<float>(ez * axial);
    }
}

void setup_rows(const Job& job, int begin, int end, double warm_start) {
    const double h = job.dt;
    const int cols = job.cols;
    // Positions stream through a ring of three rows in per-component arrays (a spring reaches
    // at most two rows down), padded by two columns either side so that a spring's other
    // end is always a plain offset; what the padding holds is never used (no spring there).
    constexpr int ring_padding = 2;
    const std::size_t padded = static_cast<std::size_t>(cols) + 2 * ring_padding;
    thread_local std::vector<double> ring;  // grown once: no step allocates
    if (ring.size() < 9 * padded) ring.assign(9 * padded, 0.0);
    auto ring_row = [&](int row) {
        return ring.data() + static_cast<std::size_t>(row % 3) * 3 * padded + ring_padding;
    };
    auto load = [&](int row) {
        double* x = ring_row(row);
        deinterleave(job.positions + 3 * static_cast<std::size_t>(row) * cols, x, x + padded,
                     x + 2 * padded, static_cast<std::size_t>(cols));
    };
    for (int row = begin; row < std::min(begin + 2, job.rows); ++row) load(row);
    // The springs that start on these rows: their blocks of h² K + h C.
    for (int row = begin; row < end; ++row) {
        if (row + 2 < job.rows) load(row + 2);
        const std::size_t base = at(job, row);
        const std::size_t first = static_cast<std::size_t>(row) * static_cast<std::size_t>(cols);
        const double* here = ring_row(row);
        for (int k = 0; k < job.direction_count; ++k) {
            const DirectionTerms& d = job.directions[k];
            float* __restrict iso = d.iso + base;
            float* __restrict ax = d.axial_x + base;
            float* __restrict ay = d.axial_y + base;
            float* __restrict az = d.axial_z + base;
            if (row + d.row_step >= job.rows) {  // no spring of this direction starts here
                for (float* terms : {iso, ax, ay, az}) std::fill(terms, terms + cols, 0.0f);
                continue;
            }
            const double* there = ring_row(row + d.row_step) + d.col_step;
            spring_terms_row(d.rest_lengths + first, here, here + padded, here + 2 * padded, there,
                             there + padded, there + 2 * padded, d.stiffness, d.damping, h, iso, ax,
                             ay, az, cols);
        }
        // g, v_s, the guess, the mass diagonal and the free mask.
        for (int c = 0; c < cols; ++c) {
            const std::size_t p = first + static_cast<std::size_t>(c);
            const std::size_t i = base + static_cast<std::size_t>(c);
            const bool is_free = job.inverse_masses[p] != 0.0;
            const double m = job.masses[p];
            job.free[i] = is_free ? 1.0f : 0.0f;
            job.mass_diagonal[i] = static_cast<float>(m + h * job.air_drag);
            const double* v = job.velocities + 3 * p;
            const double* v0 = job.initial_velocities + 3 * p;
            const double* from = job.start_velocities + 3 * p;
            const double* f = job.forces + 3 * p;
            float* g[3] = {job.rhs_change.x, job.rhs_change.y, job.rhs_change.z};
            float* vs[3] = {job.start.x, job.start.y, job.start.z};
            float* guess[3] = {job.solution.x, job.solution.y, job.solution.z};
            const float* change[3] = {job.guess_change.x, job.guess_change.y, job.guess_change.z};
            for (int axis = 0; axis < 3; ++axis) {
                g[axis][i] =
                    is_free ? static_cast<float>(h * f[axis] - m * (v[axis] - v0[axis])) : 0.0f;
                vs[axis][i] = is_free ? static_cast<float>(from[axis]) : 0.0f;
                guess[axis][i] =
                    is_free ? static_cast<float>(from[axis] + warm_start * change[axis][i]) : 0.0f;
            }
        }
    }
}

// Adds the diagonal share of one direction's blocks, iso I + a aᵀ, over a row into six
// per-component double accumulators (each its own restrict parameter, so it vectorises).
void add_diagonal_terms(const float* __restrict iso, const float* __restrict ax,
                        const float* __restrict ay, const float* __restrict az,
                        double* __restrict xx, double* __restrict yy, double* __restrict zz,
                        double* __restrict xy, double* __restrict xz, double* __restrict yz,
                        int cols) {
    for (int c = 0; c < cols; ++c) {
        const double i = iso[c];
        const double x = ax[c], y = ay[c], z = az[c];
        xx[c] += i + x * x;
        yy[c] += i + y * y;
        zz[c] += i + z * z;
        xy[c] += x * y;
        xz[c] += x * z;
        yz[c] += y * z;
    }
}

// Each particle's diagonal block of A over a row, and its inverse, the preconditioner. Both
// are taken in double (symmetric_block.inl): the block is dominated by rank-one spring
// terms, so it can be far from the identity. Per-component loops, so they vectorise.
void diagonal_row(const Job& job, int row, double* __restrict block) {
    const std::size_t base = at(job, row);
    const int cols = job.cols;
    for (int c = 0; c < cols; ++c) {
        const double m = job.mass_diagonal[base + c];
        block[c] = m;
        block[cols + c] = m;
        block[2 * cols + c] = m;
        block[3 * cols + c] = 0.0;
        block[4 * cols + c] = 0.0;
        block[5 * cols + c] = 0.0;
    }
    // The spring that starts here, then the one that ends here, direction by direction.
    for (int k = 0; k < job.direction_count; ++k) {
        const DirectionTerms& d = job.directions[k];
        const std::ptrdiff_t o = static_cast<std::ptrdiff_t>(d.row_step) * cols + d.col_step;
        for (const std::ptrdiff_t start : {std::ptrdiff_t{0}, -o}) {
            const std::size_t from =
                static_cast<std::size_t>(static_cast<std::ptrdiff_t>(base) + start);
            add_diagonal_terms(d.iso + from, d.axial_x + from, d.axial_y + from, d.axial_z + from,
                               block, block + cols, block + 2 * cols, block + 3 * cols,
                               block + 4 * cols, block + 5 * cols, cols);
        }
    }
    const float* __restrict free = job.free + base;
    for (int c = 0; c < cols; ++c) {
        const double a[6] = {block[c],
                             block[cols + c],
                             block[2 * cols + c],
                             block[3 * cols + c],
                             block[4 * cols + c],
                             block[5 * cols + c]};
        double inverse[6];
        if (job.has_contacts) {
            // A particle held on a surface along n: the block of the filtered system, S D S,
            // is singular along n; its pseudo-inverse, (S D S + n nᵀ)⁻¹ - n nᵀ, is the
            // preconditioner there. (S D⁻¹ S instead, where the sheet is tilted against the
            // surface, keeps the large 1/m of the sheet's soft normal: CG ran to 300
            // iterations.) With no contact, n = 0 and this is D⁻¹ exactly.
            const double n[3] = {job.contact_normal.x[base + c], job.contact_normal.y[base + c],
                                 job.contact_normal.z[base + c]};
            double projected[6] = {a[0], a[1], a[2], a[3], a[4], a[5]};
            project_symmetric_block(projected, n);
            add_outer_product(projected, n, 1.0);
            invert_symmetric_block(projected, inverse);
            add_outer_product(inverse, n, -1.0);
        } else {
            invert_symmetric_block(a, inverse);
        }
        for (int e = 0; e < 6; ++e) {
            job.diagonal[e][base + c] = static_cast<float>(a[e]) * free[c];
            job.inverse_diagonal[e][base + c] = static_cast<float>(inverse[e]) * free[c];
        }
    }
}

// r = b - y over a row (y already in r).
void subtract_from_rhs_row(const Job& job, int row) {
    const std::size_t base = at(job, row);
    for (int c = 0; c < job.cols; ++c) {
        const std::size_t i = base + static_cast<std::size_t>(c);
        job.residual.x[i] = job.rhs.x[i] - job.residual.x[i];
        job.residual.y[i] = job.rhs.y[i] - job.residual.y[i];
        job.residual.z[i] = job.rhs.z[i] - job.residual.z[i];
    }
}

// b = g + y (y = A v_s, filtered, already in r) where v_s = v_k, else b = g (v_k = 0), over a
// row; then r = b - y, the residual at v_s.
void form_rhs_row(const Job& job, int row) {
    const std::size_t base = at(job, row);
    const float with_start = job.linearised_at_start ? 1.0f : 0.0f;
    for (int c = 0; c < job.cols; ++c) {
        const std::size_t i = base + static_cast<std::size_t>(c);
        job.rhs.x[i] = job.rhs_change.x[i] + with_start * job.residual.x[i];
        job.rhs.y[i] = job.rhs_change.y[i] + with_start * job.residual.y[i];
        job.rhs.z[i] = job.rhs_change.z[i] + with_start * job.residual.z[i];
    }
    subtract_from_rhs_row(job, row);
}

// The pair of rows starting at `row` (even) summed into their coarse nodes, in a fixed order
// (row, then row + 1; column 2C, then 2C + 1), and each node's own correction D_c⁻¹ r_c.
void restrict_row_pair(const Job& job, int row) {
    const std::size_t first = at(job, row);
    const bool second_row = row + 1 < job.rows;
    const std::size_t second = second_row ? at(job, row + 1) : first;
    const float weight_second = second_row ? 1.0f : 0.0f;
    const float* components[3][2] = {{job.residual.x + first, job.residual.x + second},
                                     {job.residual.y + first, job.residual.y + second},
                                     {job.residual.z + first, job.residual.z + second}};
    const int cols = job.cols;
    for (int col = 0; 2 * col < cols; ++col) {
        const std::size_t node =
            static_cast<std::size_t>(row / 2) * static_cast<std::size_t>(job.coarse_cols) +
            static_cast<std::size_t>(col);
        const int c = 2 * col;
        const bool second_col = c + 1 < cols;
        double sum[3];
        for (int a = 0; a < 3; ++a) {
            const float* upper = components[a][0];
            const float* lower = components[a][1];
            double s = static_cast<double>(upper[c]);
            if (second_col) s += static_cast<double>(upper[c + 1]);
            s += static_cast<double>(weight_second * lower[c]);
            if (second_col) s += static_cast<double>(weight_second * lower[c + 1]);
            sum[a] = s;
            job.coarse_residual[3 * node + a] = s;
        }
        multiply_symmetric_block(job.coarse_inverse + 6 * node, sum,
                                 job.coarse_correction + 3 * node);
    }
}

// After row `row`'s residual is final: the pair it ends, if it ends one.
void restrict_if_pair_done(const Job& job, int row) {
    if (job.coarse_cols > 0 && (row % 2 == 1 || row + 1 == job.rows))
        restrict_row_pair(job, row - row % 2);
}

void residual_rows(const Job& job, int begin, int end, RowSums sums) {
    float* scratch = band_scratch(job.cols, 2);
    thread_local std::vector<double> block;  // grown once: no step allocates
    block.resize(6 * static_cast<std::size_t>(job.cols));
    BandProduct at_start(job, job.start, begin, scratch);
    BandProduct at_guess(job, job.solution, begin, scratch + BandProduct::scratch_floats(job.cols));
    for (int row = begin; row < end; ++row) {
        diagonal_row(job, row, block.data());
        const std::size_t base = at(job, row);
        // b from A v_s, and |b - A v_s|² (the residual's scale); then r at the guess.
        at_start.row(row, job.residual);
        form_rhs_row(job, row);
        sums.third[row] = row_dot(job.residual, job.residual, base, job.cols);
        at_guess.row(row, job.residual);
        subtract_from_rhs_row(job, row);
        precondition_row(job, row);
        sums.first[row] = row_dot(job.residual, job.preconditioned, base, job.cols);
        sums.second[row] = row_dot(job.residual, job.residual, base, job.cols);
        sums.largest[row] = row_largest_square(job.preconditioned, base, job.cols);
        restrict_if_pair_done(job, row);
    }
}

// out += s b over n floats.
void add_scaled_in_place(float* __restrict out, float s, const float* __restrict b, int n) {
    for (int c = 0; c < n; ++c) out[c] += s * b[c];
}

// out = a + s out over n floats.
void scale_and_add(float* __restrict out, const float* __restrict a, float s, int n) {
    for (int c = 0; c < n; ++c) out[c] = a[c] + s * out[c];
}

// The next search direction and its product without a second pass over the rows:
// d = z + β d and, since A is linear, q = A d = A z + β q. Only z of the neighbouring rows
// is read, and it is complete (the update pass wrote it before this pass began).
void direction_rows(const Job& job, int begin, int end, float beta, RowSums sums) {
    BandProduct applied(job, job.preconditioned, begin, band_scratch(job.cols, 1));
    for (int row = begin; row < end; ++row) {
        const std::size_t base = at(job, row);
        const int cols = job.cols;
        applied.row(row, job.applied);
        scale_and_add(job.direction.x + base, job.preconditioned.x + base, beta, cols);
        scale_and_add(job.direction.y + base, job.preconditioned.y + base, beta, cols);
        scale_and_add(job.direction.z + base, job.preconditioned.z + base, beta, cols);
        scale_and_add(job.product.x + base, job.applied.x + base, beta, cols);
        scale_and_add(job.product.y + base, job.applied.y + base, beta, cols);
        scale_and_add(job.product.z + base, job.applied.z + base, beta, cols);
        sums.first[row] = row_dot(job.direction, job.product, base, cols);
    }
}

void smooth_rows(const Job& job, int begin, int end, float omega) {
    for (int row = begin; row < end; ++row) {
        const std::size_t base = at(job, row);
        precondition_row(job, row);
        add_scaled_in_place(job.solution.x + base, omega, job.preconditioned.x + base, job.cols);
        add_scaled_in_place(job.solution.y + base, omega, job.preconditioned.y + base, job.cols);
        add_scaled_in_place(job.solution.z + base, omega, job.preconditioned.z + base, job.cols);
    }
}

void unfiltered_product_rows(const Job& job, int begin, int end) {
    BandProduct plain(job, job.direction, begin, band_scratch(job.cols, 1), false);
    for (int row = begin; row < end; ++row) plain.row(row, job.applied);
}

void update_rows(const Job& job, int begin, int end, float alpha, RowSums sums) {
    for (int row = begin; row < end; ++row) {
        const std::size_t base = at(job, row);
        add_scaled_in_place(job.solution.x + base, alpha, job.direction.x + base, job.cols);
        add_scaled_in_place(job.solution.y + base, alpha, job.direction.y + base, job.cols);
        add_scaled_in_place(job.solution.z + base, alpha, job.direction.z + base, job.cols);
        add_scaled_in_place(job.residual.x + base, -alpha, job.product.x + base, job.cols);
        add_scaled_in_place(job.residual.y + base, -alpha, job.product.y + base, job.cols);
        add_scaled_in_place(job.residual.z + base, -alpha, job.product.z + base, job.cols);
        if (job.flexible)
            sums.third[row] = row_dot(job.residual, job.preconditioned, base, job.cols);
        precondition_row(job, row);
        sums.first[row] = row_dot(job.residual, job.preconditioned, base, job.cols);
        sums.second[row] = row_dot(job.residual, job.residual, base, job.cols);
        sums.largest[row] = row_largest_square(job.preconditioned, base, job.cols);
        restrict_if_pair_done(job, row);
    }
}
