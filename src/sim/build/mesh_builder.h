// Mesh cloth: a Cloth built from an OBJ mesh (obj_reader.h) instead of a grid. The vertices
// become the particles and the faces' edges the structural springs; the rest is derived from
// how faces meet, so that a grid written as quads gets exactly the grid builder's springs.
//
// A mesh cloth is not a grid: it has no grid stencil (so the structured fast paths are not
// used), its particles count as one row (rows = 1, cols = particle count: dumps say "row 0,
// col N-1" for vertex N; messages say "vertex N", particle_name in cloth.h), `spacing` is its
// mean structural rest length, `mesh_extent` its size and `mesh_rest_shape` its vertices as
// built.
//
// Except a mesh that is exactly a grid builder's sheet (rows × cols vertices in row-major
// order at one spacing along two coordinate axes, one quad per cell in row order): that one
// is built as the grid builder builds its sheet (cloth_builder.h): rows, cols and spacing of
// the grid, the springs in the grid's order and colours, its triangles and stencil, and no
// mesh extent or rest shape. Given the same masses (cloth.particle_mass) it then steps bit
// for bit as the grid's sheet does, and hashes alike.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sim/core/cloth.h"
#include "sim/scene/obj_reader.h"
#include "sim/scene/scene.h"

namespace weft {

// The topology an OBJ mesh implies, with rest lengths from the file's positions.
struct MeshTopology {
    // For drawing: each triangle, and each quad (a, b, c, d) as (a, b, c) and (a, c, d), in
    // file order and wound as in the file.
    std::vector<Triangle> triangles;
    // Springs sorted by (i, j) with i < j, each once, so nothing depends on hashing order.
    std::vector<Spring> structural;  // the faces' sides (not a quad's split diagonal)
    std::vector<Spring> shear;       // both diagonals of every quad
    // Across every edge two faces share: two triangles get the spring joining their opposite
    // vertices; two quads (p, u, v, q) and (u, r, s, v) the two that continue each
    // endpoint's line across it, p–r and q–s (a grid's (r,c)-(r,c+2) and (r,c)-(r+2,c)); a
    // triangle and a quad count the quad's split triangle on that edge.
    std::vector<Spring> bend;
    std::vector<double> areas;  // m² per vertex: a third of each triangle it is a corner of
};

// Throws ObjError at the face's line for a degenerate (zero-area) triangle, an edge shared by
// more than two faces, or two faces folded onto each other; at the vertex's line for a vertex
// in no face (it would have no mass).
MeshTopology derive_mesh_topology(const ObjMesh& mesh);

// What is wrong with the spec's mesh pins, naming the vertex number or group; nullopt if
// they fit the mesh.
std::optional<std::string> mesh_pin_problem(const ClothSpec& spec, const ObjMesh& mesh);

// The cloth of a scene whose cloth.mesh is loaded (scene_loader.h checks it): particles at
// the vertices moved by cloth.origin, at rest; masses lumped from the triangles' areas times
// cloth.density, or cloth.particle_mass each when cloth.mesh_particle_mass; the spring
// families the scene enables; pins from cloth.pin_vertices or cloth.pin_group. Throws
// std::invalid_argument for a scene that did not pass the loader's checks (no mesh loaded, pins
// that do not fit), ObjError as derive_mesh_topology does.
Cloth build_mesh_cloth(const Scene& scene);

}  // namespace weft
