#include "sim/constraints/tearing.h"

#include <glm/geometric.hpp>

#include "sim/build/topology_edits.h"

namespace weft {

std::size_t tear_overstretched_springs(Cloth& cloth, double max_stretch,
                                       std::vector<Spring>* torn) {
    const Vec3* x = cloth.positions.data();
    return remove_springs_if(cloth, [&](const Spring& spring) {
        // Compare squared lengths: no square root for the common, intact case.
        const Vec3 d = x[spring.j] - x[spring.i];
        const double limit = max_stretch * spring.rest_length;
        const bool breaks = glm::dot(d, d) > limit * limit;
        if (breaks && torn) torn->push_back(spring);
        return breaks;
    });
}

}  // namespace weft
