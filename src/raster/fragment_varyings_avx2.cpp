// Binned fragments' varyings, eight at a time (fragment_varyings_avx2.h), built with AVX2
// and no FMA.
#include "raster/fragment_varyings_avx2.h"

#include <cstddef>

#if defined(WEFT_RASTER_AVX2)
#include <immintrin.h>
#endif

namespace weft::raster {

#if defined(WEFT_RASTER_AVX2)

void interpolate_fragment_varyings_avx2(const float* varyings_over_w, const FragmentGroup& group,
                                        float* const (&out)[grouped_varying_count]) {
    static_assert(grouped_varying_count == 8 && fragment_group_size == 8);
    // One row a fragment, its eight varyings in the lanes; empty rows are zeros.
    __m256 row[fragment_group_size];
    for (int j = 0; j < fragment_group_size; ++j) {
        if (j >= group.count) {
            row[j] = _mm256_setzero_ps();
            continue;
        }
        const float* v0 = varyings_over_w + std::size_t{8} * group.vertex[j][0];
        const float* v1 = varyings_over_w + std::size_t{8} * group.vertex[j][1];
        const float* v2 = varyings_over_w + std::size_t{8} * group.vertex[j][2];
        const __m256 sum = _mm256_add_ps(
            _mm256_add_ps(_mm256_mul_ps(_mm256_set1_ps(group.weight[j][0]), _mm256_loadu_ps(v0)),
                          _mm256_mul_ps(_mm256_set1_ps(group.weight[j][1]), _mm256_loadu_ps(v1))),
            _mm256_mul_ps(_mm256_set1_ps(group.weight[j][2]), _mm256_loadu_ps(v2)));
        row[j] = _mm256_mul_ps(sum, _mm256_set1_ps(group.w[j]));
    }
    // The 8x8 transpose: rows of fragments into rows of varyings.
    const __m256 t0 = _mm256_unpacklo_ps(row[0], row[1]), t1 = _mm256_unpackhi_ps(row[0], row[1]);
    const __m256 t2 = _mm256_unpacklo_ps(row[2], row[3]), t3 = _mm256_unpackhi_ps(row[2], row[3]);
    const __m256 t4 = _mm256_unpacklo_ps(row[4], row[5]), t5 = _mm256_unpackhi_ps(row[4], row[5]);
    const __m256 t6 = _mm256_unpacklo_ps(row[6], row[7]), t7 = _mm256_unpackhi_ps(row[6], row[7]);
    const __m256 s0 = _mm256_shuffle_ps(t0, t2, 0x44), s1 = _mm256_shuffle_ps(t0, t2, 0xee);
    const __m256 s2 = _mm256_shuffle_ps(t1, t3, 0x44), s3 = _mm256_shuffle_ps(t1, t3, 0xee);
    const __m256 s4 = _mm256_shuffle_ps(t4, t6, 0x44), s5 = _mm256_shuffle_ps(t4, t6, 0xee);
    const __m256 s6 = _mm256_shuffle_ps(t5, t7, 0x44), s7 = _mm256_shuffle_ps(t5, t7, 0xee);
    _mm256_storeu_ps(out[0], _mm256_permute2f128_ps(s0, s4, 0x20));
    _mm256_storeu_ps(out[1], _mm256_permute2f128_ps(s1, s5, 0x20));
    _mm256_storeu_ps(out[2], _mm256_permute2f128_ps(s2, s6, 0x20));
    _mm256_storeu_ps(out[3], _mm256_permute2f128_ps(s3, s7, 0x20));
    _mm256_storeu_ps(out[4], _mm256_permute2f128_ps(s0, s4, 0x31));
    _mm256_storeu_ps(out[5], _mm256_permute2f128_ps(s1, s5, 0x31));
    _mm256_storeu_ps(out[6], _mm256_permute2f128_ps(s2, s6, 0x31));
    _mm256_storeu_ps(out[7], _mm256_permute2f128_ps(s3, s7, 0x31));
}

#else

void interpolate_fragment_varyings_avx2(const float*, const FragmentGroup&,
                                        float* const (&)[grouped_varying_count]) {}

#endif

}  // namespace weft::raster
