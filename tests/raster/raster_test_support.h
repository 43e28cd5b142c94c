// Helpers shared by the rasterizer tests: vertices placed directly in window coordinates,
// a shader that counts how often each pixel is written, and camera rays computed from first
// principles (not through the library) for ray-cast references.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "raster/camera.h"
#include "raster/clipping.h"
#include "raster/framebuffer.h"
#include "raster/mesh.h"
#include "raster/triangle_rasterizer.h"

namespace weft::raster::testing {

// A clip-space vertex that lands exactly on window point (x, y) at window depth `depth`,
// scaled by w (which changes nothing on screen, only perspective weighting).
inline ClipVertex window_vertex(const Framebuffer& framebuffer, float x, float y,
                                float depth = 0.5f, float w = 1.0f) {
    ClipVertex v;
    const float ndc_x = 2.0f * x / static_cast<float>(framebuffer.width()) - 1.0f;
    const float ndc_y = 1.0f - 2.0f * y / static_cast<float>(framebuffer.height());
    v.position = {ndc_x * w, ndc_y * w, (2.0f * depth - 1.0f) * w, w};
    return v;
}

// Counts writes per pixel. Use with depth testing off, or a pixel drawn twice at the same
// depth would be hidden by the depth test rather than counted.
struct CoverageCounter {
    explicit CoverageCounter(const Framebuffer& framebuffer)
        : width(framebuffer.width()),
          counts(static_cast<std::size_t>(framebuffer.width() * framebuffer.height()), 0) {}

    int width;
    std::vector<int> counts;

    int at(int x, int y) const { return counts[static_cast<std::size_t>(y * width + x)]; }

    auto shader() {
        return [this](const Fragment& f) {
            ++counts[static_cast<std::size_t>(f.y * width + f.x)];
            return Rgba8{255, 255, 255, 255};
        };
    }
};

inline RasterState no_depth_state() {
    RasterState state;
    state.depth_test = false;
    state.depth_write = false;
    return state;
}

// The eye ray through window point (x, y), built from the camera's definition: look from
// position at target, vertical fov, aspect width / height, y up on screen.
struct ReferenceRay {
    glm::vec3 origin, direction;
};

inline ReferenceRay reference_ray(const Camera& camera, int width, int height, float x, float y) {
    const glm::vec3 forward = glm::normalize(camera.target - camera.position);
    const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::vec3 up = glm::cross(right, forward);
    const float half_height = std::tan(glm::radians(camera.fov_degrees) / 2.0f);
    const float half_width = half_height * static_cast<float>(width) / static_cast<float>(height);
    const float sx = (2.0f * x / static_cast<float>(width) - 1.0f) * half_width;
    const float sy = (1.0f - 2.0f * y / static_cast<float>(height)) * half_height;
    return {camera.position, glm::normalize(forward + sx * right + sy * up)};
}

// Möller–Trumbore: distance along the ray to the triangle, if it is hit in front.
inline std::optional<float> intersect_triangle(const ReferenceRay& ray, const glm::vec3& a,
                                               const glm::vec3& b, const glm::vec3& c) {
    const glm::vec3 e1 = b - a, e2 = c - a;
    const glm::vec3 p = glm::cross(ray.direction, e2);
    const float det = glm::dot(e1, p);
    if (std::abs(det) < 1e-12f) return std::nullopt;
    const float inv = 1.0f / det;
    const glm::vec3 s = ray.origin - a;
    const float u = glm::dot(s, p) * inv;
    if (u < 0.0f || u > 1.0f) return std::nullopt;
    const glm::vec3 q = glm::cross(s, e1);
    const float v = glm::dot(ray.direction, q) * inv;
    if (v < 0.0f || u + v > 1.0f) return std::nullopt;
    const float t = glm::dot(e2, q) * inv;
    if (t <= 0.0f) return std::nullopt;
    return t;
}

// A sheet of `cells`² quads rolled into a spiral of more than one turn about the y axis, so
// that seen from +z its layers overlap, showing both sides, and (finely divided) its
// triangles are smaller than a pixel.
inline TriangleMesh spiral_sheet(int cells) {
    TriangleMesh sheet;
    for (int j = 0; j <= cells; ++j) {
        for (int i = 0; i <= cells; ++i) {
            const float u = static_cast<float>(i) / static_cast<float>(cells);
            const float v = static_cast<float>(j) / static_cast<float>(cells);
            const float angle = 7.5f * u, radius = 0.3f + 0.6f * u;
            sheet.positions.push_back(
                {radius * std::cos(angle), 1.6f * v - 0.8f, radius * std::sin(angle)});
            sheet.normals.push_back({std::cos(angle), 0.0f, std::sin(angle)});
            sheet.uvs.push_back({u, v});
        }
    }
    const auto row = static_cast<std::uint32_t>(cells + 1);
    for (std::uint32_t j = 0; j + 1 < row; ++j) {
        for (std::uint32_t i = 0; i + 1 < row; ++i) {
            const std::uint32_t corner = j * row + i;
            sheet.triangles.push_back({corner, corner + 1, corner + row});
            sheet.triangles.push_back({corner + 1, corner + row + 1, corner + row});
        }
    }
    return sheet;
}

// The triangles of a whole grid of rows × cols vertices in the cloth builder's order and
// split (grid_normals.h): cell by cell, (top left, bottom left, top right) then (top right,
// bottom left, bottom right).
inline std::vector<TriangleIndices> whole_grid_triangles(int rows, int cols) {
    std::vector<TriangleIndices> triangles;
    for (int r = 0; r + 1 < rows; ++r) {
        for (int c = 0; c + 1 < cols; ++c) {
            const auto top_left = static_cast<std::uint32_t>(r * cols + c);
            const auto bottom_left = top_left + static_cast<std::uint32_t>(cols);
            triangles.push_back({top_left, bottom_left, top_left + 1});
            triangles.push_back({top_left + 1, bottom_left, bottom_left + 1});
        }
    }
    return triangles;
}

// Whether two frames of one size hold the same colours and the same depths, to the byte.
inline bool same_frame(const Framebuffer& a, const Framebuffer& b) {
    return std::equal(a.colours().begin(), a.colours().end(), b.colours().begin()) &&
           std::equal(a.depths().begin(), a.depths().end(), b.depths().begin());
}

}  // namespace weft::raster::testing
