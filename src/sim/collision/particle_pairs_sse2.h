// Two particles at a time in SSE2 pairs of doubles, for the scans over a particle array that
// run on every step (the colliders' test, the self-collision's move measure). The six
// coordinates of particles p and p + 1 are read as (x0 y0) (z0 x1) (y1 z1): each lane of each
// pair always holds the same component, so componentwise work (differences, products,
// minima, maxima) is one operation a pair, lane for lane the scalar one. Only a sum over a
// particle's components needs the lanes regathered, in the scalar order (x + y) + z, so the
// bits are the scalar loop's.
#pragma once

#if defined(__SSE2__)
#include <emmintrin.h>

#include "sim/core/cloth.h"

namespace weft::sse2 {

static_assert(sizeof(Vec3) == 3 * sizeof(double), "the particles' coordinates are one array");

struct ParticlePair {
    __m128d xy, zx, yz;  // (x0 y0) (z0 x1) (y1 z1)
};

// Particles p and p + 1 of `particles`.
inline ParticlePair load_pair(const Vec3* particles, std::size_t p) {
    const double* at = &particles[p].x;
    return {_mm_loadu_pd(at), _mm_loadu_pd(at + 2), _mm_loadu_pd(at + 4)};
}

// One vector as both particles' value, in the same lanes.
inline ParticlePair splat(const Vec3& v) {
    return {_mm_set_pd(v.y, v.x), _mm_set_pd(v.x, v.z), _mm_set_pd(v.z, v.y)};
}

inline ParticlePair operator-(const ParticlePair& a, const ParticlePair& b) {
    return {_mm_sub_pd(a.xy, b.xy), _mm_sub_pd(a.zx, b.zx), _mm_sub_pd(a.yz, b.yz)};
}

inline ParticlePair operator*(const ParticlePair& a, const ParticlePair& b) {
    return {_mm_mul_pd(a.xy, b.xy), _mm_mul_pd(a.zx, b.zx), _mm_mul_pd(a.yz, b.yz)};
}

// (x + y) + z of each particle: (particle p's, particle p + 1's).
inline __m128d component_sums(const ParticlePair& v) {
    const __m128d x = _mm_move_sd(v.zx, v.xy);        // (x0, x1)
    const __m128d y = _mm_shuffle_pd(v.xy, v.yz, 1);  // (y0, y1)
    const __m128d z = _mm_shuffle_pd(v.zx, v.yz, 2);  // (z0, z1)
    return _mm_add_pd(_mm_add_pd(x, y), z);
}

inline double lane(__m128d v, int i) {
    return i == 0 ? _mm_cvtsd_f64(v) : _mm_cvtsd_f64(_mm_unpackhi_pd(v, v));
}

}  // namespace weft::sse2

#endif
