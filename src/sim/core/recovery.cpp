#include "sim/core/recovery.h"

#include <algorithm>
#include <cstdio>

#include "sim/interaction/grab.h"

namespace weft {

bool Recovery::step(Simulation& simulation, double chosen_dt, std::string& message) {
    const double step_dt = simulation.dt();
    simulation.set_profiling(profiling);
    const std::uint64_t evaluations_before = simulation.force_evaluations();
    const StepReport report = simulation.step();
    if (profiling)
        profile.add(report.times, report.held, report.hand_slipped,
                    simulation.force_evaluations() - evaluations_before,
                    simulation.last_linear_solve().iterations, simulation.last_step_splits(),
                    simulation.last_step_newton_iterations(),
                    simulation.last_step_tries_stopped_early());
    if (report.hand_slipped) {
        char text[96];
        std::snprintf(text, sizeof text,
                      "the cloth slipped from the hand: a spring at it passed %gx its rest length",
                      Grab::default_grip_stretch);
        message = text;
    }
    if (!report.diverged()) {
        // Keep a sound state from about a quarter second back.
        if (simulation.time() - last_good_time >= 0.25) {
            last_good = simulation;
            last_good_time = simulation.time();
        }
        sound_seconds += step_dt;
        if (sound_seconds >= sound_seconds_before_growth) restarts_in_a_row = 0;
        if (sound_seconds < growth_wait) return true;
        if (trying_grown_dt) {  // the grown dt held as long as it took to earn it
            trying_grown_dt = false;
            growth_wait = sound_seconds_before_growth;
        }
        if (step_dt >= chosen_dt) return true;
        // Heal: what diverged is often a moment (a fling, a swing through a bad pose) that the
        // chosen dt holds again once it has passed; if not, growth_wait spaces the retries.
        // Doubling undoes one halving exactly (powers of two are exact in floating point), so
        // the run lands on the chosen dt bit for bit.
        const double grown_dt = std::min(2.0 * step_dt, chosen_dt);
        simulation.set_dt(grown_dt);
        trying_grown_dt = true;
        char text[256];
        std::snprintf(text, sizeof text, "sound for %.2g s at t=%.3f s: dt %s %.3g ms",
                      sound_seconds, simulation.time(),
                      grown_dt == chosen_dt ? "restored to" : "grown to", grown_dt * 1e3);
        sound_seconds = 0.0;
        message = text;
        return true;
    }
    // Roll back the motion, not the user's choices: the parameters stay as they are now, only
    // dt is halved. A drag in progress is let go (it may be what blew up).
    const Scene wanted = simulation.scene();
    const double diverged_at = simulation.time();
    const double halved_dt = 0.5 * step_dt;
    // A grown dt that diverged before it held as long as it took to earn it: the chosen dt
    // may be past what these parameters hold, so the next try waits twice as long.
    if (trying_grown_dt) growth_wait *= 2.0;
    trying_grown_dt = false;
    sound_seconds = 0.0;
    char text[512];
    if (halved_dt < smallest_recovery_dt) {
        simulation.reset();
        simulation.set_dt(chosen_dt);
        const int restarts = restarts_in_a_row + 1;
        forget();
        restarts_in_a_row = restarts;
        std::snprintf(text, sizeof text,
                      "diverged at t=%.3f s: %s; no step above %.0e s holds these parameters, "
                      "so the scene restarted at dt %.3g ms",
                      diverged_at, report.divergence->c_str(), smallest_recovery_dt,
                      chosen_dt * 1e3);
    } else {
        if (last_good) {
            simulation = *last_good;
            simulation.set_parameters(wanted);
        } else {
            simulation.reset();
        }
        simulation.set_dt(halved_dt);
        std::snprintf(text, sizeof text,
                      "diverged at t=%.3f s: %s; rolled back to t=%.3f s, dt halved to %.3g ms",
                      diverged_at, report.divergence->c_str(), simulation.time(), halved_dt * 1e3);
    }
    simulation.let_go();
    ++recoveries;
    message = text;
    return false;
}

}  // namespace weft
