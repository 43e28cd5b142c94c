// The viewport transform: from normalised device coordinates to window coordinates.
//
// Window coordinates are continuous: x to the right and y downwards in pixels, (0, 0) the
// top-left corner of pixel (0, 0), whose centre is (0.5, 0.5); the framebuffer spans
// [0, width] × [0, height]. Depth maps NDC z in [-1, 1] (glm's default clip convention) to
// window depth in [0, 1]. Everything that samples pixels — triangles, lines, points, camera
// rays — uses this one mapping.
#pragma once

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace weft::raster {

inline glm::vec3 ndc_to_window(const glm::vec3& ndc, int width, int height) {
    return {(ndc.x + 1.0f) * 0.5f * static_cast<float>(width),
            (1.0f - ndc.y) * 0.5f * static_cast<float>(height), ndc.z * 0.5f + 0.5f};
}

inline glm::vec3 window_to_ndc(const glm::vec3& window, int width, int height) {
    return {window.x / static_cast<float>(width) * 2.0f - 1.0f,
            1.0f - window.y / static_cast<float>(height) * 2.0f, window.z * 2.0f - 1.0f};
}

// Perspective divide, then viewport. Only meaningful for w > 0 (in front of the camera).
inline glm::vec3 clip_to_window(const glm::vec4& clip, int width, int height) {
    return ndc_to_window(glm::vec3(clip) / clip.w, width, height);
}

}  // namespace weft::raster
