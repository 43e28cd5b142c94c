// Which vector instructions the rasterizer's hot loops use.
//
// The library is built for any x86-64; the block traversal of small triangles
// (fragment_block.h) and the batched lighting (surface_shading.h) are also built with
// AVX-512, and those builds run where the CPU has it. Both builds compute every value alike —
// the same operations in the same order, no fused multiply-add — so a frame is the same to
// the byte either way (tested).
#pragma once

#include <atomic>

namespace weft::raster {

namespace detail {
// Set by use_avx512 (vector_isa.cpp); read once per triangle drawn, hence inline.
extern std::atomic<bool> avx512_active;
}  // namespace detail

// Whether this build holds the AVX-512 code and this CPU can run it.
bool avx512_supported();
// Whether the hot loops use it: by default when supported.
inline bool avx512_in_use() {
    return detail::avx512_active.load(std::memory_order_relaxed);
}
// Turns its use on or off (on only where supported); for tests and benchmarks.
void use_avx512(bool enabled);

}  // namespace weft::raster
