// Strain limiting (Provot 1995, "Deformation constraints in a mass-spring model to describe
// rigid cloth behavior"): soft springs at a step the explicit methods can afford stretch far
// more than fabric does ("super-elastic" cloth). After each step, a spring longer than
// (1 + max_stretch) × rest is shortened to that length: the correction is split between its
// ends, or given wholly to the free end when the other is pinned. The velocities take the
// same correction divided by dt, so the state stays consistent for the next step.
#pragma once

#include <cstddef>

#include "sim/core/cloth.h"

namespace weft {

// Gauss–Seidel passes over all springs until none is over the limit (a pass can stretch a
// neighbour again) or `max_passes` is reached. Returns the number of corrections made.
std::size_t limit_strain(Cloth& cloth, double max_stretch, double dt, int max_passes = 16);

}  // namespace weft
