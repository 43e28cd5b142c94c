#include "app/camera_framing.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <vector>

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

namespace {

// The root of p's piece, halving the path on the way (union-find).
std::uint32_t piece_root(std::vector<std::uint32_t>& parent, std::uint32_t p) {
    while (parent[p] != p) {
        parent[p] = parent[parent[p]];
        p = parent[p];
    }
    return p;
}

}  // namespace

Box largest_piece_box(const Cloth& cloth) {
    const std::size_t count = cloth.positions.size();
    std::vector<std::uint32_t> parent(count);
    for (std::size_t p = 0; p < count; ++p) parent[p] = static_cast<std::uint32_t>(p);
    for (const SpringGroup& group : cloth.topology().spring_groups)
        for (const Spring& spring : group.springs) {
            if (spring.i >= count || spring.j >= count) continue;
            const std::uint32_t a = piece_root(parent, spring.i), b = piece_root(parent, spring.j);
            if (a != b) parent[std::max(a, b)] = std::min(a, b);
        }
    std::vector<std::uint32_t> size(count, 0);
    std::uint32_t largest = 0;
    for (std::size_t p = 0; p < count; ++p) {
        const std::uint32_t root = piece_root(parent, static_cast<std::uint32_t>(p));
        if (++size[root] > size[largest] || (size[root] == size[largest] && root < largest))
            largest = root;
    }
    std::vector<Vec3> piece;
    for (std::size_t p = 0; p < count; ++p) {
        const Vec3& x = cloth.positions[p];
        if (piece_root(parent, static_cast<std::uint32_t>(p)) == largest && std::isfinite(x.x) &&
            std::isfinite(x.y) && std::isfinite(x.z))
            piece.push_back(x);
    }
    return bounding_box(piece);
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
