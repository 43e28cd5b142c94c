// Indexed triangle meshes as the renderer sees them: flat arrays of per-vertex data plus
// triangles of three vertex indices. MeshView borrows arrays the caller owns (the cloth's
// positions, updated every frame); TriangleMesh owns them (a tessellated sphere).
//
// Winding: a triangle is counter-clockwise seen from its front side, as weft::Triangle is;
// compute_vertex_normals makes normals point out of the front.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace weft::raster {

using TriangleIndices = std::array<std::uint32_t, 3>;
using LineIndices = std::array<std::uint32_t, 2>;

struct MeshView {
    std::span<const glm::vec3> positions;        // model space (= world space unless `model`)
    std::span<const glm::vec3> normals;          // one per position; need not be unit length
    std::span<const TriangleIndices> triangles;  // out-of-range indices: triangle skipped
    std::span<const glm::vec2> uvs = {};         // optional, one per position: for patterns
    std::span<const glm::vec3> colours = {};     // optional, one per position: replaces the
                                                 // style's front and back colours (strain map)
    glm::mat4 model{1.0f};                       // model → world
    // When above 1: the triangles are exactly the whole grid of grid_normals.h, of
    // positions.size() / grid_cols rows of grid_cols vertices (its maker checks it:
    // is_whole_grid), which lets binning load a group's corners instead of gathering them.
    int grid_cols = 0;
};

struct TriangleMesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs;
    std::vector<TriangleIndices> triangles;

    MeshView view(const glm::mat4& model = glm::mat4(1.0f)) const {
        return {positions, normals, triangles, uvs, {}, model};
    }
};

// Per-vertex normals: each triangle adds its unnormalised face normal (cross product, whose
// length is twice its area, so larger triangles weigh more) to its three vertices; the sums
// are normalised. A vertex no triangle touches, or whose sum vanishes, gets (0, 0, 0).
// `normals` must have as many elements as `positions` (else nothing is written).
void compute_vertex_normals(std::span<const glm::vec3> positions,
                            std::span<const TriangleIndices> triangles,
                            std::span<glm::vec3> normals);
std::vector<glm::vec3> compute_vertex_normals(std::span<const glm::vec3> positions,
                                              std::span<const TriangleIndices> triangles);

// The triangles around each vertex, ascending: triangles[offsets[v]] up to (not including)
// triangles[offsets[v + 1]]. A triangle naming a vertex twice is listed twice; one with an
// index out of range is not listed.
struct VertexTriangles {
    std::vector<std::uint32_t> offsets;
    std::vector<std::uint32_t> triangles;
};
void find_vertex_triangles(std::span<const TriangleIndices> triangles, std::size_t vertex_count,
                           VertexTriangles& around);

// compute_vertex_normals in two passes that threads can share, each taking a slice:
// first each triangle's face normal (triangles [begin, end); zero for a triangle with an
// index out of range), then each vertex's sum of the faces around it, in ascending order —
// the same sums in the same order as the whole mesh's, hence the same bits. `faces` has one
// element per triangle; `around` was found for these triangles and positions.size() vertices.
void compute_face_normals(std::span<const glm::vec3> positions,
                          std::span<const TriangleIndices> triangles, std::span<glm::vec3> faces,
                          std::size_t begin, std::size_t end);
void gather_vertex_normals(std::span<const glm::vec3> faces, const VertexTriangles& around,
                           std::span<glm::vec3> normals, std::size_t begin, std::size_t end);

// Every edge of the triangles once (smaller index first), sorted: a wireframe's lines.
std::vector<LineIndices> unique_edges(std::span<const TriangleIndices> triangles);

}  // namespace weft::raster
