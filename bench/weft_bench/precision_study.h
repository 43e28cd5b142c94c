// weft-bench precision: work-precision diagrams. For each integrator a ladder of steps over
// the same stretch of simulated time from the same start; the error of each run against an
// RK4 reference at a far smaller step, beside its cost. Scenes with tearing, colliders or
// self-collision get the invariant study instead (invariant_study.h).
#pragma once

#include <string>
#include <vector>

namespace weft::bench {

struct PrecisionOptions {
    std::vector<std::string> scenes;     // scene files; each gets its own plots
    std::vector<std::string> overrides;  // --set, applied to every scene
    std::string out_dir = ".";
    int repeats = 3;                  // timings: the median of this many runs
    double invariant_duration = 1.0;  // s, run length for scenes measured by invariants
};

int run_precision_study(const PrecisionOptions& options);

}  // namespace weft::bench
