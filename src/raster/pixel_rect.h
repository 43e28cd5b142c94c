// PixelRect: a half-open rectangle of pixels, [x_begin, x_end) × [y_begin, y_end).
//
// Every draw call takes one as its scissor: pixels outside it are never read or written. Today
// callers pass the whole framebuffer; a tiled, threaded renderer will pass one tile per thread.
#pragma once

#include <algorithm>
#include <limits>

namespace weft::raster {

struct PixelRect {
    int x_begin = 0;
    int y_begin = 0;
    int x_end = 0;
    int y_end = 0;

    // The scissor that clips nothing: intersected with a framebuffer it becomes the whole of it.
    static constexpr PixelRect unbounded() {
        return {0, 0, std::numeric_limits<int>::max(), std::numeric_limits<int>::max()};
    }

    constexpr int width() const { return x_end > x_begin ? x_end - x_begin : 0; }
    constexpr int height() const { return y_end > y_begin ? y_end - y_begin : 0; }
    constexpr bool empty() const { return x_end <= x_begin || y_end <= y_begin; }
    constexpr bool contains(int x, int y) const {
        return x >= x_begin && x < x_end && y >= y_begin && y < y_end;
    }

    constexpr PixelRect intersect(const PixelRect& other) const {
        return {std::max(x_begin, other.x_begin), std::max(y_begin, other.y_begin),
                std::min(x_end, other.x_end), std::min(y_end, other.y_end)};
    }

    friend constexpr bool operator==(const PixelRect&, const PixelRect&) = default;
};

}  // namespace weft::raster
