// Which build of the vectorised row kernels runs: baseline x86-64, AVX2 or AVX-512. Each
// kernel (the structured force pass's, the structured implicit solve's, the guard's sweeps)
// is compiled once per build, and every build gives the same bits (no fused multiply-add,
// IEEE operations only), so the choice is one of speed. A Simulation holds its choice among
// its options (simulation_options.h); nothing in the process chooses for it.
#pragma once

namespace weft {

enum class SimdLevel { baseline, avx2, avx512 };

// The best build this CPU runs (detected once).
SimdLevel supported_simd_level();
const char* simd_level_name(SimdLevel level);

// The build of a kernel function for `level`, or the best the CPU runs if that is lower.
template <class Function>
Function* kernel_of(SimdLevel level, Function* baseline, Function* avx2, Function* avx512) {
    if (level > supported_simd_level()) level = supported_simd_level();
    return level == SimdLevel::avx512 ? avx512 : level == SimdLevel::avx2 ? avx2 : baseline;
}

}  // namespace weft
