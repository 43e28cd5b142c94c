// Triangle rasterization: draws one clip-space triangle into a framebuffer, calling a shader
// for every pixel it covers that passes the depth test.
//
// The pipeline, one stage per step (transform happens before, in the caller):
//   1. cull     — all vertices outside one frustum plane: nothing to draw.
//   2. clip     — near plane (and guard band) in clip space: clipping.h.
//   3. setup    — divide, viewport, fixed point, facing, edge functions, clamped bounding box:
//                 triangle_setup.h.
//   4. traverse — walk the box row by row, edge functions stepped incrementally.
//   5. depth    — interpolate window depth (affine in screen space), test against the buffer.
//   6. shade    — interpolate varyings perspective-correctly, call the shader, write.
//
// The shader is a template parameter so it inlines into the pixel loop: anything callable as
//     Rgba8 shader(const Fragment& fragment)
// A shader type may also declare `static constexpr int varying_count = N;`: then N replaces
// RasterState::varying_count and the interpolation loop is unrolled at compile time.
// A shader that declares `static constexpr bool deferred = true;` is instead called as
//     shader.defer(std::size_t pixel_index, const Fragment& fragment)
// for every fragment that passes the depth test (whose depth is already written), and
// writes the colour itself later — in batches, in the order it was given the fragments.
// A deferred shader that also declares `static constexpr bool takes_fragment_blocks = true;`
// takes the fragments of small triangles sixteen at a time (fragment_block.h) through
//     const FragmentSink& sink()                 its queue's arrays
//     int reserve()                              the offset of room for fragment_block_size
//     void commit(int count, bool front_facing)  the first `count` there are filled in
// and gets exactly the fragments, in exactly the order, that defer() would have been given.
// Nothing here allocates; the framebuffer, scissor and state are passed in, never global.
// Both windings are drawn (there is no back-face culling); Fragment::front_facing tells the
// shader which side it sees.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>

#include "raster/clipping.h"
#include "raster/colour.h"
#include "raster/fragment_block.h"
#include "raster/framebuffer.h"
#include "raster/pixel_rect.h"
#include "raster/triangle_setup.h"
#include "raster/vector_isa.h"

namespace weft::raster {

struct RasterState {
    PixelRect scissor = PixelRect::unbounded();  // intersected with the framebuffer per draw
    bool depth_test = true;                      // keep a fragment only if nearer (<) than stored
    bool depth_write = true;
    int varying_count = 0;  // how many ClipVertex::varyings to interpolate (0..max_varyings)
};

struct Fragment {
    int x = 0, y = 0;                 // pixel
    float depth = 0.0f;               // window depth [0, 1] at the pixel centre
    bool front_facing = true;         // counter-clockwise on screen (see triangle_setup.h)
    const float* varyings = nullptr;  // RasterState::varying_count values, perspective-correct
};

namespace detail {

// The shader's compile-time varying count, or -1 if it does not declare one.
template <class Shader>
constexpr int static_varying_count() {
    using Type = std::remove_cvref_t<Shader>;
    if constexpr (requires { Type::varying_count; }) {
        static_assert(Type::varying_count >= 0 && Type::varying_count <= max_varyings);
        return Type::varying_count;
    } else {
        return -1;
    }
}

// How many varyings a draw with this shader interpolates: the shader's own count if it
// declares one (a constant, so loops over them unroll), else the state's.
template <class Shader>
constexpr int varying_count_of(const RasterState& state) {
    constexpr int fixed_varying_count = static_varying_count<Shader>();
    return fixed_varying_count >= 0 ? fixed_varying_count : state.varying_count;
}

// Whether the shader colours its pixels later, in batches (see above).
template <class Shader>
constexpr bool is_deferred() {
    using Type = std::remove_cvref_t<Shader>;
    if constexpr (requires { Type::deferred; })
        return Type::deferred;
    else
        return false;
}

// Whether the shader takes small triangles' fragments in blocks (see above).
template <class Shader>
constexpr bool takes_fragment_blocks() {
    using Type = std::remove_cvref_t<Shader>;
    if constexpr (requires { Type::takes_fragment_blocks; })
        return Type::takes_fragment_blocks;
    else
        return false;
}

// Stages 4–6 for a set-up triangle that fits_fragment_block(), four rows at a time, given
// each setup vertex's varyings divided by its w.
template <class Shader>
void traverse_blocks(Framebuffer& framebuffer, const RasterState& state, const TriangleSetup& setup,
                     const float* const (&varying_over_w)[3], int varying_count, Shader& shader) {
    const BlockTriangle triangle{&setup,
                                 {varying_over_w[0], varying_over_w[1], varying_over_w[2]},
                                 varying_count,
                                 framebuffer.depth_rows(),
                                 static_cast<std::uint32_t>(framebuffer.width()),
                                 state.depth_test,
                                 state.depth_write};
    const FragmentSink& sink = shader.sink();
    if (setup.y_end - setup.y_begin <= half_block_rows) {
        const int offset = shader.reserve();
        shader.commit(traverse_fragment_half_block(triangle, setup.y_begin, sink, offset),
                      setup.front_facing);
        return;
    }
    for (int y = setup.y_begin; y < setup.y_end; y += fragment_block_rows) {
        const int offset = shader.reserve();
        shader.commit(traverse_fragment_block(triangle, y, sink, offset), setup.front_facing);
    }
}

// Stages 5–6 for the covered pixel centres of one set-up triangle: depth test, the
// perspective-correct varyings, the shader. Both pixel loops below shade through it, so
// whichever of them takes a triangle, its fragments are the same to the bit. Everything it
// reads is copied in once per triangle: colour stores go through unsigned char, which may
// alias anything, so values read through a reference would be reloaded after every pixel
// written. The varyings too, with CopyVaryings, for the row walk; a tiny triangle shades a
// pixel or two, fewer reads than the copy, and reads them where they are.
//
// The varyings come as each setup vertex's varyings divided by its w: a/w and 1/w are affine
// in screen space, so their barycentric blend divided by the blended 1/w is the
// perspective-correct value (the same trick GPUs use).
template <class Shader, bool CopyVaryings = true>
struct PixelShading {
    Rgba8* colours;
    DepthRows depths;
    std::size_t width;
    int varying_count;
    bool depth_test, depth_write;
    std::int64_t bias0, bias1, bias2;
    float inverse_area;
    float depth0, depth1, depth2;
    float inverse_w0, inverse_w1, inverse_w2;
    std::array<std::array<float, max_varyings>, 3> varying_over_w;  // with CopyVaryings
    const float* given[3];                                          // without
    std::array<float, max_varyings> varyings;  // the first varying_count are set per pixel
    Fragment fragment;

    PixelShading(Framebuffer& framebuffer, const RasterState& state, const TriangleSetup& setup,
                 const float* const (&given_over_w)[3])
        : colours(framebuffer.colours().data()),
          depths(framebuffer.depth_rows()),
          width(static_cast<std::size_t>(framebuffer.width())),
          varying_count(varying_count_of<Shader>(state)),
          depth_test(state.depth_test),
          depth_write(state.depth_write),
          bias0(setup.bias[0]),
          bias1(setup.bias[1]),
          bias2(setup.bias[2]),
          inverse_area(setup.inverse_doubled_area),
          depth0(setup.depth[0]),
          depth1(setup.depth[1]),
          depth2(setup.depth[2]),
          inverse_w0(setup.inverse_w[0]),
          inverse_w1(setup.inverse_w[1]),
          inverse_w2(setup.inverse_w[2]),
          given{given_over_w[0], given_over_w[1], given_over_w[2]} {
        if constexpr (CopyVaryings) {
            for (int i = 0; i < 3; ++i)
                for (int k = 0; k < varying_count; ++k) varying_over_w[i][k] = given_over_w[i][k];
        }
        fragment.front_facing = setup.front_facing;
        fragment.varyings = varyings.data();
    }
    PixelShading(const PixelShading&) = delete;
    PixelShading& operator=(const PixelShading&) = delete;

    // Pixel (x, y), whose centre is covered, with biased edge values e0, e1, e2.
    void shade(int x, int y, std::int64_t e0, std::int64_t e1, std::int64_t e2, Shader& shader) {
        // Depth: window depth is affine in screen space, so plain barycentrics suffice.
        const float b0 = static_cast<float>(e0 - bias0) * inverse_area;
        const float b1 = static_cast<float>(e1 - bias1) * inverse_area;
        const float b2 = static_cast<float>(e2 - bias2) * inverse_area;
        const float depth = b0 * depth0 + b1 * depth1 + b2 * depth2;
        const std::size_t index = static_cast<std::size_t>(y) * width + static_cast<std::size_t>(x);
        if (depth_test && !(depth < depths[index])) return;

        // Shade: perspective-correct varyings, then the shader decides the colour.
        if (varying_count > 0) {
            const float w = 1.0f / (b0 * inverse_w0 + b1 * inverse_w1 + b2 * inverse_w2);
            for (int k = 0; k < varying_count; ++k) {
                if constexpr (CopyVaryings) {
                    varyings[k] = (b0 * varying_over_w[0][k] + b1 * varying_over_w[1][k] +
                                   b2 * varying_over_w[2][k]) *
                                  w;
                } else {
                    varyings[k] = (b0 * given[0][k] + b1 * given[1][k] + b2 * given[2][k]) * w;
                }
            }
        }
        fragment.x = x;
        fragment.y = y;
        fragment.depth = depth;
        if constexpr (is_deferred<Shader>()) {
            if (depth_write) depths[index] = depth;
            shader.defer(index, static_cast<const Fragment&>(fragment));
        } else {
            colours[index] = shader(static_cast<const Fragment&>(fragment));
            if (depth_write) depths[index] = depth;
        }
    }
};

// Stages 4–6 for one set-up triangle, pixel by pixel, given each setup vertex's varyings
// divided by its w.
template <class Shader>
void traverse_pixels(Framebuffer& framebuffer, const RasterState& state, const TriangleSetup& setup,
                     const float* const (&given_over_w)[3], Shader& shader) {
    const int x_begin = setup.x_begin, x_end = setup.x_end;
    const std::int64_t step_x0 = setup.step_x[0], step_x1 = setup.step_x[1],
                       step_x2 = setup.step_x[2];
    const double inverse_step_x0 = setup.inverse_step_x[0],
                 inverse_step_x1 = setup.inverse_step_x[1],
                 inverse_step_x2 = setup.inverse_step_x[2];
    const bool may_skip = inverse_step_x0 + inverse_step_x1 + inverse_step_x2 > 0.0;
    PixelShading<Shader> pixels(framebuffer, state, setup, given_over_w);

    std::int64_t row0 = setup.edge_origin[0], row1 = setup.edge_origin[1],
                 row2 = setup.edge_origin[2];
    for (int y = setup.y_begin; y < setup.y_end;
         ++y, row0 += setup.step_y[0], row1 += setup.step_y[1], row2 += setup.step_y[2]) {
        std::int64_t e0 = row0, e1 = row1, e2 = row2;
        // A row outside an edge that does not grow to the right stays outside.
        if ((e0 < 0 && step_x0 <= 0) || (e1 < 0 && step_x1 <= 0) || (e2 < 0 && step_x2 <= 0)) {
            continue;
        }

        // Traverse: left-bounding edges (step_x > 0) say how many pixels of this row are
        // certainly outside. The floating-point estimate is backed off by one pixel so it
        // never skips a covered pixel; coverage itself is decided exactly below.
        int x = x_begin;
        if (may_skip) {
            double skip = 0.0;
            if (e0 < 0) skip = std::max(skip, static_cast<double>(-e0) * inverse_step_x0);
            if (e1 < 0) skip = std::max(skip, static_cast<double>(-e1) * inverse_step_x1);
            if (e2 < 0) skip = std::max(skip, static_cast<double>(-e2) * inverse_step_x2);
            const double available = static_cast<double>(x_end - x_begin);
            const int jump = static_cast<int>(std::min(std::floor(skip) - 1.0, available));
            if (jump > 0) {
                x += jump;
                e0 += step_x0 * jump;
                e1 += step_x1 * jump;
                e2 += step_x2 * jump;
            }
        }

        bool entered = false;
        for (; x < x_end; ++x, e0 += step_x0, e1 += step_x1, e2 += step_x2) {
            if ((e0 | e1 | e2) < 0) {
                if (entered) break;  // convex: once out again, the rest of the row is out
                continue;
            }
            entered = true;
            pixels.shade(x, y, e0, e1, e2, shader);
        }
    }
}

// Stages 4–6 for a set-up triangle whose box holds at most 2×2 pixel centres: a cloth seen
// whole can have about as many triangles as pixels, and nearly all of them are this small.
// Coverage of the (up to) four centres is decided first, without a branch per centre, from
// the same integer edge values the pixel loop steps to, and only the covered centres are
// shaded, in the pixel loop's order and through the same PixelShading.
template <class Shader>
void traverse_tiny(Framebuffer& framebuffer, const RasterState& state, const TriangleSetup& setup,
                   const float* const (&varying_over_w)[3], Shader& shader) {
    const detail::TinyCoverage coverage =
        detail::tiny_coverage(setup.edge_origin, setup.step_x, setup.step_y,
                              setup.x_end - setup.x_begin, setup.y_end - setup.y_begin);
    unsigned covered = coverage.covered;
    if (covered == 0) return;
    PixelShading<Shader, false> pixels(framebuffer, state, setup, varying_over_w);
    for (; covered != 0; covered &= covered - 1) {
        const int k = std::countr_zero(covered);
        pixels.shade(setup.x_begin + k % tiny_box_side, setup.y_begin + k / tiny_box_side,
                     coverage.edges[k][0], coverage.edges[k][1], coverage.edges[k][2], shader);
    }
}

// Stages 4–6 for one set-up triangle: in blocks if it is small and the shader takes them,
// else pixel by pixel. The choice comes first, before the pixel loop copies what it reads:
// most of a cloth's triangles are small, and skipping that copy for them took drawing the
// demo's view on one thread from 2.12 to 2.09 ms.
template <class Shader>
void traverse_and_shade(Framebuffer& framebuffer, const RasterState& state,
                        const TriangleSetup& setup, const float* const (&given_over_w)[3],
                        Shader& shader) {
    if constexpr (takes_fragment_blocks<Shader>()) {
        if (framebuffer.avx512_in_use() && fits_fragment_block(setup)) {
            traverse_blocks(framebuffer, state, setup, given_over_w,
                            varying_count_of<Shader>(state), shader);
            return;
        }
    }
    if (setup.x_end - setup.x_begin <= tiny_box_side &&
        setup.y_end - setup.y_begin <= tiny_box_side) {
        traverse_tiny(framebuffer, state, setup, given_over_w, shader);
        return;
    }
    traverse_pixels(framebuffer, state, setup, given_over_w, shader);
}

// Stages 4–6 for a set-up triangle whose vertices were given as (a, b, c).
template <class Shader>
void traverse_set_up(Framebuffer& framebuffer, const RasterState& state, const TriangleSetup& setup,
                     const ClipVertex& a, const ClipVertex& b, const ClipVertex& c,
                     Shader& shader) {
    const ClipVertex* const input[3] = {&a, &b, &c};
    const int varying_count = varying_count_of<Shader>(state);
    std::array<std::array<float, max_varyings>, 3> over_w;
    for (int i = 0; i < 3; ++i) {
        const ClipVertex& vertex = *input[setup.vertex_order[i]];
        for (int k = 0; k < varying_count; ++k)
            over_w[i][k] = vertex.varyings[k] * setup.inverse_w[i];
    }
    const float* const ordered[3] = {over_w[0].data(), over_w[1].data(), over_w[2].data()};
    traverse_and_shade(framebuffer, state, setup, ordered, shader);
}

template <class Shader>
void rasterize_clipped(Framebuffer& framebuffer, const RasterState& state, const PixelRect& scissor,
                       const ClipVertex& a, const ClipVertex& b, const ClipVertex& c,
                       Shader& shader) {
    TriangleSetup setup;
    if (!setup_triangle(a.position, b.position, c.position, framebuffer.width(),
                        framebuffer.height(), scissor, setup)) {
        return;
    }
    traverse_set_up(framebuffer, state, setup, a, b, c, shader);
}

}  // namespace detail

// Draws triangle (a, b, c) whose vertex outcodes (clip_outcode) the caller already has —
// mesh drawing computes them once per vertex rather than once per triangle corner.
template <class Shader>
void draw_triangle(Framebuffer& framebuffer, const RasterState& state, const ClipVertex& a,
                   const ClipVertex& b, const ClipVertex& c, const TriangleOutcodes& outcodes,
                   Shader&& shader) {
    // 1. Cull: entirely outside one plane of the view frustum.
    if (outcodes.culled()) return;
    const PixelRect scissor = state.scissor.intersect(framebuffer.bounds());
    if (scissor.empty()) return;
    RasterState clamped = state;
    constexpr int fixed_varying_count = detail::static_varying_count<Shader>();
    clamped.varying_count = fixed_varying_count >= 0
                                ? fixed_varying_count
                                : std::clamp(state.varying_count, 0, max_varyings);

    if (!outcodes.needs_clipping()) {
        detail::rasterize_clipped(framebuffer, clamped, scissor, a, b, c, shader);
        return;
    }
    // 2. Clip against the near plane (and the guard band); draw what is left as a fan.
    ClippedPolygon polygon;
    clip_triangle(a, b, c, (outcodes.a | outcodes.b | outcodes.c) & clipping_planes,
                  clamped.varying_count, polygon);
    for (int i = 1; i + 1 < polygon.count; ++i) {
        detail::rasterize_clipped(framebuffer, clamped, scissor, polygon.vertices[0],
                                  polygon.vertices[i], polygon.vertices[i + 1], shader);
    }
}

// Stage 5 for a pixel centre that binning found a tiny triangle to cover (BinnedFragment),
// given the triangle's vertices in setup order: its pixel, its depth, whether it passes the
// state's depth test there, and then the depth written where the state writes depth.
struct BinnedFragmentDepth {
    std::size_t index = 0;  // the pixel's, in the framebuffer
    float depth = 0.0f;
    bool passed = false;
};

// The same, given the framebuffer's depths (Framebuffer::depth_rows) and width, for a
// caller that tests many fragments of one framebuffer.
inline BinnedFragmentDepth test_binned_fragment_depth(const DepthRows& depths, std::size_t width,
                                                      const RasterState& state,
                                                      const BinnedFragment& binned,
                                                      const WindowVertex* const (&vertex)[3]) {
    const float b0 = binned.weight[0], b1 = binned.weight[1], b2 = binned.weight[2];
    BinnedFragmentDepth result;
    result.depth = b0 * vertex[0]->depth + b1 * vertex[1]->depth + b2 * vertex[2]->depth;
    result.index = std::size_t{binned.y} * width + binned.x;
    result.passed = !state.depth_test || result.depth < depths[result.index];
    if (result.passed && state.depth_write) depths[result.index] = result.depth;
    return result;
}

inline BinnedFragmentDepth test_binned_fragment_depth(Framebuffer& framebuffer,
                                                      const RasterState& state,
                                                      const BinnedFragment& binned,
                                                      const WindowVertex* const (&vertex)[3]) {
    return test_binned_fragment_depth(framebuffer.depth_rows(),
                                      static_cast<std::size_t>(framebuffer.width()), state, binned,
                                      vertex);
}

// The clip w at a binned fragment's pixel centre, from its vertices' 1/w.
inline float binned_fragment_w(const BinnedFragment& binned,
                               const WindowVertex* const (&vertex)[3]) {
    return 1.0f /
           (binned.weight[0] * vertex[0]->inverse_w + binned.weight[1] * vertex[1]->inverse_w +
            binned.weight[2] * vertex[2]->inverse_w);
}

// Stages 5–6 for such a pixel centre, given also the vertices' varyings divided by w in setup
// order: the same depth test, the same perspective-correct varyings and the same call of the
// shader, to the bit, as PixelShading gives that centre when the pixel loops find it.
template <class Shader>
void shade_binned_fragment(Framebuffer& framebuffer, const RasterState& state,
                           const BinnedFragment& binned, const WindowVertex* const (&vertex)[3],
                           const float* const (&varying_over_w)[3], Shader& shader) {
    const BinnedFragmentDepth tested =
        test_binned_fragment_depth(framebuffer, state, binned, vertex);
    if (!tested.passed) return;
    std::array<float, max_varyings> varyings;
    const int varying_count = detail::varying_count_of<Shader>(state);
    if (varying_count > 0) {
        const float b0 = binned.weight[0], b1 = binned.weight[1], b2 = binned.weight[2];
        const float w = binned_fragment_w(binned, vertex);
        for (int k = 0; k < varying_count; ++k) {
            varyings[k] = (b0 * varying_over_w[0][k] + b1 * varying_over_w[1][k] +
                           b2 * varying_over_w[2][k]) *
                          w;
        }
    }
    Fragment fragment;
    fragment.x = binned.x;
    fragment.y = binned.y;
    fragment.depth = tested.depth;
    fragment.front_facing = binned.front_facing();
    fragment.varyings = varyings.data();
    if constexpr (detail::is_deferred<Shader>())
        shader.defer(tested.index, static_cast<const Fragment&>(fragment));
    else
        framebuffer.colours()[tested.index] = shader(static_cast<const Fragment&>(fragment));
}

// A triangle of a prepared mesh that needs no clipping: its vertices the caller has taken
// through the divide, viewport and snap (window_vertex), and their varyings divided by w
// (varying_over_w[i] for vertex i: the state's varying count of them, each the vertex's
// varying times its window inverse_w). The state has its scissor already inside the
// framebuffer and its varying count in range.
template <class Shader>
void draw_prepared_triangle(Framebuffer& framebuffer, const RasterState& state,
                            const WindowVertex& window_a, const WindowVertex& window_b,
                            const WindowVertex& window_c, const float* const (&varying_over_w)[3],
                            Shader&& shader) {
    TriangleSetup setup;
    if (!setup_triangle(window_a, window_b, window_c, state.scissor, setup)) return;
    const float* const ordered[3] = {varying_over_w[setup.vertex_order[0]],
                                     varying_over_w[setup.vertex_order[1]],
                                     varying_over_w[setup.vertex_order[2]]};
    detail::traverse_and_shade(framebuffer, state, setup, ordered, shader);
}

template <class Shader>
void draw_triangle(Framebuffer& framebuffer, const RasterState& state, const ClipVertex& a,
                   const ClipVertex& b, const ClipVertex& c, Shader&& shader) {
    const TriangleOutcodes outcodes{clip_outcode(a.position), clip_outcode(b.position),
                                    clip_outcode(c.position)};
    draw_triangle(framebuffer, state, a, b, c, outcodes, std::forward<Shader>(shader));
}

}  // namespace weft::raster
