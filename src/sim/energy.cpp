#include "sim/energy.h"

#include <glm/geometric.hpp>

namespace weft {

Energy measure_energy(const Cloth& cloth, const ForceField& field) {
    Energy energy;
    for (std::size_t p = 0; p < cloth.particle_count(); ++p) {
        if (cloth.is_pinned(p)) continue;
        const double mass = cloth.masses[p];
        energy.kinetic += 0.5 * mass * glm::dot(cloth.velocities[p], cloth.velocities[p]);
        energy.gravitational -= mass * glm::dot(field.gravity, cloth.positions[p]);
    }
    for (const SpringGroup& group : cloth.spring_groups) {
        for (const Spring& spring : group.springs) {
            const double extension =
                glm::length(cloth.positions[spring.j] - cloth.positions[spring.i]) -
                spring.rest_length;
            energy.elastic += 0.5 * group.stiffness * extension * extension;
        }
    }
    return energy;
}

}  // namespace weft
