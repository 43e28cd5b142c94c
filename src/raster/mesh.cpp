#include "raster/mesh.h"

#include <algorithm>

#include <glm/geometric.hpp>

namespace weft::raster {
namespace {

// The vertex normal from the sum of its triangles' face normals.
glm::vec3 unit_or_zero(const glm::vec3& sum) {
    const float length = glm::length(sum);
    return length > 0.0f ? sum / length : glm::vec3(0.0f);
}

// A triangle's unnormalised normal: twice its area long.
// Always inlined: it runs for every triangle of every frame, and a call costs as much.
[[gnu::always_inline]] inline glm::vec3 face_normal(std::span<const glm::vec3> positions,
                                                    const TriangleIndices& t) {
    return glm::cross(positions[t[1]] - positions[t[0]], positions[t[2]] - positions[t[0]]);
}

}  // namespace

void compute_vertex_normals(std::span<const glm::vec3> positions,
                            std::span<const TriangleIndices> triangles,
                            std::span<glm::vec3> normals) {
    if (normals.size() != positions.size()) return;
    std::fill(normals.begin(), normals.end(), glm::vec3(0.0f));
    const std::size_t count = positions.size();
    for (const TriangleIndices& t : triangles) {
        if (t[0] >= count || t[1] >= count || t[2] >= count) continue;
        const glm::vec3 face = face_normal(positions, t);
        normals[t[0]] += face;
        normals[t[1]] += face;
        normals[t[2]] += face;
    }
    for (glm::vec3& n : normals) n = unit_or_zero(n);
}

void find_vertex_triangles(std::span<const TriangleIndices> triangles, std::size_t vertex_count,
                           VertexTriangles& around) {
    around.offsets.assign(vertex_count + 1, 0);
    auto in_range = [&](const TriangleIndices& t) {
        return t[0] < vertex_count && t[1] < vertex_count && t[2] < vertex_count;
    };
    for (const TriangleIndices& t : triangles)
        if (in_range(t))
            for (std::uint32_t corner : t) ++around.offsets[corner + 1];
    for (std::size_t v = 0; v < vertex_count; ++v) around.offsets[v + 1] += around.offsets[v];
    around.triangles.resize(around.offsets[vertex_count]);
    std::vector<std::uint32_t> next(around.offsets.begin(), around.offsets.end() - 1);
    for (std::size_t index = 0; index < triangles.size(); ++index)
        if (in_range(triangles[index]))
            for (std::uint32_t corner : triangles[index])
                around.triangles[next[corner]++] = static_cast<std::uint32_t>(index);
}

void compute_face_normals(std::span<const glm::vec3> positions,
                          std::span<const TriangleIndices> triangles, std::span<glm::vec3> faces,
                          std::size_t begin, std::size_t end) {
    const std::size_t count = positions.size();
    for (std::size_t index = begin; index < end; ++index) {
        const TriangleIndices& t = triangles[index];
        faces[index] = t[0] < count && t[1] < count && t[2] < count ? face_normal(positions, t)
                                                                    : glm::vec3(0.0f);
    }
}

void gather_vertex_normals(std::span<const glm::vec3> faces, const VertexTriangles& around,
                           std::span<glm::vec3> normals, std::size_t begin, std::size_t end) {
    for (std::size_t v = begin; v < end; ++v) {
        glm::vec3 sum(0.0f);
        for (std::uint32_t k = around.offsets[v]; k < around.offsets[v + 1]; ++k)
            sum += faces[around.triangles[k]];
        normals[v] = unit_or_zero(sum);
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
