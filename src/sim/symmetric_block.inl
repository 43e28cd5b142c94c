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
