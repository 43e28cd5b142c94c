// weft-bench invariants: what a work-precision study measures where a trajectory error means
// nothing. A tear or a contact is a discontinuity: two runs a hair apart can tear a different
// spring or touch a sphere one step apart, and from then on their trajectories part for good,
// so an error against an RK4 reference measures chaos, not the integrator. What still means
// something is whether a run keeps the invariants of the physics: its energy budget, how far
// its springs stretch, how far the cloth sinks, how many springs it tears.
//
// For each integrator and each step of the ladder (the scene's dt × 2, 1, ½, ¼, ⅛, 1/16),
// one run of `duration` simulated seconds measures, after every step:
//   energy       total mechanical energy E (kinetic + gravitational + elastic of the live
//                springs); reported as E(T) − E(0) and the largest rise max_t E(t) − E(0);
//   strain       largest over live springs of |d|/L − 1, at the end and over the whole run;
//   sag          drop of the centre of mass (mean height of the particles) from start to end;
//   tearing      springs torn; contacts: resolved in the last step, and per step on average;
// then `repeats` further runs, stepping only, are timed (the first run is their warm-up)
// and the least is reported as CPU seconds per simulated second (the machine is shared: the
// least is the run others disturbed least). A diverged run is a row with diverged = yes and
// no measures, and is named on the plots. RK4 at the finest step is the reference row; each
// run's sag is also given relative to it.
#pragma once

#include <string>
#include <vector>

#include "sim/scene/scene.h"

namespace weft::bench {

struct InvariantOptions {
    std::vector<std::string> scenes;     // scene files; each gets its own plots
    std::vector<std::string> overrides;  // --set, applied to every scene
    std::string out_dir = ".";
    int repeats = 3;        // timings: the least of this many runs after a warm-up
    double duration = 1.0;  // s, simulated time of every run
};

// True for a scene whose trajectories are not smooth in time: tearing, colliders or
// self-collision. weft-bench precision measures invariants instead of errors for these.
bool has_discontinuities(const Scene& scene);

// Writes invariants_SCENE.csv (one row per run, flushed as it goes) and three plots
// (invariants_SCENE_{strain,energy,sag}.png) per scene.
int run_invariant_study(const InvariantOptions& options);

}  // namespace weft::bench
