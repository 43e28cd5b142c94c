// The block of fragment_block.h with AVX-512 intrinsics. This file alone is compiled with
// the AVX-512 options (CMakeLists.txt); it runs only where the CPU has them.
#include "raster/fragment_block.h"

#if defined(__AVX512F__) && defined(__AVX512VL__) && defined(__AVX512DQ__)
// GCC 12's intrinsics build some vectors from deliberately undefined ones
// (_mm512_undefined_ps), which -Wmaybe-uninitialized reports inside its own headers.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <immintrin.h>

#include <algorithm>

namespace weft::raster {

int traverse_fragment_block(const BlockTriangle& triangle, int y, const FragmentSink& sink,
                            int offset) {
    const TriangleSetup& setup = *triangle.setup;
    // Lane l is pixel (x_begin + l % 4, y + l / 4).
    const __m512i lane = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
    const __m512i column = _mm512_and_si512(lane, _mm512_set1_epi32(fragment_block_columns - 1));
    const __m512i row = _mm512_srli_epi32(lane, 2);
    const int rows = std::min(fragment_block_rows, setup.y_end - y);
    const __mmask16 inside_box =
        _mm512_cmplt_epi32_mask(column, _mm512_set1_epi32(setup.x_end - setup.x_begin)) &
        _mm512_cmplt_epi32_mask(row, _mm512_set1_epi32(rows));

    // The edge functions, exact: fits_fragment_block keeps them inside 32 bits.
    const std::int64_t rows_down = y - setup.y_begin;
    __m512i edge[3];
    for (int i = 0; i < 3; ++i) {
        const auto origin =
            static_cast<std::int32_t>(setup.edge_origin[i] + rows_down * setup.step_y[i]);
        edge[i] = _mm512_add_epi32(
            _mm512_set1_epi32(origin),
            _mm512_add_epi32(
                _mm512_mullo_epi32(column,
                                   _mm512_set1_epi32(static_cast<std::int32_t>(setup.step_x[i]))),
                _mm512_mullo_epi32(row,
                                   _mm512_set1_epi32(static_cast<std::int32_t>(setup.step_y[i])))));
    }
    const __m512i any_edge = _mm512_or_si512(_mm512_or_si512(edge[0], edge[1]), edge[2]);
    const __mmask16 covered =
        inside_box & _mm512_cmpge_epi32_mask(any_edge, _mm512_setzero_si512());
    if (covered == 0) return 0;

    // Barycentrics and depth, as the scalar loop: (b0·d0 + b1·d1) + b2·d2.
    const __m512 inverse_area = _mm512_set1_ps(setup.inverse_doubled_area);
    __m512 barycentric[3];
    for (int i = 0; i < 3; ++i) {
        const __m512i unbiased =
            _mm512_sub_epi32(edge[i], _mm512_set1_epi32(static_cast<std::int32_t>(setup.bias[i])));
        barycentric[i] = _mm512_mul_ps(_mm512_cvtepi32_ps(unbiased), inverse_area);
    }
    auto blend = [&](float value0, float value1, float value2) {
        return _mm512_add_ps(_mm512_add_ps(_mm512_mul_ps(barycentric[0], _mm512_set1_ps(value0)),
                                           _mm512_mul_ps(barycentric[1], _mm512_set1_ps(value1))),
                             _mm512_mul_ps(barycentric[2], _mm512_set1_ps(value2)));
    };
    const __m512 depth = blend(setup.depth[0], setup.depth[1], setup.depth[2]);

    // The depth test: each row's four stored depths, read and written only inside the box
    // (a row past the box reads nothing, from the first row's address).
    const std::uint32_t width = triangle.width;
    const std::uint32_t first_pixel =
        static_cast<std::uint32_t>(y) * width + static_cast<std::uint32_t>(setup.x_begin);
    float* row_depths[fragment_block_rows];
    for (int r = 0; r < fragment_block_rows; ++r)
        row_depths[r] = triangle.depths + first_pixel + (r < rows ? r * width : 0);
    auto row_mask = [](__mmask16 mask, int r) {
        return static_cast<__mmask8>((mask >> (fragment_block_columns * r)) & 0xF);
    };
    __mmask16 passed = covered;
    if (triangle.depth_test) {
        __m512 stored =
            _mm512_castps128_ps512(_mm_maskz_loadu_ps(row_mask(inside_box, 0), row_depths[0]));
        stored = _mm512_insertf32x4(stored,
                                    _mm_maskz_loadu_ps(row_mask(inside_box, 1), row_depths[1]), 1);
        stored = _mm512_insertf32x4(stored,
                                    _mm_maskz_loadu_ps(row_mask(inside_box, 2), row_depths[2]), 2);
        stored = _mm512_insertf32x4(stored,
                                    _mm_maskz_loadu_ps(row_mask(inside_box, 3), row_depths[3]), 3);
        passed &= _mm512_cmp_ps_mask(depth, stored, _CMP_LT_OQ);
        if (passed == 0) return 0;
    }
    if (triangle.depth_write) {
        _mm_mask_storeu_ps(row_depths[0], row_mask(passed, 0), _mm512_castps512_ps128(depth));
        _mm_mask_storeu_ps(row_depths[1], row_mask(passed, 1), _mm512_extractf32x4_ps(depth, 1));
        _mm_mask_storeu_ps(row_depths[2], row_mask(passed, 2), _mm512_extractf32x4_ps(depth, 2));
        _mm_mask_storeu_ps(row_depths[3], row_mask(passed, 3), _mm512_extractf32x4_ps(depth, 3));
    }

    // The fragments that passed, packed in lane order: framebuffer index and varyings,
    // perspective-correct as the scalar loop computes them.
    const __m512i pixel = _mm512_add_epi32(
        _mm512_set1_epi32(static_cast<std::int32_t>(first_pixel)),
        _mm512_add_epi32(
            column, _mm512_mullo_epi32(row, _mm512_set1_epi32(static_cast<std::int32_t>(width)))));
    const __m512 w = _mm512_div_ps(
        _mm512_set1_ps(1.0f), blend(setup.inverse_w[0], setup.inverse_w[1], setup.inverse_w[2]));
    // Packed first, then interpolated: the same operations on the same values, in fewer
    // lanes' worth of shuffles (four packs instead of one per varying).
    for (int i = 0; i < 3; ++i) barycentric[i] = _mm512_maskz_compress_ps(passed, barycentric[i]);
    const __m512 packed_w = _mm512_maskz_compress_ps(passed, w);
    const __m512i packed_pixel = _mm512_maskz_compress_epi32(passed, pixel);
    const int count = __builtin_popcount(passed);
    const float* const* over_w = triangle.varying_over_w;
    // Most blocks pass a few fragments: then half-width vectors suffice.
    if (count <= 8) {
        _mm256_storeu_si256(reinterpret_cast<__m256i*>(sink.pixels + offset),
                            _mm512_castsi512_si256(packed_pixel));
        const __m256 b0 = _mm512_castps512_ps256(barycentric[0]);
        const __m256 b1 = _mm512_castps512_ps256(barycentric[1]);
        const __m256 b2 = _mm512_castps512_ps256(barycentric[2]);
        const __m256 w8 = _mm512_castps512_ps256(packed_w);
        for (int k = 0; k < triangle.varying_count; ++k) {
            const __m256 blended =
                _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(b0, _mm256_set1_ps(over_w[0][k])),
                                            _mm256_mul_ps(b1, _mm256_set1_ps(over_w[1][k]))),
                              _mm256_mul_ps(b2, _mm256_set1_ps(over_w[2][k])));
            _mm256_storeu_ps(sink.varyings[k] + offset, _mm256_mul_ps(blended, w8));
        }
    } else {
        _mm512_storeu_si512(sink.pixels + offset, packed_pixel);
        for (int k = 0; k < triangle.varying_count; ++k) {
            _mm512_storeu_ps(
                sink.varyings[k] + offset,
                _mm512_mul_ps(blend(over_w[0][k], over_w[1][k], over_w[2][k]), packed_w));
        }
    }
    return count;
}

}  // namespace weft::raster

#else

namespace weft::raster {

int traverse_fragment_block(const BlockTriangle&, int, const FragmentSink&, int) {
    return 0;  // never called: avx512_supported() is false in such a build
}

}  // namespace weft::raster

#endif
