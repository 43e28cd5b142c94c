// The vertex transform's positions, eight vertices at a time (vertex_transform_avx2.h), built
// with AVX2 and no FMA.
#include "raster/vertex_transform_avx2.h"

#include <limits>

#include "raster/clipping.h"

#if defined(WEFT_RASTER_AVX2)
#include <immintrin.h>
#endif

namespace weft::raster {

#if defined(WEFT_RASTER_AVX2)

namespace {

static_assert(sizeof(glm::vec3) == 3 * sizeof(float) && sizeof(glm::vec4) == 4 * sizeof(float));

// The bits of `bit` where `mask` is set.
__m256i bits_where(__m256 mask, std::uint32_t bit) {
    return _mm256_and_si256(_mm256_castps_si256(mask), _mm256_set1_epi32(static_cast<int>(bit)));
}

// A lane's rounded coordinate as lrint gives it in 64 bits. Inside the guard band a finite
// coordinate is never -2^31, the value the lanes give a NaN; a vertex with a NaN has no
// clipping plane in its outcode (only not_finite, which culls its triangles), so its window
// vertex is still written, as lrint's 64-bit "indefinite" value.
std::int64_t widened(std::int32_t rounded) {
    return rounded == std::numeric_limits<std::int32_t>::min()
               ? std::numeric_limits<std::int64_t>::min()
               : rounded;
}

}  // namespace

void transform_positions_avx2(const glm::mat4& clip_from_model, const glm::vec3* positions,
                              std::size_t begin, std::size_t groups, int width, int height,
                              glm::vec4* clip, std::uint32_t* outcodes, WindowVertex* window) {
    __m256 m[4][4];  // m[column][row], broadcast
    for (int column = 0; column < 4; ++column)
        for (int row = 0; row < 4; ++row)
            m[column][row] = _mm256_set1_ps(clip_from_model[column][row]);
    const __m256 one = _mm256_set1_ps(1.0f), half = _mm256_set1_ps(0.5f);
    const __m256 width_f = _mm256_set1_ps(static_cast<float>(width));
    const __m256 height_f = _mm256_set1_ps(static_cast<float>(height));
    const __m256 subpixels = _mm256_set1_ps(static_cast<float>(subpixel_scale));
    const __m256 guard = _mm256_set1_ps(guard_band), w_min = _mm256_set1_ps(min_clip_w);
    const __m256 infinity = _mm256_set1_ps(__builtin_inff());
    const __m256 sign = _mm256_set1_ps(-0.0f);
    for (std::size_t group = 0; group < groups; ++group) {
        const std::size_t first_vertex = begin + group * transform_group_size;
        // Eight vec3 are 24 contiguous floats: three loads, then each component's eight picked
        // out by blends and put in order by a permutation.
        const float* at = &positions[first_vertex].x;
        const __m256 a = _mm256_loadu_ps(at), b = _mm256_loadu_ps(at + 8),
                     c = _mm256_loadu_ps(at + 16);
        const __m256 x = _mm256_permutevar8x32_ps(
            _mm256_blend_ps(_mm256_blend_ps(a, b, 0b10010010), c, 0b00100100),
            _mm256_setr_epi32(0, 3, 6, 1, 4, 7, 2, 5));
        const __m256 y = _mm256_permutevar8x32_ps(
            _mm256_blend_ps(_mm256_blend_ps(a, b, 0b00100100), c, 0b01001001),
            _mm256_setr_epi32(1, 4, 7, 2, 5, 0, 3, 6));
        const __m256 z = _mm256_permutevar8x32_ps(
            _mm256_blend_ps(_mm256_blend_ps(a, b, 0b01001001), c, 0b10010010),
            _mm256_setr_epi32(2, 5, 0, 3, 6, 1, 4, 7));
        // glm: (m0 x + m1 y) + (m2 z + m3 · 1), per row; m3 · 1 is m3.
        __m256 p[4];
        for (int row = 0; row < 4; ++row) {
            p[row] = _mm256_add_ps(
                _mm256_add_ps(_mm256_mul_ps(m[0][row], x), _mm256_mul_ps(m[1][row], y)),
                _mm256_add_ps(_mm256_mul_ps(m[2][row], z), m[3][row]));
        }
        const __m256 w = p[3], negative_w = _mm256_xor_ps(w, sign);
        const __m256 g = _mm256_mul_ps(guard, w), negative_g = _mm256_xor_ps(g, sign);
        // clip_outcode, bit by bit (ordered comparisons: false for NaN, as there).
        __m256i code = bits_where(_mm256_cmp_ps(p[0], negative_w, _CMP_LT_OQ), outside_left);
        const auto add = [&](__m256 mask, std::uint32_t bit) {
            code = _mm256_or_si256(code, bits_where(mask, bit));
        };
        add(_mm256_cmp_ps(p[0], w, _CMP_GT_OQ), outside_right);
        add(_mm256_cmp_ps(p[1], negative_w, _CMP_LT_OQ), outside_bottom);
        add(_mm256_cmp_ps(p[1], w, _CMP_GT_OQ), outside_top);
        add(_mm256_cmp_ps(p[2], negative_w, _CMP_LT_OQ), outside_near);
        add(_mm256_cmp_ps(p[2], w, _CMP_GT_OQ), outside_far);
        add(_mm256_cmp_ps(w, w_min, _CMP_LT_OQ), outside_w_min);
        add(_mm256_cmp_ps(p[0], negative_g, _CMP_LT_OQ), beyond_guard_left);
        add(_mm256_cmp_ps(p[0], g, _CMP_GT_OQ), beyond_guard_right);
        add(_mm256_cmp_ps(p[1], negative_g, _CMP_LT_OQ), beyond_guard_bottom);
        add(_mm256_cmp_ps(p[1], g, _CMP_GT_OQ), beyond_guard_top);
        __m256 finite = _mm256_castsi256_ps(_mm256_set1_epi32(-1));
        for (const __m256 component : p)
            finite = _mm256_and_ps(
                finite, _mm256_cmp_ps(_mm256_andnot_ps(sign, component), infinity, _CMP_LT_OQ));
        add(_mm256_xor_ps(finite, _mm256_castsi256_ps(_mm256_set1_epi32(-1))), not_finite);

        // window_vertex: ndc = xyz / w; window = ((ndc.x + 1) · ½ · width,
        // (1 - ndc.y) · ½ · height, ndc.z · ½ + ½); x and y snapped by lrint(· 256).
        const __m256 window_x =
            _mm256_mul_ps(_mm256_mul_ps(_mm256_add_ps(_mm256_div_ps(p[0], w), one), half), width_f);
        const __m256 window_y = _mm256_mul_ps(
            _mm256_mul_ps(_mm256_sub_ps(one, _mm256_div_ps(p[1], w)), half), height_f);
        const __m256 depth = _mm256_add_ps(_mm256_mul_ps(_mm256_div_ps(p[2], w), half), half);
        const __m256 inverse_w = _mm256_div_ps(one, w);
        const __m256i snapped_x = _mm256_cvtps_epi32(_mm256_mul_ps(window_x, subpixels));
        const __m256i snapped_y = _mm256_cvtps_epi32(_mm256_mul_ps(window_y, subpixels));

        alignas(32) float lanes[8][transform_group_size];
        alignas(32) std::int32_t snapped[2][transform_group_size];
        alignas(32) std::uint32_t codes[transform_group_size];
        for (int row = 0; row < 4; ++row) _mm256_store_ps(lanes[row], p[row]);
        _mm256_store_ps(lanes[4], depth);
        _mm256_store_ps(lanes[5], inverse_w);
        _mm256_store_si256(reinterpret_cast<__m256i*>(snapped[0]), snapped_x);
        _mm256_store_si256(reinterpret_cast<__m256i*>(snapped[1]), snapped_y);
        _mm256_store_si256(reinterpret_cast<__m256i*>(codes), code);
        for (int lane = 0; lane < transform_group_size; ++lane) {
            const std::size_t i = first_vertex + static_cast<std::size_t>(lane);
            clip[i] = {lanes[0][lane], lanes[1][lane], lanes[2][lane], lanes[3][lane]};
            outcodes[i] = codes[lane];
            if ((codes[lane] & clipping_planes) == 0)
                window[i] = {widened(snapped[0][lane]), widened(snapped[1][lane]), lanes[4][lane],
                             lanes[5][lane]};
        }
    }
}

void divide_surface_varyings_avx2(const glm::vec3* positions, const glm::vec3* normals,
                                  const glm::vec2* uvs, const std::uint32_t* outcodes,
                                  const WindowVertex* window, std::size_t begin, std::size_t end,
                                  float* varyings_over_w) {
    static_assert(sizeof(glm::vec2) == 2 * sizeof(float));
    const __m128i three = _mm_setr_epi32(-1, -1, -1, 0);  // a vec3's floats, not the next one's
    for (std::size_t i = begin; i < end; ++i) {
        if ((outcodes[i] & clipping_planes) != 0) continue;
        // [x y z nx] and [ny nz u v].
        const __m128 position = _mm_maskload_ps(&positions[i].x, three);
        const __m128 low = _mm_blend_ps(position, _mm_set1_ps(normals[i].x), 0b1000);
        // Two floats a load, at any alignment (_mm_loadu_si64 reads through an unaligned type).
        const __m128 high = _mm_movelh_ps(_mm_castsi128_ps(_mm_loadu_si64(&normals[i].y)),
                                          _mm_castsi128_ps(_mm_loadu_si64(&uvs[i].x)));
        const __m256 varyings = _mm256_set_m128(high, low);
        _mm256_storeu_ps(varyings_over_w + 8 * i,
                         _mm256_mul_ps(varyings, _mm256_set1_ps(window[i].inverse_w)));
    }
}

#else

void divide_surface_varyings_avx2(const glm::vec3*, const glm::vec3*, const glm::vec2*,
                                  const std::uint32_t*, const WindowVertex*, std::size_t,
                                  std::size_t, float*) {}

void transform_positions_avx2(const glm::mat4&, const glm::vec3*, std::size_t, std::size_t, int,
                              int, glm::vec4*, std::uint32_t*, WindowVertex*) {}

#endif

}  // namespace weft::raster
