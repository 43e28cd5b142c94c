// Binning's classification of eight triangles at once (binning_avx2.h), built with AVX2.
#include "raster/binning_avx2.h"

#include <bit>
#include <cstddef>

#include "raster/clipping.h"

#if defined(WEFT_RASTER_AVX2)
#include <immintrin.h>
#endif

namespace weft::raster {

#if defined(WEFT_RASTER_AVX2)

namespace {

// WindowVertex holds x and y as 64-bit integers, 24 bytes a vertex: the low halves, in 32-bit
// units, of vertex i are at 6i (x) and 6i + 2 (y). A window position that needs no clipping
// lies inside the guard band, |x| < 2^31 / 256 for any viewport up to 65535 pixels: its low
// half is the value.
static_assert(sizeof(WindowVertex) == 24 && offsetof(WindowVertex, x) == 0 &&
              offsetof(WindowVertex, y) == 8);
static_assert(sizeof(TriangleIndices) == 3 * sizeof(std::uint32_t));

__m256i gather(const void* base, __m256i index, __m256i mask) {
    return _mm256_mask_i32gather_epi32(_mm256_setzero_si256(), static_cast<const int*>(base), index,
                                       mask, 4);
}

__m256i select(__m256i mask, __m256i if_set, __m256i if_clear) {
    return _mm256_blendv_epi8(if_clear, if_set, mask);
}

// The eight triangles whose corners' outcodes and window positions (in 1/256 pixel) are in
// the lanes of code[c], x[c] and y[c]; `valid`: the lanes whose indices are in range.
// Always inlined into both callers, so the corners stay in registers.
[[gnu::always_inline]] inline void classify_lanes(__m256i valid, const __m256i (&code)[3],
                                                  __m256i (&x)[3], __m256i (&y)[3], int width,
                                                  int height, BinningGroup& group);

}  // namespace

void classify_for_binning_avx2(const TriangleIndices* triangles, std::uint32_t vertex_count,
                               const std::uint32_t* outcodes, const WindowVertex* window, int width,
                               int height, BinningGroup& group) {
    const __m256i ones = _mm256_set1_epi32(-1);
    // Vertex indices, checked against the vertex count (an unsigned comparison).
    constexpr std::uint32_t largest_gathered = 0x7fffffffu / 6;
    if (vertex_count == 0 || vertex_count > largest_gathered) {
        group.leave_all_undecided();
        return;
    }
    // The eight triangles' 24 indices are contiguous: three loads, then each corner's eight
    // picked out by blends and put in order by a permutation (cheaper than gathers).
    const auto* const indices = reinterpret_cast<const __m256i*>(triangles);
    const __m256i first = _mm256_loadu_si256(indices), second = _mm256_loadu_si256(indices + 1),
                  third = _mm256_loadu_si256(indices + 2);
    __m256i vertex[3] = {
        _mm256_permutevar8x32_epi32(
            _mm256_blend_epi32(_mm256_blend_epi32(first, second, 0b10010010), third, 0b00100100),
            _mm256_setr_epi32(0, 3, 6, 1, 4, 7, 2, 5)),
        _mm256_permutevar8x32_epi32(
            _mm256_blend_epi32(_mm256_blend_epi32(first, second, 0b00100100), third, 0b01001001),
            _mm256_setr_epi32(1, 4, 7, 2, 5, 0, 3, 6)),
        _mm256_permutevar8x32_epi32(
            _mm256_blend_epi32(_mm256_blend_epi32(first, second, 0b01001001), third, 0b10010010),
            _mm256_setr_epi32(2, 5, 0, 3, 6, 1, 4, 7))};
    const __m256i last_vertex = _mm256_set1_epi32(static_cast<int>(vertex_count - 1));
    __m256i valid = ones;
    for (int c = 0; c < 3; ++c) {
        valid = _mm256_and_si256(
            valid, _mm256_cmpeq_epi32(_mm256_min_epu32(vertex[c], last_vertex), vertex[c]));
    }

    const __m256i code[3] = {gather(outcodes, vertex[0], valid), gather(outcodes, vertex[1], valid),
                             gather(outcodes, vertex[2], valid)};
    // Window positions, in 1/256 pixel: the low halves of WindowVertex's x and y.
    __m256i x[3], y[3];
    for (int c = 0; c < 3; ++c) {
        const __m256i at = _mm256_mullo_epi32(vertex[c], _mm256_set1_epi32(6));
        x[c] = gather(window, at, valid);
        y[c] = gather(window, _mm256_add_epi32(at, _mm256_set1_epi32(2)), valid);
    }
    classify_lanes(valid, code, x, y, width, height, group);
}

namespace {

// Five consecutive values from `at` in lanes 0-4 (the lanes above are never read: masked,
// so nothing past the array's end is touched).
__m256i load_five(const std::int32_t* at) {
    return _mm256_maskload_epi32(at, _mm256_setr_epi32(-1, -1, -1, -1, -1, 0, 0, 0));
}

// The three corners' values of a group of four whole-grid cells from the rows above (top)
// and below (bottom) them, each holding columns c0 … c0 + 4 in lanes 0-4. Lane 2j is cell j's
// first triangle (top left, bottom left, top right), lane 2j + 1 its second (top right,
// bottom left, bottom right).
void grid_corners(__m256i top, __m256i bottom, __m256i (&corner)[3]) {
    corner[0] = _mm256_permutevar8x32_epi32(top, _mm256_setr_epi32(0, 1, 1, 2, 2, 3, 3, 4));
    corner[1] = _mm256_permutevar8x32_epi32(bottom, _mm256_setr_epi32(0, 0, 1, 1, 2, 2, 3, 3));
    const __m256i right = _mm256_setr_epi32(1, 1, 2, 2, 3, 3, 4, 4);
    corner[2] = _mm256_blend_epi32(_mm256_permutevar8x32_epi32(top, right),
                                   _mm256_permutevar8x32_epi32(bottom, right), 0b10101010);
}

}  // namespace

void classify_grid_group_avx2(std::size_t first_triangle, int grid_cols,
                              const std::uint32_t* outcodes, const std::int32_t* snapped_x,
                              const std::int32_t* snapped_y, int width, int height,
                              BinningGroup& group) {
    const auto cols = static_cast<std::size_t>(grid_cols);
    const std::size_t cell = first_triangle / 2;
    const std::size_t top_left = cell / (cols - 1) * cols + cell % (cols - 1);
    const std::size_t bottom_left = top_left + cols;
    __m256i code[3], x[3], y[3];
    grid_corners(load_five(reinterpret_cast<const std::int32_t*>(outcodes + top_left)),
                 load_five(reinterpret_cast<const std::int32_t*>(outcodes + bottom_left)), code);
    grid_corners(load_five(snapped_x + top_left), load_five(snapped_x + bottom_left), x);
    grid_corners(load_five(snapped_y + top_left), load_five(snapped_y + bottom_left), y);
    classify_lanes(_mm256_set1_epi32(-1), code, x, y, width, height, group);
}

namespace {

inline void classify_lanes(__m256i valid, const __m256i (&code)[3], __m256i (&x)[3],
                           __m256i (&y)[3], int width, int height, BinningGroup& group) {
    const __m256i ones = _mm256_set1_epi32(-1), zero = _mm256_setzero_si256();
    // Cull and clip, as TriangleOutcodes decides them.
    const __m256i all = _mm256_and_si256(_mm256_and_si256(code[0], code[1]), code[2]);
    const __m256i any = _mm256_or_si256(_mm256_or_si256(code[0], code[1]), code[2]);
    auto has = [&](__m256i bits, std::uint32_t planes) {
        return _mm256_xor_si256(
            _mm256_cmpeq_epi32(_mm256_and_si256(bits, _mm256_set1_epi32(static_cast<int>(planes))),
                               zero),
            ones);
    };
    const __m256i culled = _mm256_or_si256(has(all, frustum_planes), has(any, not_finite));
    const __m256i clipped = has(any, clipping_planes);

    // The box of pixel centres inside the viewport (detail::covered_box).
    const __m256i half = _mm256_set1_epi32(static_cast<int>(subpixel_scale / 2));
    const __m256i min_x = _mm256_min_epi32(_mm256_min_epi32(x[0], x[1]), x[2]);
    const __m256i max_x = _mm256_max_epi32(_mm256_max_epi32(x[0], x[1]), x[2]);
    const __m256i min_y = _mm256_min_epi32(_mm256_min_epi32(y[0], y[1]), y[2]);
    const __m256i max_y = _mm256_max_epi32(_mm256_max_epi32(y[0], y[1]), y[2]);
    auto ceil_to_pixel = [&](__m256i v) {
        return _mm256_srai_epi32(
            _mm256_add_epi32(v, _mm256_set1_epi32(static_cast<int>(subpixel_scale - 1))),
            subpixel_bits);
    };
    auto floor_to_pixel = [&](__m256i v) { return _mm256_srai_epi32(v, subpixel_bits); };
    const __m256i one = _mm256_set1_epi32(1);
    const __m256i x_begin = _mm256_max_epi32(ceil_to_pixel(_mm256_sub_epi32(min_x, half)), zero);
    const __m256i x_end =
        _mm256_min_epi32(_mm256_add_epi32(floor_to_pixel(_mm256_sub_epi32(max_x, half)), one),
                         _mm256_set1_epi32(width));
    const __m256i y_begin = _mm256_max_epi32(ceil_to_pixel(_mm256_sub_epi32(min_y, half)), zero);
    const __m256i y_end =
        _mm256_min_epi32(_mm256_add_epi32(floor_to_pixel(_mm256_sub_epi32(max_y, half)), one),
                         _mm256_set1_epi32(height));
    const __m256i columns = _mm256_sub_epi32(x_end, x_begin);
    const __m256i rows = _mm256_sub_epi32(y_end, y_begin);
    const __m256i empty =
        _mm256_or_si256(_mm256_cmpgt_epi32(one, columns), _mm256_cmpgt_epi32(one, rows));
    const __m256i two = _mm256_set1_epi32(tiny_box_side);
    const __m256i larger =
        _mm256_or_si256(_mm256_cmpgt_epi32(columns, two), _mm256_cmpgt_epi32(rows, two));
    // Decidable here: an extent that keeps every product below 2^21.
    const __m256i small_extent_limit = _mm256_set1_epi32(1024);
    const __m256i decidable = _mm256_andnot_si256(
        _mm256_or_si256(_mm256_cmpgt_epi32(_mm256_sub_epi32(max_x, min_x), small_extent_limit),
                        _mm256_cmpgt_epi32(_mm256_sub_epi32(max_y, min_y), small_extent_limit)),
        ones);

    // Facing and setup order (detail::doubled_area; a front face swaps vertices 1 and 2).
    __m256i area = _mm256_sub_epi32(
        _mm256_mullo_epi32(_mm256_sub_epi32(x[2], x[1]), _mm256_sub_epi32(y[0], y[1])),
        _mm256_mullo_epi32(_mm256_sub_epi32(y[2], y[1]), _mm256_sub_epi32(x[0], x[1])));
    const __m256i front = _mm256_cmpgt_epi32(zero, area);
    const __m256i zero_area = _mm256_cmpeq_epi32(area, zero);
    area = _mm256_abs_epi32(area);
    const __m256i x1 = select(front, x[2], x[1]), x2 = select(front, x[1], x[2]);
    const __m256i y1 = select(front, y[2], y[1]), y2 = select(front, y[1], y[2]);
    x[1] = x1;
    x[2] = x2;
    y[1] = y1;
    y[2] = y2;

    // The weights' normalisation, as bin_coverage makes it: 1 / area in double, then rounded
    // to float (a lane of zero area draws nothing and its weights are never read).
    const __m256d unit = _mm256_set1_pd(1.0);
    const __m256 inverse_area = _mm256_set_m128(
        _mm256_cvtpd_ps(_mm256_div_pd(unit, _mm256_cvtepi32_pd(_mm256_extracti128_si256(area, 1)))),
        _mm256_cvtpd_ps(_mm256_div_pd(unit, _mm256_cvtepi32_pd(_mm256_castsi256_si128(area)))));

    // Edge functions relative to the box's first pixel centre, as detail::EdgeFunction makes
    // them: edge i runs from vertex i + 1 to vertex i + 2.
    const __m256i origin_x = _mm256_add_epi32(_mm256_slli_epi32(x_begin, subpixel_bits), half);
    const __m256i origin_y = _mm256_add_epi32(_mm256_slli_epi32(y_begin, subpixel_bits), half);
    __m256i outside[tiny_box_side * tiny_box_side] = {zero, zero, zero, zero};
    for (int i = 0; i < 3; ++i) {
        const int a = (i + 1) % 3, b = (i + 2) % 3;
        const __m256i gradient_x = _mm256_sub_epi32(y[a], y[b]);
        const __m256i gradient_y = _mm256_sub_epi32(x[b], x[a]);
        const __m256i top_left =
            _mm256_or_si256(_mm256_cmpgt_epi32(gradient_x, zero),
                            _mm256_and_si256(_mm256_cmpeq_epi32(gradient_x, zero),
                                             _mm256_cmpgt_epi32(gradient_y, zero)));
        const __m256i bias = _mm256_andnot_si256(top_left, ones);  // 0 or -1
        const __m256i at_first = _mm256_add_epi32(
            _mm256_add_epi32(_mm256_mullo_epi32(gradient_x, _mm256_sub_epi32(origin_x, x[a])),
                             _mm256_mullo_epi32(gradient_y, _mm256_sub_epi32(origin_y, y[a]))),
            bias);
        const __m256i step_x = _mm256_slli_epi32(gradient_x, subpixel_bits);
        const __m256i step_y = _mm256_slli_epi32(gradient_y, subpixel_bits);
        const __m256i at[tiny_box_side * tiny_box_side] = {
            at_first, _mm256_add_epi32(at_first, step_x), _mm256_add_epi32(at_first, step_y),
            _mm256_add_epi32(_mm256_add_epi32(at_first, step_x), step_y)};
        for (int k = 0; k < tiny_box_side * tiny_box_side; ++k) {
            outside[k] = _mm256_or_si256(outside[k], at[k]);
            // The unbiased value over the doubled area, exact in float below 2^24.
            _mm256_storeu_ps(
                group.weight[k][i],
                _mm256_mul_ps(_mm256_cvtepi32_ps(_mm256_sub_epi32(at[k], bias)), inverse_area));
        }
    }
    // A centre is covered where no edge function is negative, inside the box.
    const __m256i wide = _mm256_cmpeq_epi32(columns, two), tall = _mm256_cmpeq_epi32(rows, two);
    const __m256i in_box[tiny_box_side * tiny_box_side] = {ones, wide, tall,
                                                           _mm256_and_si256(wide, tall)};
    __m256i covered = zero;
    for (int k = 0; k < tiny_box_side * tiny_box_side; ++k) {
        const __m256i inside = _mm256_and_si256(_mm256_cmpgt_epi32(outside[k], ones), in_box[k]);
        covered = _mm256_or_si256(covered, _mm256_and_si256(inside, _mm256_set1_epi32(1 << k)));
    }

    // The lane's kind, in the scalar path's order of decisions.
    const __m256i undecided = _mm256_or_si256(
        _mm256_andnot_si256(valid, ones),
        _mm256_andnot_si256(
            culled, _mm256_or_si256(clipped, _mm256_andnot_si256(
                                                 empty, _mm256_andnot_si256(decidable, ones)))));
    const __m256i nothing = _mm256_or_si256(
        _mm256_or_si256(culled, empty),
        _mm256_or_si256(zero_area, _mm256_andnot_si256(larger, _mm256_cmpeq_epi32(covered, zero))));
    const __m256i kind = select(undecided, _mm256_set1_epi32(BinningGroup::undecided),
                                select(nothing, zero,
                                       select(larger, _mm256_set1_epi32(BinningGroup::box_rows),
                                              _mm256_set1_epi32(BinningGroup::tiny))));
    alignas(32) std::int32_t lanes[2][binning_group_size];
    _mm256_store_si256(reinterpret_cast<__m256i*>(lanes[0]), covered);
    _mm256_store_si256(reinterpret_cast<__m256i*>(lanes[1]), front);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(group.x_begin), x_begin);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(group.y_begin), y_begin);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(group.y_end), y_end);
    auto lanes_of = [&](int kind_value) {
        return static_cast<unsigned>(_mm256_movemask_ps(
            _mm256_castsi256_ps(_mm256_cmpeq_epi32(kind, _mm256_set1_epi32(kind_value)))));
    };
    group.tiny_lanes = lanes_of(BinningGroup::tiny);
    group.box_lanes = lanes_of(BinningGroup::box_rows);
    group.undecided_lanes = lanes_of(BinningGroup::undecided);
    // Counted here, where the build has the population count instruction.
    group.undecided_count = std::popcount(group.undecided_lanes);
    for (int lane = 0; lane < binning_group_size; ++lane) {
        group.covered[lane] = static_cast<std::uint8_t>(lanes[0][lane]);
        group.front_facing[lane] = lanes[1][lane] != 0 ? 1 : 0;
    }
}

}  // namespace

#else

void classify_for_binning_avx2(const TriangleIndices*, std::uint32_t, const std::uint32_t*,
                               const WindowVertex*, int, int, BinningGroup& group) {
    group.leave_all_undecided();
}

void classify_grid_group_avx2(std::size_t, int, const std::uint32_t*, const std::int32_t*,
                              const std::int32_t*, int, int, BinningGroup& group) {
    group.leave_all_undecided();
}

#endif

}  // namespace weft::raster
