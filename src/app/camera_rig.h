// CameraRig: the demo's keyboard camera — a position and a heading (yaw, pitch) moved at a
// speed in metres per second and turned in radians per second, so motion does not depend
// on the frame rate. SDL-free, so it is unit-tested.
#pragma once

#include <glm/vec3.hpp>

#include "raster/camera.h"

namespace weft::app {

struct CameraRig {
    glm::vec3 position{0.0f, 0.0f, 3.0f};  // m
    float yaw = 0.0f;                      // rad, about +y; 0 looks down -z
    float pitch = 0.0f;                    // rad, up positive, within ±89°
    float fov_degrees = 50.0f;

    static CameraRig looking_at(const glm::vec3& position, const glm::vec3& target,
                                float fov_degrees);

    glm::vec3 forward() const;
    glm::vec3 right() const;

    // Moves by (right, up, forward) × speed × seconds; up is the world's.
    void move(const glm::vec3& right_up_forward, float speed, float seconds);
    // Turns by rates (rad/s) for `seconds`; pitch is clamped short of straight up or down.
    void turn(float yaw_rate, float pitch_rate, float seconds);
    // Mouse wheel: each notch moves 10 % of the way towards what the camera looks at, or
    // 0.1 m, whichever is more.
    void zoom(float notches, float distance_to_target);

    raster::Camera camera() const;
};

}  // namespace weft::app
