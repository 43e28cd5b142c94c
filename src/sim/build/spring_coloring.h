// Spring colouring: the springs of a group reordered into colours, no two springs of one
// colour sharing a particle (a greedy edge colouring, as Box2D v3 colours its constraints).
// The springs of one colour can then be applied by several threads at once without two
// threads ever adding to the same particle, and each particle still receives its spring
// forces in the same order — colour by colour — whatever the number of threads.
#pragma once

#include <cstddef>

#include "sim/core/cloth.h"

namespace weft {

// Sorts the group's springs by a greedy colour (stable within a colour, so particle order
// and its locality are kept) and fills group.colour_starts. Called when a group is built
// and after springs are removed.
void colour_springs(SpringGroup& group, std::size_t particle_count);

}  // namespace weft
