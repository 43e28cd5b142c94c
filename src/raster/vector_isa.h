// Which vector instructions the rasterizer's hot loops can use.
//
// The library is built for any x86-64; the block traversal of small triangles
// (fragment_block.h) and the batched lighting (surface_shading.h) are also built with
// AVX-512, and those builds run where the CPU has it. Both builds compute every value alike —
// the same operations in the same order, no fused multiply-add — so a frame is the same to
// the byte either way (tested). Each Framebuffer says whether drawing into it uses them
// (Framebuffer::use_avx512); nothing in the process chooses for it.
#pragma once

namespace weft::raster {

// Whether this build holds the AVX-512 code and this CPU can run it.
bool avx512_supported();

}  // namespace weft::raster
