// The structured force pass's row kernel for baseline x86-64 (SSE2), the build any x86-64
// CPU runs.
#define WEFT_KERNEL_SUFFIX baseline
#include "sim/grid/grid_force_kernel_build.inl"
