// The structured implicit solve's row kernels for baseline x86-64 (SSE2): four floats per
// instruction.
#define WEFT_KERNEL_SUFFIX baseline
#include "sim/integrators/implicit/implicit_grid_kernel_build.inl"
