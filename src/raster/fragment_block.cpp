#include "raster/fragment_block.h"

#include <atomic>

namespace weft::raster {

// The AVX-512 build of the block (fragment_block_avx512.cpp); null where the compiler could
// not build it.
int traverse_fragment_block_avx512(const BlockTriangle& triangle, int y, const FragmentSink& sink);
bool fragment_block_avx512_built();

namespace {

bool detect_support() {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
    return fragment_block_avx512_built() && __builtin_cpu_supports("avx512f") &&
           __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512dq");
#else
    return false;
#endif
}

const bool supported = detect_support();
std::atomic<bool> enabled{supported};

}  // namespace

bool fragment_blocks_supported() {
    return supported;
}

bool fragment_blocks_enabled() {
    return enabled.load(std::memory_order_relaxed);
}

void set_fragment_blocks(bool on) {
    enabled.store(on && supported, std::memory_order_relaxed);
}

int traverse_fragment_block(const BlockTriangle& triangle, int y, const FragmentSink& sink) {
    return traverse_fragment_block_avx512(triangle, y, sink);
}

}  // namespace weft::raster
