// Lone springs: springs with no intact triangle along them, which the shaded surface does not
// show. After a cut or a tear a piece of cloth can hang by one such spring; drawn as a thin
// line, it no longer seems to float.
#pragma once

#include <span>
#include <vector>

#include <glm/vec2.hpp>

#include "raster/mesh.h"
#include "sim/core/cloth.h"

namespace weft::view {

// The springs of `cloth` that leave the surface: at one of its ends (or both) no intact
// triangle lies along the spring. A triangle lies along spring (i, j) at i when it has i as
// a corner and the direction from i to j, in the rest sheet `rest` (one point per particle,
// m), falls within its corner's angle, edges included: for a structural spring or the shear
// diagonal that splits a cell, the triangles on either side of it; for the other diagonal,
// the triangle the diagonal crosses; for a bend spring, those beside its first structural
// edge. On a whole sheet no spring is lone (the offset layout's springs along its zig-zag
// sides, which pass outside the whole sheet's surface, never are). A mesh cloth's springs are
// judged by topology instead: lone unless a triangle at one end is, or touches, a triangle
// at the other (lone_springs.cpp). `around` lists each particle's
// triangles among `triangles` (raster::find_vertex_triangles).
std::vector<raster::LineIndices> find_lone_springs(
    const Cloth& cloth, std::span<const glm::vec2> rest,
    std::span<const raster::TriangleIndices> triangles, const raster::VertexTriangles& around);

}  // namespace weft::view
