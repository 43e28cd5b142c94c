// weft-bench stability: the largest stable step of each integrator, measured by bisection,
// against the sheet's size, its particle mass and its stiffness, beside the linear-stability
// prediction from ω_max of the assembled stiffness matrix.
#pragma once

#include <string>
#include <vector>

namespace weft::bench {

struct StabilityOptions {
    std::string scene;  // the base sheet
    std::vector<std::string> overrides;
    std::vector<std::string> sweeps;  // "grid", "mass", "stiffness"
    std::string out_dir = ".";
    double duration = 0.5;  // s of simulated time a step must survive
};

int run_stability_study(const StabilityOptions& options);

}  // namespace weft::bench
