// The vertex transform's positions, eight vertices at a time with AVX2
// (vertex_transform_avx2.cpp; only that file gets the instruction set, and it runs only where
// the CPU has it).
//
// For each vertex: its clip position (glm's mat4 × vec4, in glm's order of sums), its outcode
// (clip_outcode) and, where no clipping plane cuts it, its window vertex (window_vertex:
// the divide by w, the viewport, the snap to 1/256 pixel rounded to nearest). The same
// operations in the same order as the scalar functions and no fused multiply-add, so the
// same bits. Inside the guard band a snapped coordinate of a viewport up to 65535 pixels a
// side fits in 32 bits, which is what lets the lanes round it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "raster/triangle_setup.h"

namespace weft::raster {

inline constexpr int transform_group_size = 8;
inline constexpr int largest_avx2_viewport_side = 65535;

// Vertices [begin, begin + 8 · groups) of `positions`, through `clip_from_model`, into
// clip[i], outcodes[i] and (only where outcodes[i] has no clipping plane) window[i], for a
// viewport width × height of at most largest_avx2_viewport_side a side. Only where
// avx2_supported() (vector_isa.h).
void transform_positions_avx2(const glm::mat4& clip_from_model, const glm::vec3* positions,
                              std::size_t begin, std::size_t groups, int width, int height,
                              glm::vec4* clip, std::uint32_t* outcodes, WindowVertex* window);

// The varyings of vertices [begin, end) of a surface given in world space with position,
// normal and uv (SurfaceShader<true, false>'s eight: x y z, normal x y z, u v), each times
// its window vertex's inverse_w, into varyings_over_w[8 i ...], where outcodes[i] has no
// clipping plane: one vector a vertex, the scalar products' bits. Only where
// avx2_supported().
void divide_surface_varyings_avx2(const glm::vec3* positions, const glm::vec3* normals,
                                  const glm::vec2* uvs, const std::uint32_t* outcodes,
                                  const WindowVertex* window, std::size_t begin, std::size_t end,
                                  float* varyings_over_w);

}  // namespace weft::raster
