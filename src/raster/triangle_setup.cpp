#include "raster/triangle_setup.h"

namespace weft::raster {

bool setup_triangle(const glm::vec4& clip0, const glm::vec4& clip1, const glm::vec4& clip2,
                    int viewport_width, int viewport_height, const PixelRect& scissor,
                    TriangleSetup& setup) {
    return setup_triangle(window_vertex(clip0, viewport_width, viewport_height),
                          window_vertex(clip1, viewport_width, viewport_height),
                          window_vertex(clip2, viewport_width, viewport_height), scissor, setup);
}

}  // namespace weft::raster
