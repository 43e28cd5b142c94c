#include "sim/core/state_hash.h"

#include <cstring>

namespace weft {
namespace {

struct Fnv1a {
    std::uint64_t value = 1469598103934665603ull;
    void add(const void* data, std::size_t size) {
        const auto* bytes = static_cast<const unsigned char*>(data);
        for (std::size_t k = 0; k < size; ++k) {
            value ^= bytes[k];
            value *= 1099511628211ull;
        }
    }
};

}  // namespace

std::uint64_t hash_state(const Cloth& cloth) {
    Fnv1a hash;
    hash.add(cloth.positions.data(), cloth.positions.size() * sizeof(Vec3));
    hash.add(cloth.velocities.data(), cloth.velocities.size() * sizeof(Vec3));
    for (const SpringGroup& group : cloth.topology().spring_groups)
        for (const Spring& spring : group.springs) {
            hash.add(&spring.i, sizeof spring.i);
            hash.add(&spring.j, sizeof spring.j);
        }
    return hash.value;
}

}  // namespace weft
