#include "app/camera_rig.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace weft::app {
namespace {

constexpr float max_pitch = 1.5533f;  // 89°

}  // namespace

CameraRig CameraRig::looking_at(const glm::vec3& position, const glm::vec3& target,
                                float fov_degrees) {
    CameraRig rig;
    rig.position = position;
    rig.fov_degrees = fov_degrees;
    const glm::vec3 direction = target - position;
    const float distance = glm::length(direction);
    if (distance > 0.0f) {
        const glm::vec3 d = direction / distance;
        rig.yaw = std::atan2(-d.x, -d.z);
        rig.pitch = std::clamp(std::asin(std::clamp(d.y, -1.0f, 1.0f)), -max_pitch, max_pitch);
    }
    rig.target_distance = std::clamp(distance, min_target_distance, max_target_distance);
    return rig;
}

glm::vec3 CameraRig::forward() const {
    return {-std::sin(yaw) * std::cos(pitch), std::sin(pitch), -std::cos(yaw) * std::cos(pitch)};
}

glm::vec3 CameraRig::right() const {
    return {std::cos(yaw), 0.0f, -std::sin(yaw)};
}

glm::vec3 CameraRig::target() const {
    return position + target_distance * forward();
}

void CameraRig::move(const glm::vec3& right_up_forward, float speed, float seconds) {
    const float distance = speed * seconds;
    position += distance *
                (right_up_forward.x * right() + right_up_forward.y * glm::vec3(0.0f, 1.0f, 0.0f) +
                 right_up_forward.z * forward());
}

void CameraRig::orbit(float rightward_rate, float upward_rate, float seconds) {
    // The camera sits at target - distance·forward: raising yaw swings it to its right, and
    // lowering pitch (looking further down) lifts it over the target.
    const glm::vec3 centre = target();
    yaw += rightward_rate * seconds;
    pitch = std::clamp(pitch - upward_rate * seconds, -max_pitch, max_pitch);
    position = centre - target_distance * forward();
}

void CameraRig::zoom(float notches) {
    const glm::vec3 centre = target();
    target_distance = std::clamp(target_distance * std::pow(zoom_kept_per_notch, notches),
                                 min_target_distance, max_target_distance);
    position = centre - target_distance * forward();
}

raster::Camera CameraRig::camera() const {
    raster::Camera camera = raster::make_camera(position, position + forward(), fov_degrees);
    camera.near_plane = 0.01f;  // 1 cm: fly close to the cloth without cutting holes in it
    return camera;
}

}  // namespace weft::app
