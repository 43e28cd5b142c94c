#include "view/lone_springs.h"

#include <cmath>

namespace weft::view {
namespace {

float cross(const glm::vec2& a, const glm::vec2& b) {
    return a.x * b.y - a.y * b.x;
}

// Whether some triangle around `from` lies along the direction toward `to` in the rest
// sheet: the direction within the triangle's angle at `from`, its two edges included.
bool surface_along(std::uint32_t from, std::uint32_t to, std::span<const glm::vec2> rest,
                   std::span<const raster::TriangleIndices> triangles,
                   const raster::VertexTriangles& around) {
    const glm::vec2 d = rest[to] - rest[from];
    for (std::uint32_t k = around.offsets[from]; k < around.offsets[from + 1]; ++k) {
        const raster::TriangleIndices& t = triangles[around.triangles[k]];
        const int corner = t[0] == from ? 0 : t[1] == from ? 1 : 2;
        const glm::vec2 e1 = rest[t[(corner + 1) % 3]] - rest[from];
        const glm::vec2 e2 = rest[t[(corner + 2) % 3]] - rest[from];
        // d = a e1 + b e2 with a, b >= 0: cross(e1, d) and cross(d, e2) share the sign of
        // cross(e1, e2), or are zero along an edge (up to rounding, hence the slack).
        const float turn = cross(e1, e2);
        if (turn == 0.0f) continue;  // a degenerate triangle covers nothing
        const float side = turn > 0.0f ? 1.0f : -1.0f;
        const float slack = 1e-4f * std::abs(turn);
        if (side * cross(e1, d) >= -slack && side * cross(d, e2) >= -slack) return true;
    }
    return false;
}

// In the offset layout the sheet's left and right sides zig-zag, and the spring joining two
// outer particles of one side two rows apart runs straight past the notch between them,
// outside the surface of the whole sheet: it is part of the sheet's look, not a loose thread.
bool along_a_zigzag_side(const Cloth& cloth, const Spring& s) {
    if (cloth.odd_row_shift == 0.0 || cloth.cols < 2) return false;
    const auto cols = static_cast<std::uint32_t>(cloth.cols);
    const std::uint32_t col = s.i % cols;
    const std::uint32_t row_i = s.i / cols, row_j = s.j / cols;
    const bool side = col == 0 || col == cols - 1;
    return side && s.j % cols == col && (row_i > row_j ? row_i - row_j : row_j - row_i) == 2;
}

// A mesh's springs, by topology: its structural springs are triangle edges, and its bend
// and shear springs join corners of faces that meet at an edge, so a spring stays with the
// surface while a triangle at one end is, or touches, a triangle at the other. (A mesh's rest
// shape may be curved, a skirt, where a bend spring's straight line leaves the plane of the
// triangles at its ends, and no flat layout, such as its texture coordinates unrolled
// around an axis with a seam, serves the grid's angle test everywhere.) A piece torn off
// and hanging by the spring alone touches the rest nowhere: lone.
bool held_by_triangles(const Spring& s, std::span<const raster::TriangleIndices> triangles,
                       const raster::VertexTriangles& around) {
    for (std::uint32_t a = around.offsets[s.i]; a < around.offsets[s.i + 1]; ++a) {
        const raster::TriangleIndices& at_i = triangles[around.triangles[a]];
        for (std::uint32_t b = around.offsets[s.j]; b < around.offsets[s.j + 1]; ++b) {
            const raster::TriangleIndices& at_j = triangles[around.triangles[b]];
            for (std::uint32_t u : at_i)
                if (u == at_j[0] || u == at_j[1] || u == at_j[2]) return true;
        }
    }
    return false;
}

}  // namespace

std::vector<raster::LineIndices> find_lone_springs(
    const Cloth& cloth, std::span<const glm::vec2> rest,
    std::span<const raster::TriangleIndices> triangles, const raster::VertexTriangles& around) {
    std::vector<raster::LineIndices> lone;
    const bool mesh = cloth.is_mesh();
    for (const SpringGroup& group : cloth.topology().spring_groups)
        for (const Spring& s : group.springs)
            if (mesh) {
                if (!held_by_triangles(s, triangles, around)) lone.push_back({s.i, s.j});
            } else if ((!surface_along(s.i, s.j, rest, triangles, around) ||
                        !surface_along(s.j, s.i, rest, triangles, around)) &&
                       !along_a_zigzag_side(cloth, s))
                lone.push_back({s.i, s.j});
    return lone;
}

}  // namespace weft::view
