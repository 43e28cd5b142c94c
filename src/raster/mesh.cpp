#include "raster/mesh.h"

#include <algorithm>

#include <glm/geometric.hpp>

namespace weft::raster {

void compute_vertex_normals(std::span<const glm::vec3> positions,
                            std::span<const TriangleIndices> triangles,
                            std::span<glm::vec3> normals) {
    if (normals.size() != positions.size()) return;
    std::fill(normals.begin(), normals.end(), glm::vec3(0.0f));
    const std::size_t count = positions.size();
    for (const TriangleIndices& t : triangles) {
        if (t[0] >= count || t[1] >= count || t[2] >= count) continue;
        const glm::vec3 face =
            glm::cross(positions[t[1]] - positions[t[0]], positions[t[2]] - positions[t[0]]);
        normals[t[0]] += face;
        normals[t[1]] += face;
        normals[t[2]] += face;
    }
    for (glm::vec3& n : normals) {
        const float length = glm::length(n);
        n = length > 0.0f ? n / length : glm::vec3(0.0f);
    }
}

std::vector<glm::vec3> compute_vertex_normals(std::span<const glm::vec3> positions,
                                              std::span<const TriangleIndices> triangles) {
    std::vector<glm::vec3> normals(positions.size());
    compute_vertex_normals(positions, triangles, normals);
    return normals;
}

std::vector<LineIndices> unique_edges(std::span<const TriangleIndices> triangles) {
    std::vector<LineIndices> edges;
    edges.reserve(triangles.size() * 3);
    for (const TriangleIndices& t : triangles) {
        for (int i = 0; i < 3; ++i) {
            const std::uint32_t a = t[i], b = t[(i + 1) % 3];
            if (a != b) edges.push_back({std::min(a, b), std::max(a, b)});
        }
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    return edges;
}

}  // namespace weft::raster
