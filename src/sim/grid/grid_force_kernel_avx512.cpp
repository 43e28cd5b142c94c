// The structured force pass's row kernel for AVX-512 (-mavx512f -mavx512vl -mavx512dq,
// 512-bit vectors; see CMakeLists.txt): eight doubles per instruction. On Zen 4, which runs a
// 512-bit operation as two 256-bit halves, it is still about 15 % faster than the AVX2 build
// per step (docs/performance.md) — presumably because half the instructions for the same
// work keep twice as many springs in flight in the out-of-order window, which the latency of
// the square root and the division otherwise fill.
#define WEFT_KERNEL_SUFFIX avx512
#include "sim/grid/grid_force_kernel_build.inl"
