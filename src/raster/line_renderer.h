// Lines and points in 3-D: wireframes, springs coloured by strain, the ground grid, picked
// particles. Depth-tested against whatever the triangles left in the depth buffer.
//
// Pixel rule for a line from window point p0 to p1: along its major axis (x if |dx| >= |dy|,
// else y) it covers, for every pixel column (row) whose centre lies in [min, max) of the
// endpoints' coordinates, the one pixel the line passes through at that centre — a DDA that
// draws one pixel per column, half-open so a polyline does not draw its joints twice.
// Depth and 1/w are affine in screen space and are interpolated linearly; colours
// perspective-correctly.
//
// Depth bias: a wireframe lies exactly on its own surface, so equal depths would fight. The
// world-space drawing functions pull each endpoint towards the eye by `depth_bias` times its
// distance, which moves its depth but not its position on screen (scaling eye-space
// coordinates about the eye leaves x/w and y/w unchanged). Being relative, the bias grows
// with distance just as the depth buffer's resolution and a pixel's footprint do.
#pragma once

#include <span>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "raster/camera.h"
#include "raster/colour.h"
#include "raster/framebuffer.h"
#include "raster/mesh.h"
#include "raster/pixel_rect.h"

namespace weft::raster {

struct LineStyle {
    float depth_bias = 0.003f;  // fraction of the eye distance lines and points are pulled in
    bool depth_test = true;
    bool depth_write = true;
    // For lines lying in a surface drawn before them (wireframe, springs): the DDA's pixel
    // centre is up to half a pixel from the line, and where the surface is seen nearly
    // edge-on its depth changes faster across that half pixel than the bias covers, so the
    // surface would win at scattered pixels. With this set, a line pixel is tested against
    // the farther depth of its own pixel and of the neighbour on the line's side along the
    // minor axis (within the scissor), which brackets the surface's depth under the line.
    bool on_surface = false;
    PixelRect scissor = PixelRect::unbounded();
};

struct LineSegment {
    glm::vec3 a, b;
    Rgba8 colour_a, colour_b;
};

// A line endpoint after the divide: window position and depth, 1/w, and colour / w.
struct WindowPoint {
    glm::vec3 window;
    float inverse_w;
    glm::vec3 colour_over_w;
};

// A segment clipped and divided, ready for the pixel walk: what a line's drawing works out
// before it looks at the scissor. A frame drawn in bands sets each line up once and walks
// it in every band (prepare_lines, draw_prepared_lines), the same pixels as drawing it whole
// with each band's scissor.
struct PreparedLine {
    WindowPoint a, b;
    bool blend_colours = false;  // the ends' colours differ
};

// One segment given in clip space (no bias applied): near-plane clipped in clip space, then
// clipped to the framebuffer in window space so the DDA only walks pixels that can be drawn.
void draw_clip_space_line(Framebuffer& framebuffer, const glm::vec4& a, const glm::vec4& b,
                          Rgba8 colour_a, Rgba8 colour_b, const LineStyle& style = {});

void draw_lines(Framebuffer& framebuffer, const Camera& camera,
                std::span<const LineSegment> segments, const LineStyle& style = {});
// draw_lines in two halves: the segments set up (appended to `lines`, each pulled in by
// `depth_bias` as LineStyle's) and then drawn, as often as there are bands.
void prepare_lines(const Framebuffer& framebuffer, const Camera& camera,
                   std::span<const LineSegment> segments, float depth_bias,
                   std::vector<PreparedLine>& lines);
void draw_prepared_lines(Framebuffer& framebuffer, std::span<const PreparedLine> lines,
                         const LineStyle& style = {});

// Lines between shared vertices, each vertex transformed once: wireframes and springs.
// `line_colours` has one colour per line (else nothing is drawn).
void draw_indexed_lines(Framebuffer& framebuffer, const Camera& camera,
                        std::span<const glm::vec3> positions, std::span<const LineIndices> lines,
                        std::span<const Rgba8> line_colours, const LineStyle& style = {});
void draw_indexed_lines(Framebuffer& framebuffer, const Camera& camera,
                        std::span<const glm::vec3> positions, std::span<const LineIndices> lines,
                        Rgba8 colour, const LineStyle& style = {});

// Points as squares `size_pixels` wide centred on their projection (covering the pixels
// whose centres fall inside the square), all at the point's depth. Points behind the near
// plane are not drawn. `colours` has one colour per point (else nothing is drawn).
void draw_points(Framebuffer& framebuffer, const Camera& camera,
                 std::span<const glm::vec3> positions, std::span<const Rgba8> colours,
                 float size_pixels, const LineStyle& style = {});
void draw_points(Framebuffer& framebuffer, const Camera& camera,
                 std::span<const glm::vec3> positions, Rgba8 colour, float size_pixels,
                 const LineStyle& style = {});

}  // namespace weft::raster
