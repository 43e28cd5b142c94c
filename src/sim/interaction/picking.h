// Picking: which part of the cloth a ray (from the camera through the cursor) hits.
// Only intact triangles count, so a ray through a tear or past the edge grabs nothing.
#pragma once

#include <cstdint>
#include <optional>

#include "sim/core/cloth.h"

namespace weft {

struct RayHit {
    std::uint32_t triangle;  // index into cloth.topology().triangles
    std::uint32_t particle;  // the hit triangle's corner nearest the hit point
    double distance;         // m along the (unit) ray direction
    Vec3 point;              // m, where the ray meets the triangle
};

// The nearest intersection of the ray origin + t·direction (t > 0, direction unit length)
// with the cloth's triangles, both sides, or nothing if it misses.
std::optional<RayHit> cast_ray(const Cloth& cloth, const Vec3& origin, const Vec3& direction);

}  // namespace weft
