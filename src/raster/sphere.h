// Spheres for colliders: a UV-sphere tessellation, drawn as a shaded mesh.
#pragma once

#include <glm/vec3.hpp>

#include "raster/camera.h"
#include "raster/framebuffer.h"
#include "raster/mesh.h"
#include "raster/mesh_renderer.h"
#include "raster/pixel_rect.h"

namespace weft::raster {

// The unit sphere at the origin: `slices` around the y axis (>= 3), `stacks` from pole to
// pole (>= 2); both are clamped to [min, 1024]. Triangles are counter-clockwise seen from
// outside; normals point outwards; u runs around, v from the north pole (0) to the south (1).
// The seam and pole vertices are duplicated so u and v stay continuous per triangle.
TriangleMesh make_uv_sphere(int slices = 32, int stacks = 16);

// `unit_sphere` (from make_uv_sphere) scaled to `radius` and moved to `centre`, as a mesh to
// draw or prepare (mesh_renderer.h); it refers to `unit_sphere`'s arrays.
MeshView sphere_view(const TriangleMesh& unit_sphere, const glm::vec3& centre, float radius);

// Draws `unit_sphere` (from make_uv_sphere) scaled to `radius` and moved to `centre`.
bool draw_sphere(Framebuffer& framebuffer, const Camera& camera, const TriangleMesh& unit_sphere,
                 const glm::vec3& centre, float radius, const SurfaceStyle& style,
                 const Lighting& lighting, const PixelRect& scissor = PixelRect::unbounded());

}  // namespace weft::raster
