#include "sim/collision/floor.h"

#include <algorithm>

namespace weft {

bool is_ground_plane(const Collider& collider) {
    return collider.type == ColliderType::plane && collider.normal.y > 0.999;
}

double floor_height(const Cloth& cloth, std::span<const Collider> colliders) {
    for (const Collider& collider : colliders)
        if (is_ground_plane(collider)) return collider.point.y;
    double lowest = 0.0;  // m
    for (const Vec3& x : cloth.positions) lowest = std::min(lowest, x.y);
    const double cloth_length = cloth.rest_span();  // m
    for (std::uint32_t p : cloth.topology().pinned)
        lowest = std::min(lowest, cloth.positions[p].y - cloth_length);
    lowest -= 0.1;
    for (const Collider& collider : colliders)
        if (collider.type == ColliderType::sphere)
            lowest = std::min(lowest, collider.center.y - collider.radius);
    return lowest;
}

Collider floor_collider(double height) {
    Collider floor;
    floor.type = ColliderType::plane;
    floor.point = Vec3(0.0, height, 0.0);
    floor.normal = Vec3(0.0, 1.0, 0.0);
    floor.response = ContactResponse::impulse;
    floor.restitution = 0.0;
    floor.friction = floor_friction;
    return floor;
}

}  // namespace weft
