#include "sim/drag.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace weft {

DragHandle grab_cloth(const Cloth& cloth, const RayHit& hit, double radius) {
    DragHandle drag;
    drag.target = hit.point;
    const double radius_squared = radius * radius;
    for (std::size_t p = 0; p < cloth.particle_count(); ++p) {
        if (cloth.is_pinned(p)) continue;
        const Vec3 offset = cloth.positions[p] - hit.point;
        const double distance_squared = glm::dot(offset, offset);
        double weight = 0.0;
        if (distance_squared < radius_squared) {
            const double falloff = 1.0 - distance_squared / radius_squared;
            weight = falloff * falloff;
        }
        if (p == hit.particle) weight = std::max(weight, 1.0);
        if (weight <= 0.0) continue;
        drag.particles.push_back(static_cast<std::uint32_t>(p));
        drag.weights.push_back(weight);
        drag.offsets.push_back(offset);
    }
    return drag;
}

void accumulate_drag_forces(const DragHandle& drag, const Cloth& cloth,
                            std::span<const Vec3> positions, std::span<const Vec3> velocities,
                            std::span<Vec3> forces) {
    const double omega = drag.angular_frequency;
    for (std::size_t k = 0; k < drag.particles.size(); ++k) {
        const std::uint32_t p = drag.particles[k];
        const Vec3 goal = drag.target + drag.offsets[k];
        Vec3 acceleration = omega * omega * (goal - positions[p]) - omega * velocities[p];
        const double magnitude = glm::length(acceleration);
        if (magnitude > drag.max_acceleration) acceleration *= drag.max_acceleration / magnitude;
        forces[p] += (drag.weights[k] * cloth.topology().masses[p]) * acceleration;
    }
}

}  // namespace weft
