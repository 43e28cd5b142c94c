// A ground grid: square cells on the horizontal plane y = height, drawn as depth-tested
// lines so the cloth and colliders sit visibly above (or fall through) the floor.
#pragma once

#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "raster/camera.h"
#include "raster/colour.h"
#include "raster/framebuffer.h"
#include "raster/line_renderer.h"

namespace weft::raster {

struct GroundGrid {
    float height = 0.0f;           // y of the plane
    glm::vec2 centre{0.0f, 0.0f};  // (x, z) of the grid's centre
    int cell_count = 20;           // cells per side (clamped to 1..1000)
    float cell_size = 0.25f;       // m
    Rgba8 colour{92, 96, 104, 255};
    Rgba8 centre_colour{130, 136, 148, 255};  // the two lines through the centre
};

// Draws cell_count + 1 lines in each direction. Lines running behind the camera are clipped
// at the near plane, so the grid never wraps over the sky.
void draw_ground_grid(Framebuffer& framebuffer, const Camera& camera, const GroundGrid& grid,
                      const LineStyle& style = {});
// Its lines set up for drawing in bands (line_renderer.h: prepare_lines), appended to `lines`.
void prepare_ground_grid(const Framebuffer& framebuffer, const Camera& camera,
                         const GroundGrid& grid, float depth_bias,
                         std::vector<PreparedLine>& lines);

// The same grid on any plane: square cells along two perpendicular unit axes of the plane,
// centred on a point of it (a tilted plane collider: a slope, a wall).
struct PlaneGrid {
    glm::vec3 centre{0.0f};              // m, a point of the plane, the grid's centre
    glm::vec3 axis_u{1.0f, 0.0f, 0.0f};  // unit, in the plane
    glm::vec3 axis_v{0.0f, 0.0f, 1.0f};  // unit, in the plane, perpendicular to axis_u
    int cell_count = 20;                 // cells per side (clamped to 1..1000)
    float cell_size = 0.25f;             // m
    Rgba8 colour{92, 96, 104, 255};
    Rgba8 centre_colour{130, 136, 148, 255};

    // Axes for the plane with this normal (any length but zero): axis_u horizontal where
    // the plane is not, so a slope's lines run across it and down it.
    static PlaneGrid facing(const glm::vec3& centre, const glm::vec3& normal);
};

void draw_plane_grid(Framebuffer& framebuffer, const Camera& camera, const PlaneGrid& grid,
                     const LineStyle& style = {});
void prepare_plane_grid(const Framebuffer& framebuffer, const Camera& camera, const PlaneGrid& grid,
                        float depth_bias, std::vector<PreparedLine>& lines);

}  // namespace weft::raster
