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
    if (glm::length(direction) > 0.0f) {
        const glm::vec3 d = glm::normalize(direction);
        rig.yaw = std::atan2(-d.x, -d.z);
        rig.pitch = std::clamp(std::asin(std::clamp(d.y, -1.0f, 1.0f)), -max_pitch, max_pitch);
    }
    return rig;
}

glm::vec3 CameraRig::forward() const {
    return {-std::sin(yaw) * std::cos(pitch), std::sin(pitch), -std::cos(yaw) * std::cos(pitch)};
}

glm::vec3 CameraRig::right() const {
    return {std::cos(yaw), 0.0f, -std::sin(yaw)};
}

void CameraRig::move(const glm::vec3& right_up_forward, float speed, float seconds) {
    const float distance = speed * seconds;
    position += distance *
                (right_up_forward.x * right() + right_up_forward.y * glm::vec3(0.0f, 1.0f, 0.0f) +
                 right_up_forward.z * forward());
}

void CameraRig::turn(float yaw_rate, float pitch_rate, float seconds) {
    yaw += yaw_rate * seconds;
    pitch = std::clamp(pitch + pitch_rate * seconds, -max_pitch, max_pitch);
}

void CameraRig::zoom(float notches, float distance_to_target) {
    position += notches * std::max(0.1f, 0.1f * distance_to_target) * forward();
}

raster::Camera CameraRig::camera() const {
    raster::Camera camera = raster::make_camera(position, position + forward(), fov_degrees);
    camera.near_plane = 0.01f;  // 1 cm: fly close to the cloth without cutting holes in it
    return camera;
}

}  // namespace weft::app
