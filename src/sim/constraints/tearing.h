// Tearing: a spring stretched past max_stretch × its rest length breaks.
#pragma once

#include <cstddef>
#include <vector>

#include "sim/core/cloth.h"

namespace weft {

// Removes every spring whose length exceeds max_stretch × rest length. All springs are
// judged against the same state and removed together, so the result does not depend on
// the order in which springs are visited. Order of the survivors is kept (locality, and
// results that do not depend on which springs broke first). Triangles that lost an edge go
// with them. Returns the number removed; when `torn` is given, the removed springs are
// appended to it (for the runaway-tearing guard, which asks where they were).
std::size_t tear_overstretched_springs(Cloth& cloth, double max_stretch,
                                       std::vector<Spring>* torn = nullptr);

}  // namespace weft
