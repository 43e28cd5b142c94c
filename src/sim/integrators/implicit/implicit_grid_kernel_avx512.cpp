// The structured implicit solve's row kernels for AVX-512 (-mavx512f ...): sixteen floats per
// instruction.
#define WEFT_KERNEL_SUFFIX avx512
#include "sim/integrators/implicit/implicit_grid_kernel_build.inl"
