#include "sim/core/energy.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

#include "sim/core/chunked_reduce.h"

namespace weft {

EnergyAndStretch measure_energy_and_stretch(const Cloth& cloth, const ForceField& field,
                                            WorkerPool* pool) {
    auto add = [](Energy a, const Energy& b) {
        a.kinetic += b.kinetic;
        a.gravitational += b.gravitational;
        a.elastic += b.elastic;
        return a;
    };
    EnergyAndStretch measures;
    Energy& energy = measures.energy;
    energy = reduce_in_chunks(
        pool, cloth.particle_count(), Energy{},
        [&](std::size_t begin, std::size_t end) {
            Energy part;
            for (std::size_t p = begin; p < end; ++p) {
                if (cloth.is_pinned(p)) continue;
                const double mass = cloth.topology().masses[p];
                part.kinetic += 0.5 * mass * glm::dot(cloth.velocities[p], cloth.velocities[p]);
                part.gravitational -= mass * glm::dot(field.gravity, cloth.positions[p]);
            }
            return part;
        },
        add);
    // Per chunk: the elastic energy, summed, and the largest ratio, a maximum (exact in any
    // order); the sums are the same as without it.
    struct SpringPart {
        double elastic = 0.0;
        double largest = -std::numeric_limits<double>::infinity();
        const Spring* spring = nullptr;  // the first one as stretched as `largest`
    };
    double largest = -std::numeric_limits<double>::infinity();
    const Spring* most_stretched = nullptr;
    for (const SpringGroup& group : cloth.topology().spring_groups) {
        const SpringPart group_part = reduce_in_chunks(
            pool, group.springs.size(), SpringPart{},
            [&](std::size_t begin, std::size_t end) {
                SpringPart part;
                for (std::size_t k = begin; k < end; ++k) {
                    const Spring& spring = group.springs[k];
                    const double length =
                        glm::length(cloth.positions[spring.j] - cloth.positions[spring.i]);
                    const double extension = length - spring.rest_length;
                    part.elastic += 0.5 * group.stiffness * extension * extension;
                    const double ratio = length / spring.rest_length;
                    if (ratio > part.largest) {  // as std::max: a NaN ratio never wins
                        part.largest = ratio;
                        part.spring = &spring;
                    }
                }
                return part;
            },
            [](SpringPart a, const SpringPart& b) {
                a.elastic += b.elastic;
                if (b.largest > a.largest) {  // a's chunk comes first: ties keep it
                    a.largest = b.largest;
                    a.spring = b.spring;
                }
                return a;
            });
        energy.elastic += group_part.elastic;
        if (group_part.largest > largest) {
            largest = group_part.largest;
            most_stretched = group_part.spring;
        }
    }
    if (most_stretched) measures.most_stretched = *most_stretched;
    measures.largest_stretch_ratio =
        std::isfinite(largest) ? largest : std::numeric_limits<double>::quiet_NaN();
    return measures;
}

Energy measure_energy(const Cloth& cloth, const ForceField& field, WorkerPool* pool) {
    return measure_energy_and_stretch(cloth, field, pool).energy;
}

}  // namespace weft
