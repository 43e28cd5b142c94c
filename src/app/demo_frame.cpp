// DemoState's part in each frame of the window: pausing (the P and N keys and the panel's
// buttons), how many steps the frame takes, and what the frame measures for the HUD.
#include "app/demo_state.h"

#include <cmath>

#include "app/status_text.h"
#include "sim/core/energy.h"

namespace weft::app {

void DemoState::measure_frame(int steps) {
    const Cloth& cloth = simulation().cloth();
    // Measured, not coloured: the strain colours cost a 256² sheet's frame 7 % of its time.
    // On the simulation's threads, and both from one pass over the springs: at 256² a pass
    // reads 390 000 of them (the two passes took 4.9 % of the window's time there).
    // Paused, the energy goes unused, but the stretch is still measured (a cut shows at once).
    const EnergyAndStretch measures =
        measure_energy_and_stretch(cloth, simulation().force_field(), simulation().pool());
    const double energy = steps > 0 ? measures.energy.total() : 0.0;
    statistics.stretch_ratio = measures.largest_stretch_ratio;
    statistics.stretch_place = std::isfinite(measures.largest_stretch_ratio)
                                   ? stretch_place_text(cloth, measures.most_stretched)
                                   : std::string();
    statistics.plots.add_frame(steps, energy, statistics.stretch_ratio,
                               statistics.sim_seconds + statistics.raster_seconds);
    if (main_run().recovery.profiling && wall_now - statistics.profile_mark_wall >= 1.0) {
        statistics.recent_profile = main_run().recovery.profile.since(statistics.profile_mark);
        statistics.profile_mark = main_run().recovery.profile;
        statistics.profile_mark_wall = wall_now;
    }
}

void DemoState::toggle_pause() {
    paused = !paused;
    single_step = false;
}

void DemoState::step_once() {
    single_step = paused;
}

StepClock::Plan DemoState::plan_frame(double elapsed, double seconds_per_step,
                                      double other_seconds) {
    if (!paused) return clock.advance(elapsed, simulation().dt(), seconds_per_step, other_seconds);
    clock.reset();
    const StepClock::Plan plan{single_step ? 1 : 0, false};
    single_step = false;
    return plan;
}

}  // namespace weft::app
