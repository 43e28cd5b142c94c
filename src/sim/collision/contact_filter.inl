// The contact filter of the implicit solve, included inside an anonymous namespace by each
// file that uses it (the kernel builds and the coarse levels; see grid_force_kernel.h for
// why the kernel builds must not share inline functions). Plain arithmetic, no includes.
//
// y -= n (n · y) over n particles: the contact filter S = I - n nᵀ (Baraff & Witkin's
// constraint filter for a particle held on a solid's surface along its normal n). Where a
// particle has no contact n is zero and y is left exactly as it was.
void filter_contacts_row(const float* __restrict nx, const float* __restrict ny,
                         const float* __restrict nz, float* __restrict yx, float* __restrict yy,
                         float* __restrict yz, int n) {
    for (int c = 0; c < n; ++c) {
        const float along = nx[c] * yx[c] + ny[c] * yy[c] + nz[c] * yz[c];
        yx[c] -= along * nx[c];
        yy[c] -= along * ny[c];
        yz[c] -= along * nz[c];
    }
}
