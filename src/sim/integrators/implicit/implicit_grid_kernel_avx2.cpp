// The structured implicit solve's row kernels for AVX2 (-mavx2): eight floats per instruction.
#define WEFT_KERNEL_SUFFIX avx2
#include "sim/integrators/implicit/implicit_grid_kernel_build.inl"
