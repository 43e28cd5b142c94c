// Mechanical energy of the cloth, the quantity the conservation tests watch.
#pragma once

#include "parallel/worker_pool.h"
#include "sim/cloth.h"
#include "sim/force_pass.h"

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

}  // namespace weft
