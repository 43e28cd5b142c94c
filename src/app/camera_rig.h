// CameraRig: the demo's camera, as in a model viewer — it looks at a target a distance ahead,
// the arrow keys orbit around that target and the mouse wheel dollies toward it, while the
// free-fly keys move camera and target together. Rates are in metres and radians per
// second, so motion does not depend on the frame rate. SDL-free, so it is unit-tested.
#pragma once

#include <glm/vec3.hpp>

#include "raster/camera.h"

namespace weft::app {

struct CameraRig {
    // Arrow keys: 0.8 rad/s is a full circle in about 8 s. Turning the camera in place at
    // 1.2 rad/s took a newcomer's view off the cloth within a second; orbiting keeps the
    // target on screen at any rate, and this one is slow enough to stop where wanted.
    static constexpr float orbit_rate = 0.8f;  // rad/s
    // Mouse wheel: each notch in keeps this share of the distance to the target (out divides
    // by it), so a notch is as noticeable close up as far away and zooming in can never
    // reach or pass the target; in then out comes back to the same place.
    static constexpr float zoom_kept_per_notch = 0.85f;
    static constexpr float min_target_distance = 0.05f;    // m: 5 near planes
    static constexpr float max_target_distance = 1000.0f;  // m

    glm::vec3 position{0.0f, 0.0f, 3.0f};  // m
    float yaw = 0.0f;                      // rad, about +y; 0 looks down -z
    float pitch = 0.0f;                    // rad, up positive, within ±89°
    float target_distance = 3.0f;          // m, from the camera along forward() to the target
    float fov_degrees = 50.0f;

    static CameraRig looking_at(const glm::vec3& position, const glm::vec3& target,
                                float fov_degrees);

    glm::vec3 forward() const;
    glm::vec3 right() const;
    glm::vec3 target() const;  // m: what the camera looks at and orbits around

    // Free fly: moves camera and target by (right, up, forward) × speed × seconds; up is the
    // world's.
    void move(const glm::vec3& right_up_forward, float speed, float seconds);
    // Moves the camera around its target by rates (rad/s) for `seconds`, at the same
    // distance and still looking at it: positive `rightward` moves the camera to its right,
    // positive `upward` over the target. The climb stops short of straight up or down.
    void orbit(float rightward_rate, float upward_rate, float seconds);
    // Mouse wheel: `notches` > 0 moves toward the target, < 0 away from it, by
    // zoom_kept_per_notch of the distance per notch (within the distance limits).
    void zoom(float notches);

    raster::Camera camera() const;
};

}  // namespace weft::app
