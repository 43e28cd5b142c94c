// One build of the structured force pass's row kernel: the kernel's body (internal linkage,
// see grid_force_kernel.h) and its entry points, named with the build's suffix. Each
// grid_force_kernel_<suffix>.cpp defines WEFT_KERNEL_SUFFIX and includes this file; CMake
// compiles each with its own instruction set. None uses FMA: -ffp-contract=off keeps every
// product and sum rounded alike, so every build gives the same bits.
#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "sim/grid/grid_force_kernel.h"

#define WEFT_KERNEL_JOIN(name, suffix) name##_##suffix
#define WEFT_KERNEL_NAME(name, suffix) WEFT_KERNEL_JOIN(name, suffix)

namespace weft::grid_kernel {
namespace {
#include "sim/grid/grid_force_kernel.inl"
}  // namespace

SweepFlags WEFT_KERNEL_NAME(force_rows, WEFT_KERNEL_SUFFIX)(const Job& job, int row_begin,
                                                            int row_end, double* scratch) {
    return force_rows(job, row_begin, row_end, scratch);
}

bool WEFT_KERNEL_NAME(rows_maybe_overstretched, WEFT_KERNEL_SUFFIX)(const Job& job,
                                                                    double ratio_squared,
                                                                    int row_begin, int row_end) {
    return rows_maybe_overstretched(job, ratio_squared, row_begin, row_end);
}

StretchHeadroom WEFT_KERNEL_NAME(rows_stretch_headroom,
                                 WEFT_KERNEL_SUFFIX)(const Job& job, double ratio,
                                                     double ratio_squared, int row_begin,
                                                     int row_end) {
    return rows_stretch_headroom(job, ratio, ratio_squared, row_begin, row_end);
}

double WEFT_KERNEL_NAME(rows_linearisation_error,
                        WEFT_KERNEL_SUFFIX)(const Job& job, const double* start, double ratio,
                                            double ratio_squared, int row_begin, int row_end) {
    return rows_linearisation_error(job, start, ratio, ratio_squared, row_begin, row_end);
}

void WEFT_KERNEL_NAME(sweep_particles, WEFT_KERNEL_SUFFIX)(const double* x, const double* reference,
                                                           const double* v, std::size_t count,
                                                           double limit_squared, bool& non_finite,
                                                           bool& moved) {
    sweep_particles(x, reference, v, count, limit_squared, non_finite, moved);
}

}  // namespace weft::grid_kernel
