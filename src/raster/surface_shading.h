// The surface lighting of mesh_renderer.h, computed for many pixels at a time.
//
// Shading a pixel of a 128² cloth took about two thirds of its frame when it was done pixel
// by pixel: three square roots and four divisions in a chain, one pixel after another. The
// rasterizer now hands covered pixels over in batches (triangle_rasterizer.h, deferred
// shaders), and the lighting runs over a batch as plain loops of branch-free arithmetic
// over arrays, which the compiler vectorises. Every lane computes exactly what the one-pixel
// formula computes — the same operations in the same order, choices made by selecting
// between values computed either way — so a pixel's colour does not depend on which batch
// it was shaded in, nor on the thread that drew it. The loops (surface_batch.inl) are also
// built with AVX-512, used where the CPU has it (vector_isa.h), with the same results.
#pragma once

#include <cstdint>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "raster/colour.h"
#include "raster/mesh_renderer.h"

namespace weft::raster {

// The lighting model with everything that is constant over a draw worked out once.
struct PreparedLighting {
    glm::vec3 to_light{0.0f};  // unit length, or zero
    glm::vec3 ambient{0.0f};
    glm::vec3 light{0.0f};
    glm::vec3 eye_fill{0.0f};
    float specular_strength = 0.0f;  // 0 when the light or the style has no highlight
    float shininess = 0.0f;
    int integer_shininess = -1;  // >= 0 when shininess is a whole number: power by squaring
    // n·h at or below which the highlight stays under half an 8-bit step: it counts as 0.
    float specular_cutoff = 0.0f;
};

PreparedLighting prepare_lighting(const SurfaceStyle& style, const Lighting& lighting);

// Up to `capacity` pixels to light: inputs, scratch and the lit colour, one array per value.
struct ShadingLanes {
    static constexpr int capacity = 128;
    // In: the base colour (pattern applied), the interpolated normal (pointing out of the
    // front, any length), the unit vector to the eye, and 1 for the front face or 0.
    float base_r[capacity], base_g[capacity], base_b[capacity];
    float normal_x[capacity], normal_y[capacity], normal_z[capacity];
    float eye_x[capacity], eye_y[capacity], eye_z[capacity];
    float front[capacity];
    // Scratch.
    float lambert[capacity], fill[capacity], n_dot_h[capacity], halfway_squared[capacity];
    float highlight[capacity];
    // Out: the lit colour, unclamped RGB.
    float lit_r[capacity], lit_g[capacity], lit_b[capacity];
};

// Lights lanes [0, count) (count <= capacity).
void shade_lanes(const PreparedLighting& lighting, ShadingLanes& lanes, int count);

// Everything about a surface's shading that is constant over a draw.
struct PreparedSurface {
    PreparedLighting lighting;
    glm::vec3 eye{0.0f};  // world space, m
    glm::vec3 front_colour{0.0f}, back_colour{0.0f};
    SurfacePattern pattern = SurfacePattern::none;
    float pattern_frequency = 0.0f, pattern_contrast = 0.0f;
    bool avx512 = false;  // shade_batch lights with the AVX-512 build (vector_isa.h)
    bool avx2 = false;    // or else with the AVX2 build
};

PreparedSurface prepare_surface(const SurfaceStyle& style, const Lighting& lighting,
                                const glm::vec3& eye);

// Covered pixels waiting for their colour (the mesh shader's queue): one array per value,
// `count` (<= ShadingLanes::capacity) of each.
struct SurfaceBatch {
    int count = 0;
    const std::uint32_t* pixels = nullptr;  // framebuffer index of each
    const float* position[3] = {};          // world position, m
    const float* normal[3] = {};            // interpolated normal, any length
    const float* uv[2] = {};                // pattern coordinates; null: no pattern
    const float* colour[3] = {};            // vertex colours; null: the style's two colours
    const float* front = nullptr;           // 1 where the front face is seen, else 0
};

// Lights the batch and writes each pixel's colour, in the batch's order: a pixel queued
// twice ends with its later colour. `lanes` is scratch.
void shade_batch(const PreparedSurface& surface, const SurfaceBatch& batch, ShadingLanes& lanes,
                 Rgba8* colours);

// pattern_factor (mesh_renderer.h) in a form that vectorises: the cell index as a 32-bit
// integer, which is exact wherever |u| and |v| times the frequency stay below 2^30; beyond
// that (or NaN) any cell will do.
inline float pattern_lane(SurfacePattern pattern, float frequency, float contrast, float u,
                          float v) {
    auto cell = [](float coordinate) -> std::int32_t {
        const float safe = std::abs(coordinate) < 1073741824.0f ? coordinate : 0.0f;
        const auto truncated = static_cast<std::int32_t>(safe);
        return truncated - (static_cast<float>(truncated) > safe ? 1 : 0);
    };
    const std::int32_t cell_u = cell(u * frequency);
    const std::int32_t cell_v = cell(v * frequency);
    const std::int32_t cells = pattern == SurfacePattern::checker ? cell_u + cell_v : cell_u;
    return (cells & 1) != 0 ? 1.0f - contrast : 1.0f;
}

}  // namespace weft::raster
