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
namespace {

// The block's vectors, in two widths: four rows of four lanes in 512-bit registers, and two
// rows in 256-bit ones for triangles at most two rows high — nearly half of a cloth's small
// triangles. Zen 4 runs a 512-bit operation as two 256-bit halves, so the wide block spent
// half its work on lanes outside the box for them. The operations are the same lane by
// lane, hence the same values.
struct FourRows {
    using Floats = __m512;
    using Ints = __m512i;
    using Mask = __mmask16;
    static constexpr int rows = 4;
    static Ints lanes() {
        return _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
    }
    static Ints ints(std::int32_t value) { return _mm512_set1_epi32(value); }
    static Ints add(Ints a, Ints b) { return _mm512_add_epi32(a, b); }
    static Ints subtract(Ints a, Ints b) { return _mm512_sub_epi32(a, b); }
    static Ints multiply(Ints a, Ints b) { return _mm512_mullo_epi32(a, b); }
    static Ints bitwise_or(Ints a, Ints b) { return _mm512_or_si512(a, b); }
    static Ints column_of(Ints lane) { return _mm512_and_si512(lane, ints(3)); }
    static Ints row_of(Ints lane) { return _mm512_srli_epi32(lane, 2); }
    static Mask less(Ints a, Ints b) { return _mm512_cmplt_epi32_mask(a, b); }
    static Mask not_negative(Ints a) { return _mm512_cmpge_epi32_mask(a, _mm512_setzero_si512()); }
    static Floats floats(float value) { return _mm512_set1_ps(value); }
    static Floats to_floats(Ints a) { return _mm512_cvtepi32_ps(a); }
    static Floats add(Floats a, Floats b) { return _mm512_add_ps(a, b); }
    static Floats multiply(Floats a, Floats b) { return _mm512_mul_ps(a, b); }
    static Floats divide(Floats a, Floats b) { return _mm512_div_ps(a, b); }
    static Mask less(Floats a, Floats b) { return _mm512_cmp_ps_mask(a, b, _CMP_LT_OQ); }
    static Floats pack(Mask mask, Floats a) { return _mm512_maskz_compress_ps(mask, a); }
    static Ints pack(Mask mask, Ints a) { return _mm512_maskz_compress_epi32(mask, a); }
    static void store(std::uint32_t* to, Ints a) { _mm512_storeu_si512(to, a); }
    static void store(float* to, Floats a) { _mm512_storeu_ps(to, a); }
    static Floats join(const __m128 (&row)[rows]) {
        const __m512 low = _mm512_insertf32x4(_mm512_castps128_ps512(row[0]), row[1], 1);
        return _mm512_insertf32x4(_mm512_insertf32x4(low, row[2], 2), row[3], 3);
    }
    static void split(Floats a, __m128 (&row)[rows]) {
        row[0] = _mm512_castps512_ps128(a);
        row[1] = _mm512_extractf32x4_ps(a, 1);
        row[2] = _mm512_extractf32x4_ps(a, 2);
        row[3] = _mm512_extractf32x4_ps(a, 3);
    }
};

struct TwoRows {
    using Floats = __m256;
    using Ints = __m256i;
    using Mask = __mmask8;
    static constexpr int rows = 2;
    static Ints lanes() { return _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7); }
    static Ints ints(std::int32_t value) { return _mm256_set1_epi32(value); }
    static Ints add(Ints a, Ints b) { return _mm256_add_epi32(a, b); }
    static Ints subtract(Ints a, Ints b) { return _mm256_sub_epi32(a, b); }
    static Ints multiply(Ints a, Ints b) { return _mm256_mullo_epi32(a, b); }
    static Ints bitwise_or(Ints a, Ints b) { return _mm256_or_si256(a, b); }
    static Ints column_of(Ints lane) { return _mm256_and_si256(lane, ints(3)); }
    static Ints row_of(Ints lane) { return _mm256_srli_epi32(lane, 2); }
    static Mask less(Ints a, Ints b) { return _mm256_cmplt_epi32_mask(a, b); }
    static Mask not_negative(Ints a) { return _mm256_cmpge_epi32_mask(a, _mm256_setzero_si256()); }
    static Floats floats(float value) { return _mm256_set1_ps(value); }
    static Floats to_floats(Ints a) { return _mm256_cvtepi32_ps(a); }
    static Floats add(Floats a, Floats b) { return _mm256_add_ps(a, b); }
    static Floats multiply(Floats a, Floats b) { return _mm256_mul_ps(a, b); }
    static Floats divide(Floats a, Floats b) { return _mm256_div_ps(a, b); }
    static Mask less(Floats a, Floats b) { return _mm256_cmp_ps_mask(a, b, _CMP_LT_OQ); }
    static Floats pack(Mask mask, Floats a) { return _mm256_maskz_compress_ps(mask, a); }
    static Ints pack(Mask mask, Ints a) { return _mm256_maskz_compress_epi32(mask, a); }
    static void store(std::uint32_t* to, Ints a) {
        _mm256_storeu_si256(reinterpret_cast<__m256i*>(to), a);
    }
    static void store(float* to, Floats a) { _mm256_storeu_ps(to, a); }
    static Floats join(const __m128 (&row)[rows]) {
        return _mm256_insertf128_ps(_mm256_castps128_ps256(row[0]), row[1], 1);
    }
    static void split(Floats a, __m128 (&row)[rows]) {
        row[0] = _mm256_castps256_ps128(a);
        row[1] = _mm256_extractf128_ps(a, 1);
    }
};

// (b0·v0 + b1·v1) + b2·v2, as the scalar loop computes it.
template <class Lanes>
typename Lanes::Floats blend(const typename Lanes::Floats (&barycentric)[3], float value0,
                             float value1, float value2) {
    return Lanes::add(Lanes::add(Lanes::multiply(barycentric[0], Lanes::floats(value0)),
                                 Lanes::multiply(barycentric[1], Lanes::floats(value1))),
                      Lanes::multiply(barycentric[2], Lanes::floats(value2)));
}

// The packed fragments' varyings: each lane's blend of the vertices' varyings over w, times
// its w.
template <class Lanes>
void write_varyings(const BlockTriangle& triangle, const typename Lanes::Floats (&barycentric)[3],
                    typename Lanes::Floats w, const FragmentSink& sink, int offset) {
    const float* const* over_w = triangle.varying_over_w;
    for (int k = 0; k < triangle.varying_count; ++k) {
        Lanes::store(sink.varyings[k] + offset,
                     Lanes::multiply(
                         blend<Lanes>(barycentric, over_w[0][k], over_w[1][k], over_w[2][k]), w));
    }
}

// Rows [y, y + min(Lanes::rows, y_end - y)) of the triangle, as traverse_fragment_block.
template <class Lanes>
int traverse_block(const BlockTriangle& triangle, int y, const FragmentSink& sink, int offset) {
    using Floats = typename Lanes::Floats;
    using Ints = typename Lanes::Ints;
    using Mask = typename Lanes::Mask;
    const TriangleSetup& setup = *triangle.setup;
    // Lane l is pixel (x_begin + l % 4, y + l / 4).
    const Ints lane = Lanes::lanes();
    const Ints column = Lanes::column_of(lane);
    const Ints row = Lanes::row_of(lane);
    const int rows = std::min(Lanes::rows, setup.y_end - y);
    const Mask inside_box = Lanes::less(column, Lanes::ints(setup.x_end - setup.x_begin)) &
                            Lanes::less(row, Lanes::ints(rows));

    // The edge functions, exact: fits_fragment_block keeps them inside 32 bits.
    const std::int64_t rows_down = y - setup.y_begin;
    Ints edge[3];
    for (int i = 0; i < 3; ++i) {
        const auto origin =
            static_cast<std::int32_t>(setup.edge_origin[i] + rows_down * setup.step_y[i]);
        edge[i] = Lanes::add(
            Lanes::ints(origin),
            Lanes::add(
                Lanes::multiply(column, Lanes::ints(static_cast<std::int32_t>(setup.step_x[i]))),
                Lanes::multiply(row, Lanes::ints(static_cast<std::int32_t>(setup.step_y[i])))));
    }
    const Mask covered = inside_box & Lanes::not_negative(Lanes::bitwise_or(
                                          Lanes::bitwise_or(edge[0], edge[1]), edge[2]));
    if (covered == 0) return 0;

    // Barycentrics and depth, as the scalar loop: (b0·d0 + b1·d1) + b2·d2.
    const Floats inverse_area = Lanes::floats(setup.inverse_doubled_area);
    Floats barycentric[3];
    for (int i = 0; i < 3; ++i) {
        const Ints unbiased =
            Lanes::subtract(edge[i], Lanes::ints(static_cast<std::int32_t>(setup.bias[i])));
        barycentric[i] = Lanes::multiply(Lanes::to_floats(unbiased), inverse_area);
    }
    const Floats depth = blend<Lanes>(barycentric, setup.depth[0], setup.depth[1], setup.depth[2]);

    // The depth test: each row's four stored depths, read and written only inside the box
    // (a row past the box reads nothing, from the first row's address).
    const std::uint32_t width = triangle.width;
    const std::uint32_t first_pixel =
        static_cast<std::uint32_t>(y) * width + static_cast<std::uint32_t>(setup.x_begin);
    float* row_depths[Lanes::rows];
    for (int r = 0; r < Lanes::rows; ++r)
        row_depths[r] = &triangle.depths[first_pixel + (r < rows ? r * width : 0)];
    auto row_mask = [](Mask mask, int r) {
        return static_cast<__mmask8>((mask >> (fragment_block_columns * r)) & 0xF);
    };
    Mask passed = covered;
    if (triangle.depth_test) {
        __m128 stored[Lanes::rows];
        for (int r = 0; r < Lanes::rows; ++r)
            stored[r] = _mm_maskz_loadu_ps(row_mask(inside_box, r), row_depths[r]);
        passed &= Lanes::less(depth, Lanes::join(stored));
        if (passed == 0) return 0;
    }
    if (triangle.depth_write) {
        __m128 written[Lanes::rows];
        Lanes::split(depth, written);
        for (int r = 0; r < Lanes::rows; ++r)
            _mm_mask_storeu_ps(row_depths[r], row_mask(passed, r), written[r]);
    }

    // The fragments that passed, packed in lane order: framebuffer index and varyings,
    // perspective-correct as the scalar loop computes them.
    const Ints pixel = Lanes::add(
        Lanes::ints(static_cast<std::int32_t>(first_pixel)),
        Lanes::add(column, Lanes::multiply(row, Lanes::ints(static_cast<std::int32_t>(width)))));
    const Floats w = Lanes::divide(
        Lanes::floats(1.0f),
        blend<Lanes>(barycentric, setup.inverse_w[0], setup.inverse_w[1], setup.inverse_w[2]));
    // Packed first, then interpolated: the same operations on the same values, in fewer
    // lanes' worth of shuffles (four packs instead of one per varying).
    for (int i = 0; i < 3; ++i) barycentric[i] = Lanes::pack(passed, barycentric[i]);
    const Floats packed_w = Lanes::pack(passed, w);
    const int count = __builtin_popcount(passed);
    if constexpr (Lanes::rows == 4) {
        // Most blocks pass a few fragments: then half-width vectors suffice.
        if (count <= 8) {
            TwoRows::store(sink.pixels + offset,
                           _mm512_castsi512_si256(Lanes::pack(passed, pixel)));
            const __m256 narrow[3] = {_mm512_castps512_ps256(barycentric[0]),
                                      _mm512_castps512_ps256(barycentric[1]),
                                      _mm512_castps512_ps256(barycentric[2])};
            write_varyings<TwoRows>(triangle, narrow, _mm512_castps512_ps256(packed_w), sink,
                                    offset);
            return count;
        }
    }
    Lanes::store(sink.pixels + offset, Lanes::pack(passed, pixel));
    write_varyings<Lanes>(triangle, barycentric, packed_w, sink, offset);
    return count;
}

}  // namespace

int traverse_fragment_block(const BlockTriangle& triangle, int y, const FragmentSink& sink,
                            int offset) {
    return traverse_block<FourRows>(triangle, y, sink, offset);
}

int traverse_fragment_half_block(const BlockTriangle& triangle, int y, const FragmentSink& sink,
                                 int offset) {
    return traverse_block<TwoRows>(triangle, y, sink, offset);
}

}  // namespace weft::raster

#else

namespace weft::raster {

int traverse_fragment_block(const BlockTriangle&, int, const FragmentSink&, int) {
    return 0;  // never called: avx512_supported() is false in such a build
}

int traverse_fragment_half_block(const BlockTriangle&, int, const FragmentSink&, int) {
    return 0;
}

}  // namespace weft::raster

#endif
