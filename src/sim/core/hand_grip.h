// The hand's grip on the cloth (interaction/grab.h): the springs that tie the particles the
// hand holds to the free cloth, and how far the most stretched of them is stretched. The
// simulation judges the grip after a step, implicit Euler within it; both read it here.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <span>

#include "sim/core/cloth.h"

namespace weft {

// A spring from a particle the hand holds to a free one.
struct HandGripSpring {
    std::uint32_t held;   // particle in the hand
    std::uint32_t other;  // particle outside it
    double rest_length;   // m
};

// The grip springs' largest stretch, in rest lengths (at least 1), with the held end at
// held(p) and the other at other(p).
template <class HeldEnd, class OtherEnd>
double largest_grip_stretch(std::span<const HandGripSpring> springs, HeldEnd held, OtherEnd other) {
    double largest_squared = 1.0;
    for (const HandGripSpring& spring : springs) {
        const Vec3 d = other(spring.other) - held(spring.held);
        const double rest_squared = spring.rest_length * spring.rest_length;
        if (!(rest_squared > 0.0)) continue;
        largest_squared = std::max(largest_squared, glm::dot(d, d) / rest_squared);
    }
    return std::sqrt(largest_squared);
}

// The same with both ends where `positions` has them.
inline double largest_grip_stretch(std::span<const HandGripSpring> springs,
                                   std::span<const Vec3> positions) {
    const auto at = [&](std::uint32_t p) { return positions[p]; };
    return largest_grip_stretch(springs, at, at);
}

}  // namespace weft
