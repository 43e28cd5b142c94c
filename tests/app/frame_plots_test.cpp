// Pausing and the HUD's plots, through the calls the window makes each frame: plan the
// frame, step, measure. Truths: a paused frame takes no step unless one was asked for, and
// adds no sample to any plot (the energy plot used to scroll while paused); each sample
// is the quantity measured directly on the state the frame ended in.
#include <gtest/gtest.h>

#include "app/demo_state.h"
#include "shipped_demo.h"
#include "sim/core/energy.h"
#include "sim/guards/divergence.h"

namespace weft::app {
namespace {

constexpr double frame_seconds = 1.0 / 60.0;

// One frame as the window runs it; returns the steps it took.
int run_frame(DemoState& state, double sim_seconds = 0.002, double raster_seconds = 0.003) {
    const int steps = state.step(state.plan_frame(frame_seconds, 1e-5).steps);
    state.statistics.sim_seconds = sim_seconds;
    state.statistics.raster_seconds = raster_seconds;
    state.measure_frame(steps);
    return steps;
}

std::size_t samples(const DemoState& state) {
    const FramePlots& plots = state.statistics.plots;
    EXPECT_EQ(plots.energy.samples().size(), plots.stretch_percent.samples().size());
    EXPECT_EQ(plots.energy.samples().size(), plots.frame_milliseconds.samples().size());
    return plots.energy.samples().size();
}

TEST(Pausing, APausedFrameTakesNoStepUntilOneIsAskedFor) {
    DemoState state = demo();
    EXPECT_GT(run_frame(state), 0);
    state.toggle_pause();
    for (int frame = 0; frame < 10; ++frame) EXPECT_EQ(run_frame(state), 0);
    state.step_once();
    EXPECT_EQ(run_frame(state), 1);
    EXPECT_EQ(run_frame(state), 0);  // one step, not one a frame
}

TEST(Pausing, OneStepAskedForWhileRunningIsNotOwedToALaterPause) {
    DemoState state = demo();
    state.step_once();  // N while running: nothing to do
    run_frame(state);
    state.toggle_pause();
    EXPECT_EQ(run_frame(state), 0);
}

TEST(Pausing, ResumingDoesNotRushToCatchUpThePausedTime) {
    DemoState state = demo();
    run_frame(state);
    state.toggle_pause();
    for (int frame = 0; frame < 120; ++frame) run_frame(state);  // two seconds paused
    state.toggle_pause();
    // One frame's worth of steps (and a fifth more for an uneven frame), not two seconds'.
    EXPECT_LE(run_frame(state), static_cast<int>(1.2 / 60.0 / state.simulation().dt()));
}

TEST(FramePlots, EveryPlotHoldsStillWhilePaused) {
    DemoState state = demo();
    run_frame(state);
    ASSERT_EQ(samples(state), 1u);
    state.toggle_pause();
    for (int frame = 0; frame < 50; ++frame) run_frame(state);
    EXPECT_EQ(samples(state), 1u);
    // A single step (N) is one sample of each, of the state after it.
    state.step_once();
    run_frame(state, 0.004, 0.006);
    ASSERT_EQ(samples(state), 2u);
    const FramePlots& plots = state.statistics.plots;
    const Simulation& sim = state.simulation();
    EXPECT_EQ(plots.energy.latest(),
              static_cast<float>(measure_energy(sim.cloth(), sim.force_field()).total()));
    EXPECT_EQ(plots.stretch_percent.latest(),
              static_cast<float>(100.0 * (largest_stretch_ratio(sim.cloth()) - 1.0)));
    EXPECT_FLOAT_EQ(plots.frame_milliseconds.latest(), 10.0f);  // 4 ms stepping + 6 drawing
    // Running: a sample a frame, the last five seconds' worth at 60 frames a second.
    state.toggle_pause();
    for (int frame = 0; frame < 400; ++frame) run_frame(state);
    EXPECT_EQ(samples(state), plot_samples_kept);
}

TEST(FramePlots, TheLargestStretchIsMeasuredEveryFramePausedOrNot) {
    DemoState state = demo();
    state.toggle_pause();
    run_frame(state);
    EXPECT_EQ(state.statistics.stretch_ratio, largest_stretch_ratio(state.simulation().cloth()));
}

TEST(PlotHistory, KeepsTheLastSamplesOldestFirst) {
    PlotHistory history(3);
    for (float sample : {1.0f, 2.0f, 3.0f, 4.0f, 5.0f}) history.add(sample);
    EXPECT_EQ(history.samples(), (std::vector<float>{3.0f, 4.0f, 5.0f}));
    EXPECT_EQ(history.latest(), 5.0f);
}

}  // namespace
}  // namespace weft::app
