// Recovery from divergence for one run: every step is checked, and a step that diverged is
// rolled back to a recent sound state with dt halved; once the run has been sound long
// enough, dt doubles back toward the chosen one. The window, headless replays and the
// benchmarks' replays step through it, so all three see the same run. It also sums the step
// profile when asked.
#pragma once

#include <optional>
#include <string>

#include "sim/core/simulation.h"
#include "sim/core/step_profile.h"

namespace weft {

// Recovery halves dt down to this; below it the scene restarts instead (a step this small
// would stall the demo without making a hopeless parameter set stable).
inline constexpr double smallest_recovery_dt = 1e-6;  // s

// Restarts in a row (with no half second of sound motion between them) after which the window
// pauses and says what to change: parameters that no step holds would otherwise restart the
// scene for ever.
inline constexpr int restarts_before_pause = 3;

// After a rollback dt doubles back toward the chosen one each time the run has gone this long
// without diverging. Simulated time, not steps or wall time: deterministic in a replay, and
// the same stretch of motion at any dt, long enough for the swing or fling that diverged to
// pass, short enough that three halvings heal within 1.5 s.
inline constexpr double sound_seconds_before_growth = 0.5;  // s, simulated

// Recovery from divergence for one simulation: a recent sound state to roll back to, and how
// long the run has been sound since dt last changed.
struct Recovery {
    std::optional<Simulation> last_good;
    double last_good_time = -1.0;  // s, simulated
    int recoveries = 0;
    // s, simulated: run without divergence since the last rollback, growth or restart.
    double sound_seconds = 0.0;
    // s, simulated: how long dt must hold before it grows. Doubles each time a grown dt
    // diverges before it has held this long, so parameters that cannot hold the chosen dt
    // settle at one that can, retried ever more rarely instead of rolled back every second.
    double growth_wait = sound_seconds_before_growth;
    bool trying_grown_dt = false;  // dt grew and has not yet held for growth_wait
    // Restarts with no sound_seconds_before_growth of sound motion between them.
    int restarts_in_a_row = 0;
    // With profiling on, every step's phases and counters are summed into profile (kept
    // through rollbacks and restarts: it is the run's, not the state's).
    bool profiling = false;
    StepProfile profile;

    void forget() {
        last_good.reset();
        last_good_time = -1.0;
        restarts_in_a_row = 0;
        restart_growth();
    }
    // Whether the last restarts came one after another often enough that only other
    // parameters can help.
    bool hopeless() const { return restarts_in_a_row >= restarts_before_pause; }
    // dt is where it was chosen, or the cloth is new: no history of what held applies.
    void restart_growth() {
        sound_seconds = 0.0;
        growth_wait = sound_seconds_before_growth;
        trying_grown_dt = false;
    }
    // One step. On divergence: rolls back to the last sound state keeping the parameters as
    // they are now, halves dt, lets go of any drag, and returns false with `message` saying
    // what happened; if halving would go below smallest_recovery_dt it restarts the scene at
    // `chosen_dt` instead. After growth_wait of sound steps below `chosen_dt`, doubles dt (at
    // most to `chosen_dt`) and returns true with `message` saying so; otherwise `message` is
    // left as it was.
    bool step(Simulation& simulation, double chosen_dt, std::string& message);
};

}  // namespace weft
