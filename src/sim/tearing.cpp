#include "sim/tearing.h"

#include <algorithm>
#include <glm/geometric.hpp>

namespace weft {

std::size_t tear_overstretched_springs(Cloth& cloth, double max_stretch) {
    std::size_t removed = 0;
    const Vec3* x = cloth.positions.data();
    for (SpringGroup& group : cloth.spring_groups) {
        removed += std::erase_if(group.springs, [&](const Spring& spring) {
            // Compare squared lengths: no square root for the common, intact case.
            const Vec3 d = x[spring.j] - x[spring.i];
            const double limit = max_stretch * spring.rest_length;
            return glm::dot(d, d) > limit * limit;
        });
    }
    return removed;
}

}  // namespace weft
