#include "sim/divergence.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <sstream>

namespace weft {
namespace {

bool is_finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::string particle_name(const Cloth& cloth, std::size_t p) {
    std::ostringstream out;
    out << "particle (row " << p / cloth.cols << ", col " << p % cloth.cols << ")";
    return out.str();
}

}  // namespace

std::optional<std::string> find_divergence(const Cloth& cloth, bool check_runaway_stretch) {
    for (std::size_t p = 0; p < cloth.particle_count(); ++p) {
        if (!is_finite(cloth.positions[p]))
            return particle_name(cloth, p) + " has a non-finite position";
        if (!is_finite(cloth.velocities[p]))
            return particle_name(cloth, p) + " has a non-finite velocity";
    }
    if (!check_runaway_stretch) return std::nullopt;
    for (const SpringGroup& group : cloth.spring_groups) {
        for (const Spring& spring : group.springs) {
            const double length =
                glm::length(cloth.positions[spring.j] - cloth.positions[spring.i]);
            if (length > runaway_stretch_ratio * spring.rest_length) {
                std::ostringstream out;
                out << spring_family_name(group.family) << " spring between "
                    << particle_name(cloth, spring.i) << " and " << particle_name(cloth, spring.j)
                    << " stretched to " << length / spring.rest_length << "x its rest length";
                return out.str();
            }
        }
    }
    return std::nullopt;
}

}  // namespace weft
