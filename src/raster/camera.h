// Camera: a perspective camera looking from a position at a target.
//
// Right-handed world, y up by default. The matrices are glm's right-handed ones with the
// OpenGL clip convention (NDC z in [-1, 1]); they are requested by their explicit names
// (lookAtRH, perspectiveRH_NO) so a GLM_FORCE_* define elsewhere cannot change them under the
// rasterizer's near-plane clipping, which assumes the near plane is z = -w.
//
// Degenerate inputs never produce NaN: a target on the position looks down -z, an up vector
// parallel to the view direction is replaced by another axis, and fov, near and far are
// clamped into a usable range (see the .cpp).
#pragma once

#include <optional>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace weft::raster {

class Framebuffer;

struct Camera {
    glm::vec3 position{0.0f, 0.0f, 3.0f};
    glm::vec3 target{0.0f, 0.0f, 0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fov_degrees = 50.0f;  // vertical field of view
    float near_plane = 0.05f;   // m; > 0. The camera can come this close to the cloth.
    float far_plane = 100.0f;   // m; > near_plane
};

// The scene file's [camera] table: position, target, vertical fov; y up, default near/far.
Camera make_camera(const glm::vec3& position, const glm::vec3& target, float fov_degrees);

// Orthonormal camera frame: right, up and forward (the direction the camera looks).
struct CameraBasis {
    glm::vec3 right;
    glm::vec3 up;
    glm::vec3 forward;
};
CameraBasis camera_basis(const Camera& camera);

float aspect_ratio(int width, int height);  // width / height

glm::mat4 view_matrix(const Camera& camera);                      // world → eye
glm::mat4 projection_matrix(const Camera& camera, float aspect);  // eye → clip
glm::mat4 view_projection_matrix(const Camera& camera, int width, int height);
glm::mat4 view_projection_matrix(const Camera& camera, const Framebuffer& framebuffer);

struct Ray {
    glm::vec3 origin;
    glm::vec3 direction;  // unit length

    glm::vec3 at(float distance) const { return origin + distance * direction; }
};

// The world-space ray from the eye through a point of the window (see viewport.h: pixel
// (x, y) has its centre at (x + 0.5, y + 0.5)). For picking: the demo grabs the cloth
// particle nearest this ray.
Ray camera_ray(const Camera& camera, int width, int height, const glm::vec2& window_point);

// Where a world point lands in the window (x, y in pixels, z window depth in [0, 1]), or
// nothing if it is not in front of the near plane.
std::optional<glm::vec3> project_to_window(const Camera& camera, int width, int height,
                                           const glm::vec3& world_point);

}  // namespace weft::raster
