// Planar shadows: a mesh flattened onto the horizontal plane of the floor along the key
// light's direction, then drawn in one colour before everything that stands on the floor.
//
// The projection is affine for a directional light, so it is a model matrix: the mesh's
// own positions go through it and the camera in one transform, with nothing copied. Where
// layers of a folded cloth land on the same spot, each pixel is written with the same colour
// however many cover it, so the shadow never darkens twice.
#pragma once

#include <cstdint>
#include <optional>
#include <span>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "parallel/worker_pool.h"
#include "raster/camera.h"
#include "raster/colour.h"
#include "raster/framebuffer.h"
#include "raster/mesh.h"
#include "raster/mesh_renderer.h"
#include "raster/pixel_rect.h"

namespace weft::raster {

// Moves every point along the light's direction onto the plane y = height:
//     p' = p - L (p.y - height) / L.y
// with L = direction_to_light (any length). Nothing when the light is lower than about
// 8.6° above the horizon (L.y < 0.15 |L|, or L not finite): its shadows would stretch
// towards the horizon, far from what casts them.
std::optional<glm::mat4> shadow_projection(const glm::vec3& direction_to_light, float height);

// Transforms a mesh's positions (through mesh.model, which for a shadow includes the
// projection) for flat drawing: clip positions, outcodes and window vertices, no varyings.
// Normals, uvs and colours are not read. `used`, when not empty, lists every vertex the
// triangles name, and only those are transformed (a coarse shadow names few of a cloth's).
// Splits the vertices between the pool's threads when there is one; the same values for any
// split.
void prepare_flat_mesh(const Camera& camera, int width, int height, const MeshView& mesh,
                       PreparedMesh& prepared, WorkerPool* pool = nullptr,
                       std::span<const std::uint32_t> used = {});

// Draws a flat-prepared mesh inside `scissor` in one colour, depth-tested and depth-written.
void draw_flat_mesh(Framebuffer& framebuffer, const PreparedMesh& prepared, Rgba8 colour,
                    const PixelRect& scissor = PixelRect::unbounded());

// Band `band` of a flat-prepared mesh whose triangles were binned (bin_triangles): exactly the
// pixels draw_flat_mesh draws with the band's rows as scissor.
void draw_flat_band(Framebuffer& framebuffer, const PreparedMesh& prepared,
                    const TriangleBands& bands, int band, Rgba8 colour);

}  // namespace weft::raster
