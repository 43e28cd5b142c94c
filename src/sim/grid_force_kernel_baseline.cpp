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

}  // namespace weft::grid_kernel
