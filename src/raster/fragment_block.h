// Small triangles, sixteen pixels at a time.
//
// A 128² cloth across a tenth of a 1280×720 screen is 34 000 triangles of about three pixels
// each: its pixel loop is almost all per-triangle and per-row overhead, and the branches of
// a scalar walk over a 3×3 box (inside this edge? this row? passes the depth test?) follow
// each triangle's shape, which changes from one triangle to the next. A triangle whose box is
// at most four pixels wide is instead taken four rows at a time as one block of 4×4 lanes:
// coverage, depth, the depth test and the perspective-correct varyings are computed for all
// sixteen lanes at once, and the fragments that pass are packed into the deferred shader's
// queue (triangle_rasterizer.h) with no branch per pixel. Drawing the demo's view of that
// cloth on one thread took 3.31 ms this way against 3.60 ms pixel by pixel (docs/performance.md).
// A triangle at most two rows high takes a block of 4×2 lanes in half-width vectors instead.
//
// Every lane computes exactly what the scalar pixel loop computes — the same integer edge
// functions, the same float operations in the same order, no fused multiply-add — and the
// fragments come out in the scalar loop's order (row by row, left to right), so a frame is
// the same to the byte whichever path drew it (tested).
//
// The block needs AVX-512 (its mask registers and compress): where it is not in use
// (vector_isa.h), the scalar loop draws every triangle.
#pragma once

#include <cstdint>

#include "raster/clipping.h"
#include "raster/framebuffer.h"
#include "raster/triangle_setup.h"

namespace weft::raster {

inline constexpr int fragment_block_columns = 4;
inline constexpr int fragment_block_rows = 4;
inline constexpr int fragment_block_size = fragment_block_columns * fragment_block_rows;
inline constexpr int half_block_rows = 2;  // rows of traverse_fragment_half_block

// Where blocks' fragments go (a deferred shader's queue): fragment j of a block written at
// `offset` lands in pixels[offset + j] and varyings[k][offset + j], with room for
// fragment_block_size from the offset. Lanes past the count returned are written too, with
// values of no meaning.
struct FragmentSink {
    std::uint32_t* pixels;          // framebuffer index (y · width + x)
    float* varyings[max_varyings];  // varying k of the fragments, one array per varying
};

// A set-up triangle and what the block reads of the frame, prepared once per triangle.
struct BlockTriangle {
    const TriangleSetup* setup;
    // Varying k of setup vertex i divided by its w (the rasterizer's varying_over_w).
    const float* varying_over_w[3];
    int varying_count;
    DepthRows depths;     // the framebuffer's
    std::uint32_t width;  // the framebuffer's width, pixels
    bool depth_test;
    bool depth_write;
};

// Whether the block can draw this triangle: its box at most fragment_block_columns wide,
// and every edge function over the block's lanes small enough for 32-bit integers.
inline bool fits_fragment_block(const TriangleSetup& setup) {
    if (setup.x_end - setup.x_begin > fragment_block_columns) return false;
    // |E| ≤ |origin| + 3·|step_x| + (rows − 1)·|step_y| over a block of rows from y_begin,
    // where rows ≤ 16 keeps the sum below 2^28 + 18·2^20 < 2^31.
    constexpr std::int64_t step_limit = std::int64_t{1} << 20;
    constexpr std::int64_t origin_limit = std::int64_t{1} << 28;
    if (setup.y_end - setup.y_begin > 16) return false;
    for (int i = 0; i < 3; ++i) {
        if (setup.edge_origin[i] > origin_limit || setup.edge_origin[i] < -origin_limit)
            return false;
        if (setup.step_x[i] > step_limit || setup.step_x[i] < -step_limit) return false;
        if (setup.step_y[i] > step_limit || setup.step_y[i] < -step_limit) return false;
    }
    return true;
}

// Rows [y, min(y + 4, y_end)) of the triangle: the fragments that pass the depth test, in
// order, into `sink` at `offset` (their depths written if depth_write). Returns how many.
// Only into a framebuffer that uses AVX-512 (Framebuffer::avx512_in_use), for a triangle that
// fits_fragment_block().
int traverse_fragment_block(const BlockTriangle& triangle, int y, const FragmentSink& sink,
                            int offset);
// The same for rows [y, min(y + 2, y_end)), in half-width vectors: for a triangle at most
// half_block_rows high, which the block above would draw with half its lanes outside the box.
// Chosen by the caller, where the triangle's height is at hand: choosing inside cost the
// demo's view 2 % of its drawing time (1.92 against 1.88 ms on one thread).
int traverse_fragment_half_block(const BlockTriangle& triangle, int y, const FragmentSink& sink,
                                 int offset);

}  // namespace weft::raster
