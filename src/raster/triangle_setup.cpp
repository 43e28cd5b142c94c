#include "raster/triangle_setup.h"

#include <cmath>

#include "raster/viewport.h"

namespace weft::raster {
namespace {

std::int64_t snap(float window_coordinate) {
    return static_cast<std::int64_t>(
        std::lrint(window_coordinate * static_cast<float>(subpixel_scale)));
}

}  // namespace

WindowVertex window_vertex(const glm::vec4& clip, int viewport_width, int viewport_height) {
    const glm::vec3 window = clip_to_window(clip, viewport_width, viewport_height);
    return {snap(window.x), snap(window.y), window.z, 1.0f / clip.w};
}

bool setup_triangle(const glm::vec4& clip0, const glm::vec4& clip1, const glm::vec4& clip2,
                    int viewport_width, int viewport_height, const PixelRect& scissor,
                    TriangleSetup& setup) {
    return setup_triangle(window_vertex(clip0, viewport_width, viewport_height),
                          window_vertex(clip1, viewport_width, viewport_height),
                          window_vertex(clip2, viewport_width, viewport_height), scissor, setup);
}

}  // namespace weft::raster
