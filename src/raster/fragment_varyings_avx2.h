// Binned fragments' varyings, eight fragments at a time with AVX2
// (fragment_varyings_avx2.cpp; only that file gets the instruction set, and it runs only
// where the CPU has it).
//
// A surface whose vertices carry eight varyings (position, normal and uv, each divided by
// w) fits one vector a vertex: a fragment's varyings are its three vertices' vectors
// weighted, (b0 v0 + b1 v1 + b2 v2) w, and eight fragments' are then turned into one vector
// a varying, as the deferred shader's queue holds them. The same operations in the same
// order as shade_binned_fragment's scalar loop and no fused multiply-add, so the same bits.
#pragma once

#include <cstdint>

namespace weft::raster {

inline constexpr int grouped_varying_count = 8;
inline constexpr int fragment_group_size = 8;

// Fragments that passed their depth test, waiting for their varyings.
struct FragmentGroup {
    int count = 0;
    std::uint32_t pixel[fragment_group_size];      // framebuffer index
    float front[fragment_group_size];              // 1 when the front face is seen
    std::uint32_t vertex[fragment_group_size][3];  // the triangle's vertices, setup order
    float weight[fragment_group_size][3];          // barycentric of each
    float w[fragment_group_size];                  // clip w at the pixel
};

// out[k][j] = ((b0 v0[k] + b1 v1[k]) + b2 v2[k]) w for fragment j < group.count and varying
// k < 8, where vi = varyings_over_w + 8 · vertex i. Writes all eight slots of each out[k]
// (those from group.count on hold nothing meaningful). Only where avx2_supported()
// (vector_isa.h).
void interpolate_fragment_varyings_avx2(const float* varyings_over_w, const FragmentGroup& group,
                                        float* const (&out)[grouped_varying_count]);

}  // namespace weft::raster
