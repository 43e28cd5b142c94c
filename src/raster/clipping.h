// Clip-space vertices and triangle clipping, the stage between transform and rasterization.
//
// A triangle arrives as three clip-space positions (x, y, z, w) = projection · view · world.
// Before the perspective divide we must
//   - reject it if all three vertices are outside the same frustum plane (it cannot be seen);
//   - clip it against the near plane z = -w. Dividing by w of a vertex behind the camera
//     (w < 0) would mirror it through the eye and draw a triangle "wrapped around" the screen;
//     clipping keeps only the part in front, a triangle or a quad (two triangles).
//   - clip it against a guard band |x|, |y| <= guard_band · w, far outside the screen, so the
//     window coordinates of any vertex fit the rasterizer's 64-bit fixed-point edge functions
//     (a triangle the camera is inside of can otherwise project to billions of pixels).
//     Only triangles crossing that band, i.e. within a few centimetres of the eye, pay for it.
// Sutherland–Hodgman does the clipping: each plane adds at most one vertex to the convex
// polygon, so 6 planes leave at most 9 vertices, drawn as a fan.
//
// An edge shared by two triangles is cut at exactly the same point in both, because the
// intersection is always computed from the edge's inside vertex towards its outside vertex,
// whichever way round the triangle lists it. That keeps clipped meshes crack-free.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

#include <glm/vec4.hpp>

namespace weft::raster {

// Per-vertex attributes the rasterizer interpolates (perspective-correctly) for shading:
// e.g. world position, normal, texture coordinates, colour — whatever the shader reads.
inline constexpr int max_varyings = 12;

struct ClipVertex {
    glm::vec4 position{0.0f, 0.0f, 0.0f, 1.0f};  // clip space
    std::array<float, max_varyings> varyings{};
};

// Guard band half-width in units of w (the visible frustum is 1). At 16384 pixels a side this
// keeps window coordinates within ±2^18 pixels, so with 8 sub-pixel bits the edge functions
// stay below 2^56.
inline constexpr float guard_band = 32.0f;

// Outcode bits: which planes a clip-space point is outside of.
enum ClipPlaneBits : std::uint32_t {
    outside_left = 1u << 0,    // x < -w
    outside_right = 1u << 1,   // x > w
    outside_bottom = 1u << 2,  // y < -w
    outside_top = 1u << 3,     // y > w
    outside_near = 1u << 4,    // z < -w (also every point behind the eye)
    outside_far = 1u << 5,     // z > w
    outside_w_min = 1u << 6,   // w < min_clip_w: only reachable with non-perspective matrices
    beyond_guard_left = 1u << 7,
    beyond_guard_right = 1u << 8,
    beyond_guard_bottom = 1u << 9,
    beyond_guard_top = 1u << 10,
    not_finite = 1u << 11,  // a NaN or infinite coordinate: the triangle is never drawn
};

// Planes that cull a triangle when all three vertices are outside the same one.
inline constexpr std::uint32_t frustum_planes = outside_left | outside_right | outside_bottom |
                                                outside_top | outside_near | outside_far |
                                                outside_w_min;
// Planes the clipper actually cuts along.
inline constexpr std::uint32_t clipping_planes = outside_near | outside_w_min | beyond_guard_left |
                                                 beyond_guard_right | beyond_guard_bottom |
                                                 beyond_guard_top;

inline constexpr float min_clip_w = 1e-6f;

inline std::uint32_t clip_outcode(const glm::vec4& p) {
    const float w = p.w, g = guard_band * p.w;
    std::uint32_t code = 0;
    if (p.x < -w) code |= outside_left;
    if (p.x > w) code |= outside_right;
    if (p.y < -w) code |= outside_bottom;
    if (p.y > w) code |= outside_top;
    if (p.z < -w) code |= outside_near;
    if (p.z > w) code |= outside_far;
    if (w < min_clip_w) code |= outside_w_min;
    if (p.x < -g) code |= beyond_guard_left;
    if (p.x > g) code |= beyond_guard_right;
    if (p.y < -g) code |= beyond_guard_bottom;
    if (p.y > g) code |= beyond_guard_top;
    // NaN compares false everywhere above, and infinities would turn into NaN when clipped.
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) || !std::isfinite(w)) {
        code |= not_finite;
    }
    return code;
}

// The outcodes of a triangle's three vertices, computed once per vertex by mesh drawing.
struct TriangleOutcodes {
    std::uint32_t a, b, c;

    bool culled() const {
        return (a & b & c & frustum_planes) != 0 || ((a | b | c) & not_finite) != 0;
    }
    bool needs_clipping() const { return ((a | b | c) & clipping_planes) != 0; }
};

struct ClippedPolygon {
    static constexpr int max_vertices = 9;  // 3 + one per clipping plane
    std::array<ClipVertex, max_vertices> vertices;
    int count = 0;  // 0: nothing left; otherwise >= 3, a convex polygon in the input's winding
};

// Clips triangle (a, b, c) against the planes in `planes` (a subset of clipping_planes,
// normally the union of the vertices' outcodes). Only the first `varying_count` varyings are
// interpolated; the rest of each output vertex's varyings are left unspecified.
void clip_triangle(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c,
                   std::uint32_t planes, int varying_count, ClippedPolygon& out);

}  // namespace weft::raster
