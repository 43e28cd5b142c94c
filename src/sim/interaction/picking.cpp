#include "sim/interaction/picking.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

namespace weft {

std::optional<RayHit> cast_ray(const Cloth& cloth, const Vec3& origin, const Vec3& direction) {
    std::optional<RayHit> nearest;
    double nearest_distance = std::numeric_limits<double>::infinity();
    const Vec3* x = cloth.positions.data();
    for (std::size_t t = 0; t < cloth.topology().triangles.size(); ++t) {
        const Triangle& triangle = cloth.topology().triangles[t];
        // Möller–Trumbore: solve origin + s·direction = a + u (b - a) + v (c - a).
        const Vec3 a = x[triangle.a], edge_ab = x[triangle.b] - a, edge_ac = x[triangle.c] - a;
        const Vec3 p = glm::cross(direction, edge_ac);
        const double determinant = glm::dot(edge_ab, p);
        if (std::abs(determinant) < 1e-15) continue;  // ray parallel to the triangle
        const double inverse = 1.0 / determinant;
        const Vec3 to_origin = origin - a;
        const double u = glm::dot(to_origin, p) * inverse;
        if (u < 0.0 || u > 1.0) continue;
        const Vec3 q = glm::cross(to_origin, edge_ab);
        const double v = glm::dot(direction, q) * inverse;
        if (v < 0.0 || u + v > 1.0) continue;
        const double distance = glm::dot(edge_ac, q) * inverse;
        if (distance <= 0.0 || distance >= nearest_distance) continue;
        nearest_distance = distance;
        // Barycentric weights (1 - u - v, u, v): the largest marks the nearest corner.
        const double w = 1.0 - u - v;
        const std::uint32_t corner =
            (w >= u && w >= v) ? triangle.a : (u >= v ? triangle.b : triangle.c);
        nearest =
            RayHit{static_cast<std::uint32_t>(t), corner, distance, origin + distance * direction};
    }
    return nearest;
}

}  // namespace weft
