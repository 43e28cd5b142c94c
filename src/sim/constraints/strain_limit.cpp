#include "sim/constraints/strain_limit.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace weft {

std::size_t limit_strain(Cloth& cloth, double max_stretch, double dt, int max_passes) {
    std::size_t corrections = 0;
    Vec3* x = cloth.positions.data();
    Vec3* v = cloth.velocities.data();
    const double* inverse_mass = cloth.topology().inverse_masses.data();
    const double inverse_dt = 1.0 / dt;
    for (int pass = 0; pass < max_passes; ++pass) {
        std::size_t corrected_this_pass = 0;
        for (const SpringGroup& group : cloth.topology().spring_groups) {
            for (const Spring& spring : group.springs) {
                const Vec3 d = x[spring.j] - x[spring.i];
                const double length = std::sqrt(glm::dot(d, d));
                const double limit = (1.0 + max_stretch) * spring.rest_length;
                if (length <= limit) continue;
                const bool i_free = inverse_mass[spring.i] > 0.0,
                           j_free = inverse_mass[spring.j] > 0.0;
                if (!i_free && !j_free) continue;
                // Share of the excess each end takes: half each, or all to the free end.
                const double share_i = i_free ? (j_free ? 0.5 : 1.0) : 0.0;
                const double share_j = j_free ? (i_free ? 0.5 : 1.0) : 0.0;
                const Vec3 excess = (length - limit) / length * d;  // along i -> j
                x[spring.i] += share_i * excess;
                x[spring.j] -= share_j * excess;
                v[spring.i] += (share_i * inverse_dt) * excess;
                v[spring.j] -= (share_j * inverse_dt) * excess;
                ++corrected_this_pass;
            }
        }
        corrections += corrected_this_pass;
        if (corrected_this_pass == 0) break;
    }
    return corrections;
}

}  // namespace weft
