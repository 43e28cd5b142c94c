// The demo's recovery from the guards that watch for what does not diverge: energy gained from
// nowhere on contact, and tearing that runs away. Each rolls back, halves dt and runs on, as
// from a divergence (demo_state_test.cpp, "recovery that heals").
//
// Truths: the runs are unstable at the dt they start with and stable at a quarter of it
// (docs/accuracy.md); the message names the guard that fired; the run goes on finite, its
// simulated time advancing with every frame.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "../sim/test_scenes.h"
#include "app/demo_state.h"
#include "shipped_demo.h"
#include "sim/guards/divergence.h"

namespace weft::app {
namespace {

// Steps `state` until its first rollback; returns the message it gave then.
std::string step_until_rolled_back(DemoState& state) {
    for (int frame = 0; frame < 200 && state.main_run().recovery.recoveries == 0; ++frame)
        state.step(16);
    EXPECT_EQ(state.main_run().recovery.recoveries, 1);
    return state.message;
}

// After a rollback: the run goes on for `seconds` more of simulated time, finite, within a
// bounded number of frames (no freeze), every frame without a rollback advancing the time,
// and with at most a few rollbacks more while dt finds what holds.
void runs_on_after_recovery(DemoState& state, double seconds) {
    const double until = state.simulation().time() + seconds;
    // 16 steps a frame at a sixteenth of the chosen dt (four halvings) cover the chosen dt
    // a frame; four times as many frames leave room for the rollbacks.
    const int most_frames = static_cast<int>(4.0 * seconds / state.main_run().restart_dt);
    int frames = 0;
    while (state.simulation().time() < until) {
        ASSERT_LT(++frames, most_frames) << "the run stalls at t = " << state.simulation().time();
        const double before = state.simulation().time();
        const int recoveries = state.main_run().recovery.recoveries;
        state.step(16);
        if (state.main_run().recovery.recoveries == recoveries) {
            ASSERT_GT(state.simulation().time(), before) << state.message;
        }
        ASSERT_FALSE(find_divergence(state.simulation().cloth(), false)) << "not finite";
    }
    EXPECT_LE(state.main_run().recovery.recoveries, 6);
}

TEST(DemoState, AnEnergyAlarmRollsBackHalvesDtAndTheRunGoesOn) {
    // Explicit Euler on the sheet on a sphere, in a heavy material at 0.5 ms, gains energy on
    // contact from 0.45 s, with every spring still short of the runaway stretch (the energy
    // guard's case); at 0.25 ms it holds (docs/accuracy.md).
    DemoState state = demo("sheet_on_sphere.toml");
    std::vector<std::string> overrides = weft::testing::heavy_sheet_on_sphere;
    overrides.push_back("solver.integrator=explicit-euler");
    ASSERT_FALSE(state.change(overrides));
    const std::string said = step_until_rolled_back(state);
    EXPECT_NE(said.find("energy grew"), std::string::npos) << said;
    EXPECT_NE(said.find("dt halved"), std::string::npos) << said;
    EXPECT_NE(said.find("rolled back to"), std::string::npos) << said;
    EXPECT_EQ(state.simulation().dt(), 0.00025);
    runs_on_after_recovery(state, 1.5);
}

TEST(DemoState, ARunawayTearRollsBackHalvesDtAndTheRunGoesOn) {
    // Explicit Euler at 2 ms on the tearing sheet shreds it from 0.056 s (docs/accuracy.md);
    // at 1 ms it does so from 0.21 s, and at 0.5 ms it holds.
    DemoState state = demo("tearing_sheet.toml");
    ASSERT_FALSE(state.change({"solver.integrator=explicit-euler", "solver.dt=0.002"}));
    const std::string said = step_until_rolled_back(state);
    EXPECT_NE(said.find("tearing ran away"), std::string::npos) << said;
    EXPECT_NE(said.find("dt halved"), std::string::npos) << said;
    EXPECT_EQ(state.simulation().dt(), 0.001);
    // The rollback went back to before the shredding: the sheet is whole again.
    EXPECT_EQ(state.simulation().cloth().spring_count(),
              Simulation(state.scene).cloth().spring_count());
    runs_on_after_recovery(state, 1.5);
}

}  // namespace
}  // namespace weft::app
