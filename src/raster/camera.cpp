#include "raster/camera.h"

#include <algorithm>
#include <cmath>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "raster/framebuffer.h"
#include "raster/viewport.h"

namespace weft::raster {
namespace {

// Ranges that keep the projection finite and invertible.
constexpr float min_fov_degrees = 0.01f;
constexpr float max_fov_degrees = 179.0f;
constexpr float min_near = 1e-6f;

float usable_fov_degrees(const Camera& camera) {
    const float fov = camera.fov_degrees;
    return fov == fov ? std::clamp(fov, min_fov_degrees, max_fov_degrees) : 50.0f;
}

float usable_near(const Camera& camera) {
    return camera.near_plane > min_near ? camera.near_plane : min_near;
}

float usable_far(const Camera& camera) {
    const float near_plane = usable_near(camera);
    return camera.far_plane > near_plane * 1.001f ? camera.far_plane : near_plane * 1.001f + 1.0f;
}

glm::vec3 normalised_or(const glm::vec3& v, const glm::vec3& fallback) {
    const float length = glm::length(v);
    return length > 1e-20f && std::isfinite(length) ? v / length : fallback;
}

}  // namespace

Camera make_camera(const glm::vec3& position, const glm::vec3& target, float fov_degrees) {
    Camera camera;
    camera.position = position;
    camera.target = target;
    camera.fov_degrees = fov_degrees;
    return camera;
}

CameraBasis camera_basis(const Camera& camera) {
    const glm::vec3 forward =
        normalised_or(camera.target - camera.position, glm::vec3(0.0f, 0.0f, -1.0f));
    glm::vec3 up = normalised_or(camera.up, glm::vec3(0.0f, 1.0f, 0.0f));
    // Looking (almost) along `up` leaves the roll undefined: borrow the axis least aligned
    // with the view direction instead.
    if (std::abs(glm::dot(up, forward)) > 0.9999f) {
        up = std::abs(forward.z) < 0.9f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
    }
    const glm::vec3 right = glm::normalize(glm::cross(forward, up));
    return {right, glm::cross(right, forward), forward};
}

float aspect_ratio(int width, int height) {
    return height > 0 && width > 0 ? static_cast<float>(width) / static_cast<float>(height) : 1.0f;
}

glm::mat4 view_matrix(const Camera& camera) {
    const CameraBasis basis = camera_basis(camera);
    return glm::lookAtRH(camera.position, camera.position + basis.forward, basis.up);
}

glm::mat4 projection_matrix(const Camera& camera, float aspect) {
    const float usable_aspect = aspect > 0.0f && std::isfinite(aspect) ? aspect : 1.0f;
    return glm::perspectiveRH_NO(glm::radians(usable_fov_degrees(camera)), usable_aspect,
                                 usable_near(camera), usable_far(camera));
}

glm::mat4 view_projection_matrix(const Camera& camera, int width, int height) {
    return projection_matrix(camera, aspect_ratio(width, height)) * view_matrix(camera);
}

glm::mat4 view_projection_matrix(const Camera& camera, const Framebuffer& framebuffer) {
    return view_projection_matrix(camera, framebuffer.width(), framebuffer.height());
}

Ray camera_ray(const Camera& camera, int width, int height, const glm::vec2& window_point) {
    // Built from the camera frame directly rather than by inverting the matrices: the point
    // at NDC (x, y) on the plane one unit ahead of the eye is forward + x·tan(fov/2)·aspect
    // along right + y·tan(fov/2) along up.
    const CameraBasis basis = camera_basis(camera);
    const glm::vec3 ndc = window_to_ndc(glm::vec3(window_point, 0.0f), width, height);
    const float tan_half_fov = std::tan(glm::radians(usable_fov_degrees(camera)) * 0.5f);
    const float aspect = aspect_ratio(width, height);
    const glm::vec3 direction = basis.forward + basis.right * (ndc.x * tan_half_fov * aspect) +
                                basis.up * (ndc.y * tan_half_fov);
    return {camera.position, glm::normalize(direction)};
}

std::optional<glm::vec3> project_to_window(const Camera& camera, int width, int height,
                                           const glm::vec3& world_point) {
    const glm::vec4 clip =
        view_projection_matrix(camera, width, height) * glm::vec4(world_point, 1.0f);
    if (!(clip.z >= -clip.w) || !(clip.w > 0.0f)) return std::nullopt;
    return clip_to_window(clip, width, height);
}

}  // namespace weft::raster
