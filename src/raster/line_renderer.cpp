#include "raster/line_renderer.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include <glm/mat4x4.hpp>

#include "raster/clipping.h"
#include "raster/viewport.h"

namespace weft::raster {
namespace {

// World → clip with the depth bias folded in: eye-space points are scaled towards the eye.
class BiasedProjection {
  public:
    BiasedProjection(const Camera& camera, const Framebuffer& framebuffer, float depth_bias)
        : view_(view_matrix(camera)),
          projection_(
              projection_matrix(camera, aspect_ratio(framebuffer.width(), framebuffer.height()))),
          scale_(1.0f - std::clamp(depth_bias, 0.0f, 0.5f)) {}

    glm::vec4 operator()(const glm::vec3& world) const {
        const glm::vec4 eye = view_ * glm::vec4(world, 1.0f);
        return projection_ * glm::vec4(glm::vec3(eye) * scale_, 1.0f);
    }

  private:
    glm::mat4 view_;
    glm::mat4 projection_;
    float scale_;
};

WindowPoint lerp(const WindowPoint& a, const WindowPoint& b, float t) {
    return {a.window + t * (b.window - a.window), a.inverse_w + t * (b.inverse_w - a.inverse_w),
            a.colour_over_w + t * (b.colour_over_w - a.colour_over_w)};
}

WindowPoint to_window_point(const glm::vec4& clip, const glm::vec3& colour, int width, int height) {
    const float inverse_w = 1.0f / clip.w;
    return {clip_to_window(clip, width, height), inverse_w, colour * inverse_w};
}

// Liang–Barsky: the parameter range [t0, t1] of p0 + t (p1 - p0) inside the rectangle.
bool clip_to_rect(const glm::vec2& p0, const glm::vec2& p1, float x_min, float y_min, float x_max,
                  float y_max, float& t0, float& t1) {
    const glm::vec2 d = p1 - p0;
    const float p[4] = {-d.x, d.x, -d.y, d.y};
    const float q[4] = {p0.x - x_min, x_max - p0.x, p0.y - y_min, y_max - p0.y};
    t0 = 0.0f;
    t1 = 1.0f;
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0.0f) {
            if (q[i] < 0.0f) return false;  // parallel to and outside this side
            continue;
        }
        const float t = q[i] / p[i];
        if (p[i] < 0.0f) {
            t0 = std::max(t0, t);
        } else {
            t1 = std::min(t1, t);
        }
    }
    return t0 <= t1;
}

struct ClipEnd {
    glm::vec4 position;
    glm::vec3 colour;
};

// Keeps the part of segment a–b where distance(p) >= 0; false if nothing is left. The cut
// is computed from the inside end, whichever end that is.
template <class Distance>
bool clip_segment(ClipEnd& a, ClipEnd& b, Distance distance) {
    const float d_a = distance(a.position), d_b = distance(b.position);
    if (d_a >= 0.0f && d_b >= 0.0f) return true;
    if (!(d_a >= 0.0f) && !(d_b >= 0.0f)) return false;
    ClipEnd& inside = d_a >= 0.0f ? a : b;
    ClipEnd& outside = d_a >= 0.0f ? b : a;
    const float d_in = d_a >= 0.0f ? d_a : d_b, d_out = d_a >= 0.0f ? d_b : d_a;
    const float t = d_in / (d_in - d_out);
    outside.position = inside.position + t * (outside.position - inside.position);
    outside.colour = inside.colour + t * (outside.colour - inside.colour);
    return true;
}

// The DDA over the major axis, of a line already clipped to (a margin around) the framebuffer.
// Every pixel is computed from the start point, not accumulated, so long lines do not drift.
void walk_line(Framebuffer& framebuffer, const PreparedLine& line, const PixelRect& scissor,
               const LineStyle& style) {
    WindowPoint a = line.a, b = line.b;
    const bool blend_colours = line.blend_colours;
    const bool x_major = std::abs(b.window.x - a.window.x) >= std::abs(b.window.y - a.window.y);
    const int major = x_major ? 0 : 1, minor = 1 - major;
    if (a.window[major] > b.window[major]) std::swap(a, b);
    const float start = a.window[major], length = b.window[major] - a.window[major];
    if (!(length > 0.0f)) return;  // zero length (or NaN): covers no pixel centre

    const int major_begin = x_major ? scissor.x_begin : scissor.y_begin;
    const int major_end = x_major ? scissor.x_end : scissor.y_end;
    const int minor_begin = x_major ? scissor.y_begin : scissor.x_begin;
    const int minor_end = x_major ? scissor.y_end : scissor.x_end;
    // Pixel centres c + 0.5 in [start, end): c from ceil(start - 0.5) to ceil(end - 0.5) - 1.
    int first = std::max(major_begin, static_cast<int>(std::ceil(start - 0.5f)));
    int last = std::min(major_end, static_cast<int>(std::ceil(b.window[major] - 0.5f)));
    const float minor_start = a.window[minor], minor_delta = b.window[minor] - a.window[minor];
    // Only the stretch whose minor coordinate can fall inside the scissor is walked: a frame
    // drawn in thin bands would otherwise walk every line's whole length in every band. The
    // stretch is estimated in double with two pixels to spare on either side; which pixels
    // are drawn is still decided pixel by pixel below, exactly as without it.
    if (minor_delta != 0.0f) {
        const double slope = static_cast<double>(length) / static_cast<double>(minor_delta);
        const double at_begin =
            start - 0.5 + (static_cast<double>(minor_begin) - minor_start) * slope;
        const double at_end = start - 0.5 + (static_cast<double>(minor_end) - minor_start) * slope;
        const double low = std::min(at_begin, at_end) - 2.0,
                     high = std::max(at_begin, at_end) + 2.0;
        if (low > static_cast<double>(first)) first = static_cast<int>(std::min(low, 1e9));
        if (high < static_cast<double>(last)) last = static_cast<int>(std::max(high, -1e9));
    }

    const std::size_t width = static_cast<std::size_t>(framebuffer.width());
    Rgba8* const colours = framebuffer.colours().data();
    const DepthRows depths = framebuffer.depth_rows();
    const bool depth_test = style.depth_test, depth_write = style.depth_write;
    const float inverse_length = 1.0f / length;
    const float depth_start = a.window.z, depth_delta = b.window.z - a.window.z;
    const Rgba8 flat_colour = to_rgba8(a.colour_over_w / a.inverse_w);
    for (int c = first; c < last; ++c) {
        const float t = (static_cast<float>(c) + 0.5f - start) * inverse_length;
        const int m = static_cast<int>(std::floor(minor_start + t * minor_delta));
        if (m < minor_begin || m >= minor_end) continue;
        const int x = x_major ? c : m, y = x_major ? m : c;
        const std::size_t index = static_cast<std::size_t>(y) * width + static_cast<std::size_t>(x);
        const float depth = depth_start + t * depth_delta;
        float surface_depth = depths[index];
        if (style.on_surface) {
            // The surface under the line's exact point lies between this pixel's centre and
            // the next one's toward the point: the farther of the two bounds it.
            const float exact = minor_start + t * minor_delta;
            const int next = exact < static_cast<float>(m) + 0.5f ? m - 1 : m + 1;
            if (next >= minor_begin && next < minor_end) {
                const std::size_t next_index =
                    x_major ? static_cast<std::size_t>(next) * width + static_cast<std::size_t>(x)
                            : static_cast<std::size_t>(y) * width + static_cast<std::size_t>(next);
                surface_depth = std::max(surface_depth, depths[next_index]);
            }
        }
        if (depth_test && !(depth < surface_depth)) continue;
        if (blend_colours) {
            const WindowPoint p = lerp(a, b, t);
            colours[index] = to_rgba8(p.colour_over_w / p.inverse_w);
        } else {
            colours[index] = flat_colour;
        }
        if (depth_write) depths[index] = depth;
    }
}

// Cull, clip and divide: everything of a line's drawing that does not depend on the scissor;
// nothing when no part of it can be drawn.
std::optional<PreparedLine> prepare_clip_space_line(const Framebuffer& framebuffer,
                                                    const glm::vec4& a, const glm::vec4& b,
                                                    Rgba8 colour_a, Rgba8 colour_b) {
    // Cull: both ends outside the same frustum plane, or not a number.
    const std::uint32_t code_a = clip_outcode(a), code_b = clip_outcode(b);
    if ((code_a & code_b & frustum_planes) != 0 || ((code_a | code_b) & not_finite) != 0)
        return std::nullopt;

    // Clip against the near plane in clip space (from the inside end, as for triangles), so
    // a line passing behind the camera keeps only its visible part instead of wrapping;
    // then against w = min_clip_w, which only non-perspective matrices can violate.
    ClipEnd end_a{a, to_vec3(colour_a)}, end_b{b, to_vec3(colour_b)};
    if (!clip_segment(end_a, end_b, [](const glm::vec4& p) { return p.z + p.w; }) ||
        !clip_segment(end_a, end_b, [](const glm::vec4& p) { return p.w - min_clip_w; })) {
        return std::nullopt;
    }

    // Divide and viewport.
    const int width = framebuffer.width(), height = framebuffer.height();
    const WindowPoint p0 = to_window_point(end_a.position, end_a.colour, width, height);
    const WindowPoint p1 = to_window_point(end_b.position, end_b.colour, width, height);

    // Clip to the framebuffer (plus a pixel of margin) in window space: a line reaching far
    // off screen costs only its visible pixels. Depth, 1/w and colour/w are affine here.
    // Deliberately not to the scissor: the clipped ends must not depend on the tile, or a
    // line drawn tile by tile could round to other pixels at the seams than drawn whole;
    // walk_line restricts the pixels to the scissor instead.
    const float width_f = static_cast<float>(width), height_f = static_cast<float>(height);
    float t0 = 0.0f, t1 = 1.0f;
    if (!clip_to_rect(glm::vec2(p0.window), glm::vec2(p1.window), -1.0f, -1.0f, width_f + 1.0f,
                      height_f + 1.0f, t0, t1)) {
        return std::nullopt;
    }
    return PreparedLine{t0 > 0.0f ? lerp(p0, p1, t0) : p0, t1 < 1.0f ? lerp(p0, p1, t1) : p1,
                        colour_a != colour_b};
}

}  // namespace

void draw_clip_space_line(Framebuffer& framebuffer, const glm::vec4& a, const glm::vec4& b,
                          Rgba8 colour_a, Rgba8 colour_b, const LineStyle& style) {
    const PixelRect scissor = style.scissor.intersect(framebuffer.bounds());
    if (scissor.empty()) return;
    if (const std::optional<PreparedLine> line =
            prepare_clip_space_line(framebuffer, a, b, colour_a, colour_b))
        walk_line(framebuffer, *line, scissor, style);
}

void prepare_lines(const Framebuffer& framebuffer, const Camera& camera,
                   std::span<const LineSegment> segments, float depth_bias,
                   std::vector<PreparedLine>& lines) {
    const BiasedProjection project(camera, framebuffer, depth_bias);
    for (const LineSegment& segment : segments) {
        if (const std::optional<PreparedLine> line =
                prepare_clip_space_line(framebuffer, project(segment.a), project(segment.b),
                                        segment.colour_a, segment.colour_b))
            lines.push_back(*line);
    }
}

void draw_prepared_lines(Framebuffer& framebuffer, std::span<const PreparedLine> lines,
                         const LineStyle& style) {
    const PixelRect scissor = style.scissor.intersect(framebuffer.bounds());
    if (scissor.empty()) return;
    for (const PreparedLine& line : lines) walk_line(framebuffer, line, scissor, style);
}

void draw_lines(Framebuffer& framebuffer, const Camera& camera,
                std::span<const LineSegment> segments, const LineStyle& style) {
    const BiasedProjection project(camera, framebuffer, style.depth_bias);
    for (const LineSegment& segment : segments) {
        draw_clip_space_line(framebuffer, project(segment.a), project(segment.b), segment.colour_a,
                             segment.colour_b, style);
    }
}

namespace {

void draw_indexed_lines_impl(Framebuffer& framebuffer, const Camera& camera,
                             std::span<const glm::vec3> positions,
                             std::span<const LineIndices> lines, const Rgba8* colours,
                             std::size_t colour_stride, const LineStyle& style) {
    const BiasedProjection project(camera, framebuffer, style.depth_bias);
    std::vector<glm::vec4> clip(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) clip[i] = project(positions[i]);
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const LineIndices& line = lines[i];
        if (line[0] >= clip.size() || line[1] >= clip.size()) continue;
        const Rgba8 colour = colours[i * colour_stride];
        draw_clip_space_line(framebuffer, clip[line[0]], clip[line[1]], colour, colour, style);
    }
}

void draw_points_impl(Framebuffer& framebuffer, const Camera& camera,
                      std::span<const glm::vec3> positions, const Rgba8* colours,
                      std::size_t colour_stride, float size_pixels, const LineStyle& style) {
    const PixelRect scissor = style.scissor.intersect(framebuffer.bounds());
    if (scissor.empty() || !(size_pixels > 0.0f)) return;
    const float half = 0.5f * std::min(size_pixels, 1024.0f);
    const BiasedProjection project(camera, framebuffer, style.depth_bias);
    const int width = framebuffer.width(), height = framebuffer.height();
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const glm::vec4 clip = project(positions[i]);
        const std::uint32_t code = clip_outcode(clip);
        if ((code & (outside_near | outside_w_min | outside_far | not_finite)) != 0) continue;
        const glm::vec3 window = clip_to_window(clip, width, height);
        // Pixel centres in [centre - half, centre + half) on both axes, within the scissor.
        auto first_centre = [](float low, int begin, int end) {
            return static_cast<int>(std::clamp(std::ceil(low - 0.5f), static_cast<float>(begin),
                                               static_cast<float>(end)));
        };
        const int x_begin = first_centre(window.x - half, scissor.x_begin, scissor.x_end);
        const int x_end = first_centre(window.x + half, scissor.x_begin, scissor.x_end);
        const int y_begin = first_centre(window.y - half, scissor.y_begin, scissor.y_end);
        const int y_end = first_centre(window.y + half, scissor.y_begin, scissor.y_end);
        const Rgba8 colour = colours[i * colour_stride];
        for (int y = y_begin; y < y_end; ++y) {
            for (int x = x_begin; x < x_end; ++x) {
                float& depth = framebuffer.depth(x, y);
                if (style.depth_test && !(window.z < depth)) continue;
                framebuffer.colour(x, y) = colour;
                if (style.depth_write) depth = window.z;
            }
        }
    }
}

}  // namespace

void draw_indexed_lines(Framebuffer& framebuffer, const Camera& camera,
                        std::span<const glm::vec3> positions, std::span<const LineIndices> lines,
                        std::span<const Rgba8> line_colours, const LineStyle& style) {
    if (line_colours.size() != lines.size() || lines.empty()) return;
    draw_indexed_lines_impl(framebuffer, camera, positions, lines, line_colours.data(), 1, style);
}

void draw_indexed_lines(Framebuffer& framebuffer, const Camera& camera,
                        std::span<const glm::vec3> positions, std::span<const LineIndices> lines,
                        Rgba8 colour, const LineStyle& style) {
    draw_indexed_lines_impl(framebuffer, camera, positions, lines, &colour, 0, style);
}

void draw_points(Framebuffer& framebuffer, const Camera& camera,
                 std::span<const glm::vec3> positions, std::span<const Rgba8> colours,
                 float size_pixels, const LineStyle& style) {
    if (colours.size() != positions.size() || positions.empty()) return;
    draw_points_impl(framebuffer, camera, positions, colours.data(), 1, size_pixels, style);
}

void draw_points(Framebuffer& framebuffer, const Camera& camera,
                 std::span<const glm::vec3> positions, Rgba8 colour, float size_pixels,
                 const LineStyle& style) {
    draw_points_impl(framebuffer, camera, positions, &colour, 0, size_pixels, style);
}

}  // namespace weft::raster
