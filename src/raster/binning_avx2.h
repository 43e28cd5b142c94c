// Binning's classification of triangles, eight at a time with AVX2 (binning_avx2.cpp; only
// that file gets the instruction set, and it runs only where the CPU has it).
//
// A sheet seen whole has about as many triangles as pixels, and nearly all of them are tiny:
// a box of at most 2×2 pixel centres (triangle_setup.h). For those, every value binning needs
// fits in 32 bits once taken relative to the box's first pixel centre: with the triangle's
// extent below 1024/256 pixel a side, the edge functions stay below 2^22 and are exact in
// int32 and in float. So the group's eight triangles get their cull, box, facing, edge
// functions and coverage in vector lanes, and the scalar code only emits what they cover. A
// larger triangle of such an extent needs only its box's rows. A triangle the lanes cannot
// decide (an index out of range, one that needs clipping, or an extent of more than 1024/256
// pixel) is left to the scalar path: it says so, and nothing else.
#pragma once

#include <cstddef>
#include <cstdint>

#include "raster/mesh.h"
#include "raster/triangle_setup.h"

namespace weft::raster {

inline constexpr int binning_group_size = 8;

// What the lanes decided, lane by lane (lane i is the group's i-th triangle).
struct BinningGroup {
    enum Kind : std::uint8_t {
        draws_nothing = 0,  // culled, outside the view, between pixel centres or of zero area
        tiny = 1,           // covers the centres in `covered`, with the values below
        box_rows = 2,       // larger than tiny: may reach rows [y_begin, y_end)
        undecided = 3,      // for the scalar path
    };
    // The decisions as lane masks (bit i for lane i; a lane in none draws nothing), so that
    // binning visits only the lanes that put something in a band: a sheet seen whole has
    // many triangles that cover no pixel centre.
    unsigned tiny_lanes = 0, box_lanes = 0, undecided_lanes = 0;
    int undecided_count = 0;                   // lanes in undecided_lanes
    std::uint8_t covered[binning_group_size];  // bit (row · 2 + column) of the box
    std::uint8_t front_facing[binning_group_size];
    std::int32_t x_begin[binning_group_size], y_begin[binning_group_size];
    std::int32_t y_end[binning_group_size];
    // The weight of setup vertex i at centre k (first, right, below, diagonal) of a tiny
    // triangle: bin_coverage's, to the bit.
    float weight[tiny_box_side * tiny_box_side][3][binning_group_size];

    Kind kind(int lane) const {
        const unsigned bit = 1u << lane;
        if ((tiny_lanes & bit) != 0) return tiny;
        if ((box_lanes & bit) != 0) return box_rows;
        if ((undecided_lanes & bit) != 0) return undecided;
        return draws_nothing;
    }
    // Every lane left to the scalar path.
    void leave_all_undecided() {
        tiny_lanes = box_lanes = 0;
        undecided_lanes = (1u << binning_group_size) - 1;
        undecided_count = binning_group_size;
    }
};

// Classifies the eight triangles from `triangles` (of a mesh with `vertex_count` vertices,
// whose outcodes and window positions are given) inside a viewport width × height pixels of at
// most 65535 a side. Only where avx2_supported() (vector_isa.h).
void classify_for_binning_avx2(const TriangleIndices* triangles, std::uint32_t vertex_count,
                               const std::uint32_t* outcodes, const WindowVertex* window, int width,
                               int height, BinningGroup& group);

// A mesh that is a whole grid (grid_normals.h) needs no gathers: the group of its triangles
// [first_triangle, first_triangle + 8) is four cells of one row when first_triangle is even
// and the row has four cells from there. Then its corners are five consecutive vertices of
// two rows, loaded and put in place by permutations.
inline bool grid_group_fits(std::size_t first_triangle, int grid_cols) {
    if (grid_cols < 2 || first_triangle % 2 != 0) return false;
    const auto cells_per_row = static_cast<std::size_t>(grid_cols - 1);
    return (first_triangle / 2) % cells_per_row + binning_group_size / 2 <= cells_per_row;
}

// classify_for_binning_avx2 for such a group of a grid grid_cols vertices wide, from the
// vertices' outcodes and the x and y of their window positions (in 1/256 pixel, the low
// halves of WindowVertex's, one array each): the same group, lane for lane.
void classify_grid_group_avx2(std::size_t first_triangle, int grid_cols,
                              const std::uint32_t* outcodes, const std::int32_t* snapped_x,
                              const std::int32_t* snapped_y, int width, int height,
                              BinningGroup& group);

}  // namespace weft::raster
