// The structured force pass's row kernel, compiled for baseline x86-64 (SSE2).
#include <cmath>

#include "sim/grid_force_kernel.h"

namespace weft::grid_kernel {
namespace {
#include "sim/grid_force_kernel.inl"
}  // namespace

void force_rows_baseline(const Job& job, int row_begin, int row_end, double* scratch) {
    force_rows(job, row_begin, row_end, scratch);
}

bool rows_maybe_overstretched_baseline(const Job& job, double ratio_squared, int row_begin,
                                       int row_end) {
    return rows_maybe_overstretched(job, ratio_squared, row_begin, row_end);
}

void sweep_particles_baseline(const double* x, const double* reference, const double* v,
                              std::size_t count, double limit_squared, bool& non_finite,
                              bool& moved) {
    sweep_particles(x, reference, v, count, limit_squared, non_finite, moved);
}

}  // namespace weft::grid_kernel
