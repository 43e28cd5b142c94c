// Triangle setup: from three clip-space positions (already clipped, w > 0) to what the pixel
// loop needs. Stages:
//   perspective divide  →  viewport  →  snap to fixed point  →  winding / facing
//   →  edge functions with the top-left fill rule  →  bounding box clamped to the scissor.
//
// Fixed point (Giesen, "The barycentric conspiracy" / "Triangle rasterization in practice"):
// window coordinates are rounded to 1/256 pixel. Every later coverage decision is exact
// integer arithmetic on those snapped values, so two triangles sharing an edge see exactly
// opposite edge functions along it, and the top-left rule gives each pixel centre on the edge
// to exactly one of them: no cracks, no pixel drawn twice.
//
// Edge function of the directed edge a→b at point p (window space, y down):
//     E(p) = (a.y - b.y)·p.x + (b.x - a.x)·p.y + (a.x·b.y - a.y·b.x)
// Setup orders the vertices so E > 0 inside for all three edges. Its gradient (A, B) points
// inwards; a pixel centre exactly on an edge (E = 0) belongs to the triangle only if the edge
// is a left edge (A > 0: the inside is to its right) or a top edge (A = 0, B > 0: horizontal
// with the inside below). Non-top-left edges get a bias of -1 so "covered" is simply
// "all three biased values >= 0".
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <utility>

#include <glm/vec4.hpp>

#include "raster/pixel_rect.h"
#include "raster/viewport.h"

namespace weft::raster {

inline constexpr int subpixel_bits = 8;
inline constexpr std::int64_t subpixel_scale = std::int64_t{1} << subpixel_bits;  // 256

// Filled in by setup_triangle, and meaningful only when it returns true. The arrays have no
// initialisers on purpose: a setup is made for every triangle drawn, and zeroing its ~200
// bytes each time took 15 % of the pixel loop's time in a profile of a 128² cloth.
struct TriangleSetup {
    // Pixels to visit: the bounding box of the snapped triangle ∩ the scissor, half-open.
    int x_begin = 0, y_begin = 0, x_end = 0, y_end = 0;

    // Biased edge functions at the centre of pixel (x_begin, y_begin), in units of
    // 1/256² pixel², and their change per pixel step in x and in y. Edge i is opposite
    // vertex i, so its unbiased value divided by the doubled area is vertex i's barycentric.
    std::int64_t edge_origin[3];
    std::int64_t step_x[3];
    std::int64_t step_y[3];
    std::int64_t bias[3];  // 0 for top-left edges, -1 otherwise (already in edge_origin)

    // 1 / step_x for edges that bound the span from the left (step_x > 0), else 0: lets the
    // pixel loop jump to near the first covered pixel of a row instead of testing every one.
    // All 0 for a box only a few pixels wide, whose rows are walked pixel by pixel.
    double inverse_step_x[3];

    float inverse_doubled_area = 0.0f;  // 1 / (sum of the three unbiased edge values)
    float depth[3];                     // window depth of each vertex, [0, 1]
    float inverse_w[3];                 // 1/w of each vertex, for perspective correction

    // Setup vertex i is input vertex vertex_order[i]: front-facing triangles swap two
    // vertices so that the edge functions are positive inside.
    int vertex_order[3] = {0, 1, 2};

    // Counter-clockwise on screen, i.e. counter-clockwise seen from the side it is viewed
    // from — OpenGL's default front face. A mesh listing its triangles counter-clockwise
    // seen from the front therefore shows its front where front_facing is true.
    bool front_facing = true;
};

// One vertex after the perspective divide, the viewport and the snap to fixed point: all
// that setup needs of it. A mesh shares each vertex between about six triangles, so mesh
// drawing makes these once per vertex (mesh_renderer.h) rather than once per corner.
struct WindowVertex {
    std::int64_t x = 0, y = 0;  // window coordinates × 256, rounded to nearest
    float depth = 0.0f;         // window depth, [0, 1]
    float inverse_w = 0.0f;     // 1 / w, for perspective correction
};

// The position must have w > 0 and lie inside the guard band (see clipping.h). Inline: mesh
// drawing makes one for every vertex of every frame.
inline WindowVertex window_vertex(const glm::vec4& clip, int viewport_width, int viewport_height) {
    const glm::vec3 window = clip_to_window(clip, viewport_width, viewport_height);
    auto snap = [](float coordinate) {
        return static_cast<std::int64_t>(
            std::lrint(coordinate * static_cast<float>(subpixel_scale)));
    };
    return {snap(window.x), snap(window.y), window.z, 1.0f / clip.w};
}

namespace detail {

// floor(value / 256) and ceil(value / 256) for any sign (>> is arithmetic in C++20).
inline std::int64_t floor_to_pixel(std::int64_t value) {
    return value >> subpixel_bits;
}
inline std::int64_t ceil_to_pixel(std::int64_t value) {
    return (value + subpixel_scale - 1) >> subpixel_bits;
}

// Twice the signed area, as edge 1→2 evaluated at vertex 0. Negative means
// counter-clockwise on screen (y points down): the front face.
inline std::int64_t doubled_area(const WindowVertex& p0, const WindowVertex& p1,
                                 const WindowVertex& p2) {
    return (p2.x - p1.x) * (p0.y - p1.y) - (p2.y - p1.y) * (p0.x - p1.x);
}

// The pixels whose centres (x + 0.5, y + 0.5) the bounding box holds, clamped to `scissor`,
// half-open; empty if none.
inline PixelRect covered_box(const WindowVertex& p0, const WindowVertex& p1, const WindowVertex& p2,
                             const PixelRect& scissor) {
    const std::int64_t half = subpixel_scale / 2;
    const std::int64_t min_x = std::min({p0.x, p1.x, p2.x});
    const std::int64_t max_x = std::max({p0.x, p1.x, p2.x});
    const std::int64_t min_y = std::min({p0.y, p1.y, p2.y});
    const std::int64_t max_y = std::max({p0.y, p1.y, p2.y});
    const std::int64_t x_begin =
        std::max<std::int64_t>(ceil_to_pixel(min_x - half), scissor.x_begin);
    const std::int64_t x_end =
        std::min<std::int64_t>(floor_to_pixel(max_x - half) + 1, scissor.x_end);
    const std::int64_t y_begin =
        std::max<std::int64_t>(ceil_to_pixel(min_y - half), scissor.y_begin);
    const std::int64_t y_end =
        std::min<std::int64_t>(floor_to_pixel(max_y - half) + 1, scissor.y_end);
    if (x_begin >= x_end || y_begin >= y_end) return {0, 0, 0, 0};
    return {static_cast<int>(x_begin), static_cast<int>(y_begin), static_cast<int>(x_end),
            static_cast<int>(y_end)};
}

// The edge function of the directed edge a→b, biased by the top-left rule: a point
// (x, y) in 1/256 pixel is on the inside when at(x, y) >= 0.
struct EdgeFunction {
    std::int64_t gradient_x, gradient_y, bias;
    std::int64_t a_x, a_y;

    EdgeFunction(const WindowVertex& a, const WindowVertex& b)
        : gradient_x(a.y - b.y), gradient_y(b.x - a.x), a_x(a.x), a_y(a.y) {
        const bool top_left = gradient_x > 0 || (gradient_x == 0 && gradient_y > 0);
        bias = top_left ? 0 : -1;
    }
    std::int64_t at(std::int64_t x, std::int64_t y) const {
        return gradient_x * (x - a_x) + gradient_y * (y - a_y) + bias;
    }
};

// Rows narrower than this many pixels are walked pixel by pixel: jumping to the first
// covered pixel costs more than it saves.
inline constexpr int narrow_span = 8;

}  // namespace detail

// Returns false if nothing can be drawn: zero area after snapping, or no pixel centre of
// the bounding box inside `scissor` (which must already lie inside the framebuffer).
// Inline: it runs once per triangle drawn, and the pixel loop reads what it writes.
inline bool setup_triangle(const WindowVertex& vertex0, const WindowVertex& vertex1,
                           const WindowVertex& vertex2, const PixelRect& scissor,
                           TriangleSetup& setup) {
    const WindowVertex* p[3] = {&vertex0, &vertex1, &vertex2};

    // Winding: swapping two vertices of a front face makes every triangle positive inside,
    // so one pixel loop serves both sides.
    std::int64_t area = detail::doubled_area(*p[0], *p[1], *p[2]);
    if (area == 0) return false;
    setup.front_facing = area < 0;
    int order[3] = {0, 1, 2};
    if (setup.front_facing) {
        std::swap(p[1], p[2]);
        std::swap(order[1], order[2]);
        area = -area;
    }

    // Bounding box of the pixel centres the triangle can cover, clamped to the scissor: a
    // triangle that fills the whole view from up close costs only the pixels on screen.
    const PixelRect box = detail::covered_box(*p[0], *p[1], *p[2], scissor);
    if (box.empty()) return false;
    setup.x_begin = box.x_begin;
    setup.x_end = box.x_end;
    setup.y_begin = box.y_begin;
    setup.y_end = box.y_end;
    const bool narrow = box.width() < detail::narrow_span;

    // Edge functions, evaluated at the first pixel centre, with the top-left rule's bias.
    const std::int64_t half = subpixel_scale / 2;
    const std::int64_t origin_x = std::int64_t{box.x_begin} * subpixel_scale + half;
    const std::int64_t origin_y = std::int64_t{box.y_begin} * subpixel_scale + half;
    for (int i = 0; i < 3; ++i) {
        // Edge i runs between the other two vertices.
        const detail::EdgeFunction edge(*p[(i + 1) % 3], *p[(i + 2) % 3]);
        setup.bias[i] = edge.bias;
        setup.edge_origin[i] = edge.at(origin_x, origin_y);
        setup.step_x[i] = edge.gradient_x * subpixel_scale;
        setup.step_y[i] = edge.gradient_y * subpixel_scale;
        setup.inverse_step_x[i] =
            edge.gradient_x > 0 && !narrow ? 1.0 / static_cast<double>(setup.step_x[i]) : 0.0;
    }

    // What interpolation needs: barycentric normalisation, depth and 1/w per vertex.
    setup.inverse_doubled_area = static_cast<float>(1.0 / static_cast<double>(area));
    for (int i = 0; i < 3; ++i) {
        setup.vertex_order[i] = order[i];
        setup.depth[i] = p[i]->depth;
        setup.inverse_w[i] = p[i]->inverse_w;
    }
    return true;
}

// The same from clip-space positions (w > 0, inside the guard band).
bool setup_triangle(const glm::vec4& clip0, const glm::vec4& clip1, const glm::vec4& clip2,
                    int viewport_width, int viewport_height, const PixelRect& scissor,
                    TriangleSetup& setup);

// Boxes at most this many pixel centres wide and high are tiny: bin_coverage decides their
// coverage exactly, and the rasterizer shades them without its row walk (traverse_tiny).
inline constexpr int tiny_box_side = 2;

namespace detail {

// A tiny box's four pixel centres — its first, the one right of it, the one below, the
// diagonal — as bit (row · 2 + column): the biased values of the three edge functions at
// each, and which of them lie inside the box (columns × rows) and are covered. All four are
// evaluated whatever the box's size, so that no branch depends on the triangle's shape.
struct TinyCoverage {
    std::int64_t edges[tiny_box_side * tiny_box_side][3];
    unsigned covered = 0;
};
inline TinyCoverage tiny_coverage(const std::int64_t (&at_first)[3],
                                  const std::int64_t (&step_x)[3], const std::int64_t (&step_y)[3],
                                  int columns, int rows) {
    static_assert(tiny_box_side == 2, "four centres: the first, right, below, diagonal");
    TinyCoverage coverage;
    std::int64_t any_outside[tiny_box_side * tiny_box_side] = {0, 0, 0, 0};
    for (int i = 0; i < 3; ++i) {
        coverage.edges[0][i] = at_first[i];
        coverage.edges[1][i] = at_first[i] + step_x[i];
        coverage.edges[2][i] = at_first[i] + step_y[i];
        coverage.edges[3][i] = at_first[i] + step_x[i] + step_y[i];
        for (int k = 0; k < tiny_box_side * tiny_box_side; ++k)
            any_outside[k] |= coverage.edges[k][i];
    }
    const unsigned in_box =
        columns == 2 ? (rows == 2 ? 0b1111u : 0b0011u) : (rows == 2 ? 0b0101u : 0b0001u);
    for (int k = 0; k < tiny_box_side * tiny_box_side; ++k)
        coverage.covered |= static_cast<unsigned>(any_outside[k] >= 0) << k;
    coverage.covered &= in_box;
    return coverage;
}

}  // namespace detail

// A pixel centre that a tiny triangle covers, found while binning (bin_coverage), with all
// that shading it needs of the triangle's setup: its barycentric weights, as the pixel loop
// computes them from the same integer edge values. A sheet seen whole has about as many
// triangles as pixels: drawing these, the band that draws a tiny triangle does not set it up
// again.
struct BinnedFragment {
    static constexpr std::uint32_t front_bit = std::uint32_t{1} << 31;
    std::uint32_t triangle = 0;  // the mesh's triangle index, | front_bit when front-facing
    std::uint16_t x = 0, y = 0;  // pixel
    float weight[3] = {};        // barycentric of setup vertex i (triangle_setup.h's order)

    std::uint32_t triangle_index() const { return triangle & ~front_bit; }
    bool front_facing() const { return (triangle & front_bit) != 0; }
    // The triangle's vertex indices in setup order: a front face swaps its second and third.
    std::array<std::uint32_t, 3> setup_vertices(const std::array<std::uint32_t, 3>& t) const {
        return front_facing() ? std::array<std::uint32_t, 3>{t[0], t[2], t[1]} : t;
    }
};

// What binning learns of a snapped triangle inside `bounds`: the rows of the pixel centres
// it covers, exactly as setup_triangle and the pixel loop decide it, for a triangle whose box
// holds at most 2×2 of them (tiny) — and then also which of those centres it covers and their
// weights. Many triangles of a sheet seen whole fall between pixel centres and cover none.
// A larger triangle is not examined: the rows of its box. Empty rows (first > last) when it
// covers nothing, has zero area once snapped, or its box holds no pixel centre of `bounds`.
struct BinnedCoverage {
    int first = 0, last = -1;  // rows, inclusive
    bool tiny = false;
    // For a tiny triangle that covers something: its box's first pixel centre, the covered
    // centres as bit (row · 2 + column), the side seen, and each covered centre's weights.
    int x_begin = 0, y_begin = 0;
    unsigned covered = 0;
    bool front_facing = false;
    float weights[tiny_box_side * tiny_box_side][3];

    bool empty() const { return first > last; }
};
inline void bin_coverage(const WindowVertex& vertex0, const WindowVertex& vertex1,
                         const WindowVertex& vertex2, const PixelRect& bounds,
                         BinnedCoverage& coverage) {
    coverage.first = 0;
    coverage.last = -1;
    coverage.tiny = false;
    std::int64_t area = detail::doubled_area(vertex0, vertex1, vertex2);
    if (area == 0) return;
    const PixelRect box = detail::covered_box(vertex0, vertex1, vertex2, bounds);
    if (box.empty()) return;
    if (box.width() > tiny_box_side || box.height() > tiny_box_side) {
        coverage.first = box.y_begin;
        coverage.last = box.y_end - 1;
        return;
    }
    const WindowVertex* p[3] = {&vertex0, &vertex1, &vertex2};
    coverage.front_facing = area < 0;
    if (coverage.front_facing) {  // as setup_triangle orders a front face
        std::swap(p[1], p[2]);
        area = -area;
    }
    const std::int64_t half = subpixel_scale / 2;
    const std::int64_t origin_x = std::int64_t{box.x_begin} * subpixel_scale + half;
    const std::int64_t origin_y = std::int64_t{box.y_begin} * subpixel_scale + half;
    std::int64_t at_first[3], step_x[3], step_y[3], bias[3];
    for (int i = 0; i < 3; ++i) {  // as setup_triangle makes them
        const detail::EdgeFunction edge(*p[(i + 1) % 3], *p[(i + 2) % 3]);
        at_first[i] = edge.at(origin_x, origin_y);
        step_x[i] = edge.gradient_x * subpixel_scale;
        step_y[i] = edge.gradient_y * subpixel_scale;
        bias[i] = edge.bias;
    }
    const detail::TinyCoverage tiny =
        detail::tiny_coverage(at_first, step_x, step_y, box.width(), box.height());
    if (tiny.covered == 0) return;
    const bool top_row = (tiny.covered & 0b0011u) != 0, bottom_row = (tiny.covered & 0b1100u) != 0;
    coverage.first = top_row ? box.y_begin : box.y_begin + 1;
    coverage.last = bottom_row ? box.y_begin + 1 : box.y_begin;
    coverage.tiny = true;
    coverage.x_begin = box.x_begin;
    coverage.y_begin = box.y_begin;
    coverage.covered = tiny.covered;
    // As PixelShading weighs a covered centre: the unbiased edge value over the doubled area.
    const auto inverse_area = static_cast<float>(1.0 / static_cast<double>(area));
    for (unsigned left = tiny.covered; left != 0; left &= left - 1) {
        const int k = std::countr_zero(left);
        for (int i = 0; i < 3; ++i)
            coverage.weights[k][i] = static_cast<float>(tiny.edges[k][i] - bias[i]) * inverse_area;
    }
}

}  // namespace weft::raster
