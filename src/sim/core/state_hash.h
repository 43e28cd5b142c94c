// A hash of the cloth's state — every bit of every position and velocity, and the springs
// left — so a run can be checked for determinism (repeated runs, thread counts) by
// comparing one number, as Box2D's and Jolt's determinism tests do.
#pragma once

#include <cstdint>

#include "sim/core/cloth.h"

namespace weft {

// FNV-1a over the bytes of positions, velocities and the live springs' particle indices.
std::uint64_t hash_state(const Cloth& cloth);

}  // namespace weft
