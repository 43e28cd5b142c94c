// The floor: the ground drawn under the cloth is a plane collider with friction, so a cloth
// or a piece cut off lands on it and rests instead of falling for ever. A scene with a ground
// plane of its own (a plane facing up among its colliders) keeps that one; a scene may say it
// has no floor ([floor] enabled = false).
#pragma once

#include <span>

#include "sim/collision/colliders.h"
#include "sim/core/cloth.h"

namespace weft {

// Friction coefficient of the floor: cotton on a wooden floor.
inline constexpr double floor_friction = 0.5;

// Whether `collider` is a ground plane: a plane whose normal points up.
bool is_ground_plane(const Collider& collider);

// m: where the floor goes for a cloth as it starts among `colliders`. A ground plane's
// height if there is one; else a tenth of a metre below the lowest of: the origin, where the
// cloth starts, what it can reach hanging from its pins (a cloth edge's length below the
// lowest pin), and no higher than the bottom of any sphere, so a ball stands on it.
double floor_height(const Cloth& cloth, std::span<const Collider> colliders);

// The floor at `height` (m): an impulse plane facing up, no bounce, floor_friction.
Collider floor_collider(double height);

}  // namespace weft
