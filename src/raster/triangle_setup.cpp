#include "raster/triangle_setup.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "raster/viewport.h"

namespace weft::raster {
namespace {

struct FixedPoint {
    std::int64_t x, y;  // window coordinates × 256
};

FixedPoint snap(const glm::vec3& window) {
    return {static_cast<std::int64_t>(std::lrint(window.x * static_cast<float>(subpixel_scale))),
            static_cast<std::int64_t>(std::lrint(window.y * static_cast<float>(subpixel_scale)))};
}

// floor(value / 256) and ceil(value / 256) for any sign (>> is arithmetic in C++20).
std::int64_t floor_to_pixel(std::int64_t value) {
    return value >> subpixel_bits;
}
std::int64_t ceil_to_pixel(std::int64_t value) {
    return (value + subpixel_scale - 1) >> subpixel_bits;
}

}  // namespace

bool setup_triangle(const glm::vec4& clip0, const glm::vec4& clip1, const glm::vec4& clip2,
                    int viewport_width, int viewport_height, const PixelRect& scissor,
                    TriangleSetup& setup) {
    // Perspective divide and viewport.
    const glm::vec4* clip[3] = {&clip0, &clip1, &clip2};
    glm::vec3 window[3];
    for (int i = 0; i < 3; ++i) {
        window[i] = clip_to_window(*clip[i], viewport_width, viewport_height);
    }

    // Snap to fixed point.
    FixedPoint p[3] = {snap(window[0]), snap(window[1]), snap(window[2])};

    // Winding: twice the signed area, as edge 1→2 evaluated at vertex 0. Negative means
    // counter-clockwise on screen (y points down): the front face. Swapping two vertices
    // makes every triangle positive inside, so one pixel loop serves both sides.
    auto doubled_area = [&] {
        return (p[2].x - p[1].x) * (p[0].y - p[1].y) - (p[2].y - p[1].y) * (p[0].x - p[1].x);
    };
    std::int64_t area = doubled_area();
    if (area == 0) return false;
    setup.front_facing = area < 0;
    int order[3] = {0, 1, 2};
    if (setup.front_facing) {
        std::swap(p[1], p[2]);
        std::swap(order[1], order[2]);
        area = -area;
    }

    // Bounding box of the pixel centres (x + 0.5, y + 0.5) the triangle can cover, clamped
    // to the scissor: a triangle that fills the whole view from up close costs only the
    // pixels on screen.
    const std::int64_t half = subpixel_scale / 2;
    const std::int64_t min_x = std::min({p[0].x, p[1].x, p[2].x});
    const std::int64_t max_x = std::max({p[0].x, p[1].x, p[2].x});
    const std::int64_t min_y = std::min({p[0].y, p[1].y, p[2].y});
    const std::int64_t max_y = std::max({p[0].y, p[1].y, p[2].y});
    const std::int64_t x_begin =
        std::max<std::int64_t>(ceil_to_pixel(min_x - half), scissor.x_begin);
    const std::int64_t x_end =
        std::min<std::int64_t>(floor_to_pixel(max_x - half) + 1, scissor.x_end);
    const std::int64_t y_begin =
        std::max<std::int64_t>(ceil_to_pixel(min_y - half), scissor.y_begin);
    const std::int64_t y_end =
        std::min<std::int64_t>(floor_to_pixel(max_y - half) + 1, scissor.y_end);
    if (x_begin >= x_end || y_begin >= y_end) return false;
    setup.x_begin = static_cast<int>(x_begin);
    setup.x_end = static_cast<int>(x_end);
    setup.y_begin = static_cast<int>(y_begin);
    setup.y_end = static_cast<int>(y_end);

    // Edge functions, evaluated at the first pixel centre, with the top-left rule's bias.
    const std::int64_t origin_x = x_begin * subpixel_scale + half;
    const std::int64_t origin_y = y_begin * subpixel_scale + half;
    for (int i = 0; i < 3; ++i) {
        const FixedPoint& a = p[(i + 1) % 3];  // edge i runs between the other two vertices
        const FixedPoint& b = p[(i + 2) % 3];
        const std::int64_t gradient_x = a.y - b.y;
        const std::int64_t gradient_y = b.x - a.x;
        const bool top_left = gradient_x > 0 || (gradient_x == 0 && gradient_y > 0);
        setup.bias[i] = top_left ? 0 : -1;
        setup.edge_origin[i] =
            gradient_x * (origin_x - a.x) + gradient_y * (origin_y - a.y) + setup.bias[i];
        setup.step_x[i] = gradient_x * subpixel_scale;
        setup.step_y[i] = gradient_y * subpixel_scale;
        setup.inverse_step_x[i] = gradient_x > 0 ? 1.0 / static_cast<double>(setup.step_x[i]) : 0.0;
    }

    // What interpolation needs: barycentric normalisation, depth and 1/w per vertex.
    setup.inverse_doubled_area = static_cast<float>(1.0 / static_cast<double>(area));
    for (int i = 0; i < 3; ++i) {
        setup.vertex_order[i] = order[i];
        setup.depth[i] = window[order[i]].z;
        setup.inverse_w[i] = 1.0f / clip[order[i]]->w;
    }
    return true;
}

}  // namespace weft::raster
