#include "sim/colliders.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace weft {
namespace {

Vec3 to_vec3(const Vec3d& v) {
    return {v[0], v[1], v[2]};
}

}  // namespace

std::vector<Collider> make_colliders(const std::vector<ColliderSpec>& specs) {
    std::vector<Collider> colliders;
    for (const ColliderSpec& spec : specs) {
        Collider c;
        c.type = spec.type;
        c.center = to_vec3(spec.center);
        c.radius = spec.radius;
        c.point = to_vec3(spec.point);
        c.normal = glm::normalize(to_vec3(spec.normal));
        c.response = spec.response;
        c.restitution = spec.restitution;
        c.friction = spec.friction;
        colliders.push_back(c);
    }
    return colliders;
}

double signed_distance(const Collider& collider, const Vec3& x, Vec3& outward_normal) {
    if (collider.type == ColliderType::plane) {
        outward_normal = collider.normal;
        return glm::dot(x - collider.point, collider.normal);
    }
    const Vec3 from_center = x - collider.center;
    const double distance = glm::length(from_center);
    // At the very centre any direction is outward; pick up.
    outward_normal = distance > 0.0 ? from_center / distance : Vec3(0.0, 1.0, 0.0);
    return distance - collider.radius;
}

void accumulate_repulsion_forces(std::span<const Collider> colliders, const Cloth& cloth,
                                 std::span<const Vec3> positions, std::span<const Vec3> velocities,
                                 std::span<Vec3> forces) {
    constexpr double omega = repulsion_angular_frequency;
    for (const Collider& collider : colliders) {
        if (collider.response != ContactResponse::repulsion) continue;
        for (std::size_t p = 0; p < positions.size(); ++p) {
            Vec3 n;
            const double depth = repulsion_layer - signed_distance(collider, positions[p], n);
            if (depth <= 0.0) continue;
            const double mass = cloth.masses[p];
            const double normal_speed = glm::dot(velocities[p], n);
            // Spring m ω² depth and a critically damped dashpot on the normal speed; the
            // contact only pushes, never pulls.
            const double normal_force =
                std::max(0.0, mass * (omega * omega * depth - 2.0 * omega * normal_speed));
            Vec3 force = normal_force * n;
            // Coulomb friction, regularised over 1 mm/s so resting contact does not chatter.
            const Vec3 tangential = velocities[p] - normal_speed * n;
            const double sliding_speed = glm::length(tangential);
            if (sliding_speed > 0.0) {
                const double scale =
                    collider.friction * normal_force / std::max(sliding_speed, 1e-3);
                force -= scale * tangential;
            }
            forces[p] += force;
        }
    }
}

namespace {

// Moves every free particle found inside an impulse collider onto its surface, then hands it
// to `respond(collider, velocity, outward_normal)`; returns how many there were.
template <class Respond>
std::size_t move_onto_impulse_colliders(std::span<const Collider> colliders, Cloth& cloth,
                                        Respond respond) {
    std::size_t moved = 0;
    for (const Collider& collider : colliders) {
        if (collider.response != ContactResponse::impulse) continue;
        // A particle clearly outside a sphere (by a margin far above rounding) needs no
        // square root: most of the sheet, most of the time. Those nearer are measured
        // exactly as before, so every result is the same to the bit.
        const double clearly_outside_squared = collider.radius * collider.radius * (1.0 + 1e-9);
        for (std::size_t p = 0; p < cloth.particle_count(); ++p) {
            if (cloth.is_pinned(p)) continue;
            if (collider.type == ColliderType::sphere) {
                const Vec3 from_center = cloth.positions[p] - collider.center;
                if (glm::dot(from_center, from_center) > clearly_outside_squared) continue;
            }
            Vec3 n;
            const double distance = signed_distance(collider, cloth.positions[p], n);
            if (distance >= 0.0) continue;
            ++moved;
            cloth.positions[p] -= distance * n;  // onto the surface
            respond(collider, cloth.velocities[p], n);
        }
    }
    return moved;
}

}  // namespace

std::size_t resolve_impulse_contacts(std::span<const Collider> colliders, Cloth& cloth) {
    return move_onto_impulse_colliders(
        colliders, cloth, [](const Collider& collider, Vec3& v, const Vec3& n) {
            const double normal_speed = glm::dot(v, n);
            if (normal_speed >= 0.0) return;  // already leaving
            const Vec3 tangential = v - normal_speed * n;
            const double normal_change = -(1.0 + collider.restitution) * normal_speed;
            const double sliding_speed = glm::length(tangential);
            const double tangential_scale =
                sliding_speed > 0.0
                    ? std::max(0.0, 1.0 - collider.friction * normal_change / sliding_speed)
                    : 0.0;
            v = -collider.restitution * normal_speed * n + tangential_scale * tangential;
        });
}

std::size_t push_out_of_impulse_colliders(std::span<const Collider> colliders, Cloth& cloth) {
    // Only the velocity into the solid goes: restitution and friction were applied once, by
    // resolve_impulse_contacts.
    return move_onto_impulse_colliders(colliders, cloth,
                                       [](const Collider&, Vec3& v, const Vec3& n) {
                                           const double normal_speed = glm::dot(v, n);
                                           if (normal_speed < 0.0) v -= normal_speed * n;
                                       });
}

}  // namespace weft
