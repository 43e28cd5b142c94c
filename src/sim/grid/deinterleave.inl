// Interleaved x y z into three per-component arrays: a function of its own, with
// non-overlapping arguments, so it vectorises. Included inside an anonymous namespace by the
// kernel bodies that stream rows of Vec3 (grid_force_kernel.inl, implicit_grid_kernel.inl),
// so every build keeps its own copy (see grid_force_kernel.h). Plain arithmetic, no includes.
inline void deinterleave(const double* __restrict xyz, double* __restrict x, double* __restrict y,
                         double* __restrict z, std::size_t count) {
    for (std::size_t c = 0; c < count; ++c) {
        x[c] = xyz[3 * c];
        y[c] = xyz[3 * c + 1];
        z[c] = xyz[3 * c + 2];
    }
}
