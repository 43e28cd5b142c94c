// The structured force pass's row kernel, compiled for AVX2 (-mavx2; see CMakeLists.txt).
// No FMA: -ffp-contract=off keeps every product and sum rounded as in the baseline build, so
// both builds give the same bits.
#include <cmath>

#include "sim/grid_force_kernel.h"

namespace weft::grid_kernel {
namespace {
#include "sim/grid_force_kernel.inl"
}  // namespace

void force_rows_avx2(const Job& job, int row_begin, int row_end, double* scratch) {
    force_rows(job, row_begin, row_end, scratch);
}

bool rows_maybe_overstretched_avx2(const Job& job, double ratio_squared, int row_begin,
                                   int row_end) {
    return rows_maybe_overstretched(job, ratio_squared, row_begin, row_end);
}

void sweep_particles_avx2(const double* x, const double* reference, const double* v,
                          std::size_t count, double limit_squared, bool& non_finite, bool& moved) {
    sweep_particles(x, reference, v, count, limit_squared, non_finite, moved);
}

}  // namespace weft::grid_kernel
