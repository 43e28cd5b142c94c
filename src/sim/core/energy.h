// Mechanical energy of the cloth, the quantity the conservation tests watch.
#pragma once

#include "parallel/worker_pool.h"
#include "sim/core/cloth.h"
#include "sim/core/force_pass.h"

namespace weft {

struct Energy {
    double kinetic = 0.0;        // J, Σ ½ m |v|²
    double gravitational = 0.0;  // J, Σ -m g · x (zero at the origin)
    double elastic = 0.0;        // J, Σ ½ k (|d| - L)² over all springs
    double total() const { return kinetic + gravitational + elastic; }
};

// Pinned particles contribute nothing: they never move, so their terms are constant. With a
// pool, split between its threads; the same bits for any thread count (chunked_reduce.h).
Energy measure_energy(const Cloth& cloth, const ForceField& field, WorkerPool* pool = nullptr);

// The energy and the largest stretch ratio |d| / L over all springs (largest_stretch_ratio in
// divergence.h, the same number), from one pass over the springs instead of two: the
// window shows both every frame, and at 256² each pass reads 390 000 springs.
struct EnergyAndStretch {
    Energy energy;
    double largest_stretch_ratio = 0.0;  // NaN when not finite or when there is no spring
    // The spring stretched that much (the first such, in group and spring order): where a
    // reader of the ratio looks. Meaningless when the ratio is NaN.
    Spring most_stretched{0, 0, 0.0};
};
EnergyAndStretch measure_energy_and_stretch(const Cloth& cloth, const ForceField& field,
                                            WorkerPool* pool = nullptr);

}  // namespace weft
