// SimulationOptions: how a Simulation computes its steps, chosen per Simulation as Box2D's
// b2WorldDef is chosen per world. Every choice is a sound step of the same method: the tests
// and benchmarks compare them, and a run never changes them behind another's back.
#pragma once

#include "sim/grid/kernel_build.h"

namespace weft {

struct SimulationOptions {
    // The build of the vectorised row kernels; every build gives the same bits.
    SimdLevel kernel_build = supported_simd_level();
    // Symplectic Euler on a plain grid steps inside the structured force pass, so the forces
    // never make a round trip through memory (grid_force_pass.h); the same bits as the force
    // pass followed by the update loop.
    bool fused_grid_steps = true;
    // With this, the fused step above computes its spring forces in float, the state and the
    // update staying in double (grid_force_pass.h): eight springs a vector instead of four,
    // with an error far below the method's own (tested). Off by default, so a scene's run is
    // the double step's bits.
    bool single_precision_springs = false;
    // Implicit Euler on a plain grid takes the structured single-precision solve
    // (implicit_grid_solve.h); off, the general double-precision path, the reference for the
    // method's exact discrete behaviour.
    bool structured_implicit_solve = true;

    bool operator==(const SimulationOptions&) const = default;
};

}  // namespace weft
