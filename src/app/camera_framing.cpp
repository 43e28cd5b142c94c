#include "app/camera_framing.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "raster/camera.h"

namespace weft::app {

Box bounding_box(std::span<const Vec3> positions) {
    if (positions.empty()) return {};
    Vec3 low = positions[0], high = positions[0];
    for (const Vec3& x : positions) {
        low = glm::min(low, x);
        high = glm::max(high, x);
    }
    return {glm::vec3(low), glm::vec3(high)};
}

CameraRig framed(const CameraRig& rig, const Box& box, float aspect, float margin) {
    // In the camera's frame (right r, up u, forward f) a point q relative to the target, at
    // distance d behind it, projects to x = q·r / (d + q·f), y = q·u / (d + q·f) in units of
    // the tangent: it is inside the inner border when |q·r| <= tx (d + q·f) and
    // |q·u| <= ty (d + q·f), that is d >= |q·r| / tx - q·f and d >= |q·u| / ty - q·f. The
    // least d is the largest of these over the corners, and that corner sits on the border.
    const raster::CameraBasis basis = raster::camera_basis(rig.camera());
    const float kept = std::clamp(1.0f - margin, 0.05f, 1.0f);
    const float ty = std::tan(0.5f * glm::radians(rig.fov_degrees)) * kept;
    const float tx = ty * std::max(aspect, 1e-3f);
    const glm::vec3 centre = box.centre();
    float distance = CameraRig::min_target_distance;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 q =
            glm::vec3(corner & 1 ? box.high.x : box.low.x, corner & 2 ? box.high.y : box.low.y,
                      corner & 4 ? box.high.z : box.low.z) -
            centre;
        const float depth = glm::dot(q, basis.forward);
        distance = std::max({distance, std::abs(glm::dot(q, basis.right)) / tx - depth,
                             std::abs(glm::dot(q, basis.up)) / ty - depth,
                             // every corner in front of the near plane, with room to spare
                             -depth + 10.0f * rig.camera().near_plane});
    }
    CameraRig result = rig;
    result.target_distance = std::min(distance, CameraRig::max_target_distance);
    result.position = centre - result.target_distance * rig.forward();
    return result;
}

}  // namespace weft::app
