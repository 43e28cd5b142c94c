// The structured force pass's row kernel for AVX2 (-mavx2; see CMakeLists.txt): four doubles
// per instruction.
#define WEFT_KERNEL_SUFFIX avx2
#include "sim/grid/grid_force_kernel_build.inl"
