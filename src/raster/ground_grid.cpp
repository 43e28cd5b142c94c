#include "raster/ground_grid.h"

#include <algorithm>
#include <cmath>
#include <span>

#include <glm/geometric.hpp>

namespace weft::raster {

PlaneGrid PlaneGrid::facing(const glm::vec3& centre, const glm::vec3& normal) {
    const glm::vec3 n = glm::normalize(normal);
    // Across the slope: horizontal and in the plane. A horizontal plane has every horizontal
    // direction in it; take x, as the ground grid does.
    glm::vec3 across = glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), n);
    across = glm::length(across) > 1e-6f ? glm::normalize(across) : glm::vec3(1.0f, 0.0f, 0.0f);
    PlaneGrid grid;
    grid.centre = centre;
    grid.axis_u = across;
    grid.axis_v = glm::normalize(glm::cross(n, across));
    return grid;
}

namespace {

PlaneGrid plane_of(const GroundGrid& grid) {
    PlaneGrid plane;
    plane.centre = {grid.centre.x, grid.height, grid.centre.y};
    plane.cell_count = grid.cell_count;
    plane.cell_size = grid.cell_size;
    plane.colour = grid.colour;
    plane.centre_colour = grid.centre_colour;
    return plane;
}

}  // namespace

void prepare_plane_grid(const Framebuffer& framebuffer, const Camera& camera, const PlaneGrid& grid,
                        float depth_bias, std::vector<PreparedLine>& lines) {
    const int cells = std::clamp(grid.cell_count, 1, 1000);
    const float half_extent = 0.5f * static_cast<float>(cells) * grid.cell_size;
    const glm::vec3 corner = grid.centre - half_extent * (grid.axis_u + grid.axis_v);
    const glm::vec3 along_u = 2.0f * half_extent * grid.axis_u;
    const glm::vec3 along_v = 2.0f * half_extent * grid.axis_v;
    // The lines a batch at a time: each call works out the camera's matrices again.
    constexpr int batch_lines = 64;
    LineSegment segments[batch_lines];
    int queued = 0;
    for (int i = 0; i <= cells; ++i) {
        const float offset = static_cast<float>(i) * grid.cell_size;
        const Rgba8 colour = 2 * i == cells ? grid.centre_colour : grid.colour;
        const glm::vec3 u_line = corner + offset * grid.axis_u;  // a line along v at this u
        const glm::vec3 v_line = corner + offset * grid.axis_v;  // a line along u at this v
        segments[queued++] = {u_line, u_line + along_v, colour, colour};
        segments[queued++] = {v_line, v_line + along_u, colour, colour};
        if (queued == batch_lines || i == cells) {
            prepare_lines(framebuffer, camera, std::span<const LineSegment>(segments, queued),
                          depth_bias, lines);
            queued = 0;
        }
    }
}

void draw_plane_grid(Framebuffer& framebuffer, const Camera& camera, const PlaneGrid& grid,
                     const LineStyle& style) {
    std::vector<PreparedLine> lines;
    prepare_plane_grid(framebuffer, camera, grid, style.depth_bias, lines);
    draw_prepared_lines(framebuffer, lines, style);
}

void prepare_ground_grid(const Framebuffer& framebuffer, const Camera& camera,
                         const GroundGrid& grid, float depth_bias,
                         std::vector<PreparedLine>& lines) {
    prepare_plane_grid(framebuffer, camera, plane_of(grid), depth_bias, lines);
}

void draw_ground_grid(Framebuffer& framebuffer, const Camera& camera, const GroundGrid& grid,
                      const LineStyle& style) {
    draw_plane_grid(framebuffer, camera, plane_of(grid), style);
}

}  // namespace weft::raster
