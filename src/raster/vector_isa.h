// Which vector instructions the rasterizer's hot loops can use.
//
// The library is built for any x86-64; the block traversal of small triangles
// (fragment_block.h) and the batched lighting (surface_shading.h) are also built with
// AVX-512, the lighting also with AVX2, and those builds run where the CPU has them. Every
// build computes every value alike — the same operations in the same order, no fused
// multiply-add — so a frame is the same to the byte either way (tested). Each Framebuffer says
// whether drawing into it uses them (Framebuffer::use_avx512, use_avx2); nothing in the
// process chooses for it; the binned fragments' varyings (fragment_varyings_avx2.h) follow the
// framebuffer's choice, and a whole grid's normals (GridNormals::use_avx2) make their own.
// Binning's classification of triangles (binning_avx2.h) is integer work with one answer, and
// the vertex transform's positions (vertex_transform_avx2.h) are the scalar operations in
// lanes: both run wherever AVX2 does.
#pragma once

namespace weft::raster {

// Whether this build holds the AVX-512 code and this CPU can run it.
bool avx512_supported();

// Whether this build holds the AVX2 code and this CPU can run it.
bool avx2_supported();

}  // namespace weft::raster
