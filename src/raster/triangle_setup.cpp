#include "raster/triangle_setup.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "raster/viewport.h"

namespace weft::raster {
namespace {

std::int64_t snap(float window_coordinate) {
    return static_cast<std::int64_t>(
        std::lrint(window_coordinate * static_cast<float>(subpixel_scale)));
}

// floor(value / 256) and ceil(value / 256) for any sign (>> is arithmetic in C++20).
std::int64_t floor_to_pixel(std::int64_t value) {
    return value >> subpixel_bits;
}
std::int64_t ceil_to_pixel(std::int64_t value) {
    return (value + subpixel_scale - 1) >> subpixel_bits;
}

// Twice the signed area, as edge 1→2 evaluated at vertex 0. Negative means
// counter-clockwise on screen (y points down): the front face.
std::int64_t doubled_area(const WindowVertex& p0, const WindowVertex& p1, const WindowVertex& p2) {
    return (p2.x - p1.x) * (p0.y - p1.y) - (p2.y - p1.y) * (p0.x - p1.x);
}

// The pixels whose centres (x + 0.5, y + 0.5) the bounding box holds, clamped to `scissor`,
// half-open; empty if none.
PixelRect covered_box(const WindowVertex& p0, const WindowVertex& p1, const WindowVertex& p2,
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

// Rows narrower than this many pixels are walked pixel by pixel: jumping to the first
// covered pixel costs more than it saves.
constexpr int narrow_span = 8;

}  // namespace

WindowVertex window_vertex(const glm::vec4& clip, int viewport_width, int viewport_height) {
    const glm::vec3 window = clip_to_window(clip, viewport_width, viewport_height);
    return {snap(window.x), snap(window.y), window.z, 1.0f / clip.w};
}

bool may_cover_pixels(const WindowVertex& vertex0, const WindowVertex& vertex1,
                      const WindowVertex& vertex2, const PixelRect& bounds) {
    return doubled_area(vertex0, vertex1, vertex2) != 0 &&
           !covered_box(vertex0, vertex1, vertex2, bounds).empty();
}

bool setup_triangle(const glm::vec4& clip0, const glm::vec4& clip1, const glm::vec4& clip2,
                    int viewport_width, int viewport_height, const PixelRect& scissor,
                    TriangleSetup& setup) {
    return setup_triangle(window_vertex(clip0, viewport_width, viewport_height),
                          window_vertex(clip1, viewport_width, viewport_height),
                          window_vertex(clip2, viewport_width, viewport_height), scissor, setup);
}

bool setup_triangle(const WindowVertex& vertex0, const WindowVertex& vertex1,
                    const WindowVertex& vertex2, const PixelRect& scissor, TriangleSetup& setup) {
    const WindowVertex* p[3] = {&vertex0, &vertex1, &vertex2};

    // Winding: swapping two vertices of a front face makes every triangle positive inside,
    // so one pixel loop serves both sides.
    std::int64_t area = doubled_area(*p[0], *p[1], *p[2]);
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
    const PixelRect box = covered_box(*p[0], *p[1], *p[2], scissor);
    if (box.empty()) return false;
    setup.x_begin = box.x_begin;
    setup.x_end = box.x_end;
    setup.y_begin = box.y_begin;
    setup.y_end = box.y_end;
    const bool narrow = box.width() < narrow_span;

    // Edge functions, evaluated at the first pixel centre, with the top-left rule's bias.
    const std::int64_t half = subpixel_scale / 2;
    const std::int64_t origin_x = std::int64_t{box.x_begin} * subpixel_scale + half;
    const std::int64_t origin_y = std::int64_t{box.y_begin} * subpixel_scale + half;
    for (int i = 0; i < 3; ++i) {
        const WindowVertex& a = *p[(i + 1) % 3];  // edge i runs between the other two vertices
        const WindowVertex& b = *p[(i + 2) % 3];
        const std::int64_t gradient_x = a.y - b.y;
        const std::int64_t gradient_y = b.x - a.x;
        const bool top_left = gradient_x > 0 || (gradient_x == 0 && gradient_y > 0);
        setup.bias[i] = top_left ? 0 : -1;
        setup.edge_origin[i] =
            gradient_x * (origin_x - a.x) + gradient_y * (origin_y - a.y) + setup.bias[i];
        setup.step_x[i] = gradient_x * subpixel_scale;
        setup.step_y[i] = gradient_y * subpixel_scale;
        setup.inverse_step_x[i] =
            gradient_x > 0 && !narrow ? 1.0 / static_cast<double>(setup.step_x[i]) : 0.0;
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

}  // namespace weft::raster
