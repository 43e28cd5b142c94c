#include "raster/ground_grid.h"

#include <algorithm>

namespace weft::raster {

void draw_ground_grid(Framebuffer& framebuffer, const Camera& camera, const GroundGrid& grid,
                      const LineStyle& style) {
    const int cells = std::clamp(grid.cell_count, 1, 1000);
    const float half_extent = 0.5f * static_cast<float>(cells) * grid.cell_size;
    const float x0 = grid.centre.x - half_extent, z0 = grid.centre.y - half_extent;
    const float x1 = grid.centre.x + half_extent, z1 = grid.centre.y + half_extent;
    LineSegment segments[2];
    for (int i = 0; i <= cells; ++i) {
        const float offset = static_cast<float>(i) * grid.cell_size;
        const Rgba8 colour = 2 * i == cells ? grid.centre_colour : grid.colour;
        segments[0] = {
            {x0 + offset, grid.height, z0}, {x0 + offset, grid.height, z1}, colour, colour};
        segments[1] = {
            {x0, grid.height, z0 + offset}, {x1, grid.height, z0 + offset}, colour, colour};
        draw_lines(framebuffer, camera, segments, style);
    }
}

}  // namespace weft::raster
