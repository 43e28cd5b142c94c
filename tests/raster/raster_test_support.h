// Helpers shared by the rasterizer tests: vertices placed directly in window coordinates,
// a shader that counts how often each pixel is written, and camera rays computed from first
// principles (not through the library) for ray-cast references.
#pragma once

#include <cmath>
#include <optional>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "raster/camera.h"
#include "raster/clipping.h"
#include "raster/framebuffer.h"
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

}  // namespace weft::raster::testing
