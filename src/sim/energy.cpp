#include "sim/energy.h"

#include <glm/geometric.hpp>

#include "sim/chunked_reduce.h"

namespace weft {

Energy measure_energy(const Cloth& cloth, const ForceField& field, WorkerPool* pool) {
    auto add = [](Energy a, const Energy& b) {
        a.kinetic += b.kinetic;
        a.gravitational += b.gravitational;
        a.elastic += b.elastic;
        return a;
    };
    Energy energy = reduce_in_chunks(
        pool, cloth.particle_count(), Energy{},
        [&](std::size_t begin, std::size_t end) {
            Energy part;
            for (std::size_t p = begin; p < end; ++p) {
                if (cloth.is_pinned(p)) continue;
                const double mass = cloth.masses[p];
                part.kinetic += 0.5 * mass * glm::dot(cloth.velocities[p], cloth.velocities[p]);
                part.gravitational -= mass * glm::dot(field.gravity, cloth.positions[p]);
            }
            return part;
        },
        add);
    for (const SpringGroup& group : cloth.spring_groups) {
        energy.elastic += reduce_in_chunks(
            pool, group.springs.size(), 0.0,
            [&](std::size_t begin, std::size_t end) {
                double elastic = 0.0;
                for (std::size_t k = begin; k < end; ++k) {
                    const Spring& spring = group.springs[k];
                    const double extension =
                        glm::length(cloth.positions[spring.j] - cloth.positions[spring.i]) -
                        spring.rest_length;
                    elastic += 0.5 * group.stiffness * extension * extension;
                }
                return elastic;
            },
            [](double a, double b) { return a + b; });
    }
    return energy;
}

}  // namespace weft
