// The text of `weft --headless --profile`: a run's StepProfile as a small table of phases
// (total, per step, share) and the solver's counters.
#pragma once

#include <string>

#include "sim/core/step_profile.h"

namespace weft::app {

// `dt`: the run's step (s), `threads`: the step's worker threads.
std::string profile_text(const StepProfile& profile, double dt, int threads);
// The same, narrow enough for the panel: ms a step and share per phase, and the counters a
// step.
std::string profile_panel_text(const StepProfile& profile);

}  // namespace weft::app
