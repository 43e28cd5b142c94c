// Symmetric 3x3 blocks stored as six numbers, xx yy zz xy xz yz: the inverse by cofactors and
// the product with a vector. Included inside an anonymous namespace by each file that uses it
// (the implicit solve's kernel builds and its coarse levels), so every build keeps its own
// copy (see grid_force_kernel.h for why the kernel builds must not share inline functions).
// Plain arithmetic, no includes.

// out = a⁻¹, or zeros where a is singular or not positive definite (a pinned particle's).
inline void invert_symmetric_block(const double* a, double* out) {
    const double xx = a[0], yy = a[1], zz = a[2], xy = a[3], xz = a[4], yz = a[5];
    const double c_xx = yy * zz - yz * yz;
    const double c_xy = xz * yz - xy * zz;
    const double c_xz = xy * yz - xz * yy;
    const double determinant = xx * c_xx + xy * c_xy + xz * c_xz;
    // 1/det, or 0, without a branch (so loops of inverses vectorise): a singular block
    // divides 0 by 1.
    const double invertible = determinant > 0.0 ? 1.0 : 0.0;
    const double inverse = invertible / (invertible * determinant + (1.0 - invertible));
    out[0] = c_xx * inverse;
    out[1] = (xx * zz - xz * xz) * inverse;
    out[2] = (xx * yy - xy * xy) * inverse;
    out[3] = c_xy * inverse;
    out[4] = c_xz * inverse;
    out[5] = (xy * xz - xx * yz) * inverse;
}

// out = a v.
inline void multiply_symmetric_block(const double* a, const double* v, double* out) {
    out[0] = a[0] * v[0] + a[3] * v[1] + a[4] * v[2];
    out[1] = a[3] * v[0] + a[1] * v[1] + a[5] * v[2];
    out[2] = a[4] * v[0] + a[5] * v[1] + a[2] * v[2];
}

// a = S a S with S = I - n nᵀ (n unit, or zero: then a is left exactly as it was): the block
// seen from the plane normal to n, for a particle whose velocity along n is held.
inline void project_symmetric_block(double* a, const double* n) {
    double an[3];  // a n
    multiply_symmetric_block(a, n, an);
    const double n_a_n = n[0] * an[0] + n[1] * an[1] + n[2] * an[2];  // nᵀ a n
    // S a S = a - n (a n)ᵀ - (a n) nᵀ + (nᵀ a n) n nᵀ, entry by entry.
    constexpr int row[6] = {0, 1, 2, 0, 0, 1};
    constexpr int col[6] = {0, 1, 2, 1, 2, 2};
    for (int e = 0; e < 6; ++e)
        a[e] =
            a[e] - n[row[e]] * an[col[e]] - an[row[e]] * n[col[e]] + n_a_n * n[row[e]] * n[col[e]];
}

// a += scale n nᵀ.
inline void add_outer_product(double* a, const double* n, double scale) {
    a[0] += scale * n[0] * n[0];
    a[1] += scale * n[1] * n[1];
    a[2] += scale * n[2] * n[2];
    a[3] += scale * n[0] * n[1];
    a[4] += scale * n[0] * n[2];
    a[5] += scale * n[1] * n[2];
}
