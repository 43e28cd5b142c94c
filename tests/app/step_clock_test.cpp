// The demo's step clock: simulated time keeps pace with the wall clock, within a budget.
#include <gtest/gtest.h>

#include "app/step_clock.h"

namespace weft::app {
namespace {

TEST(StepClock, SimulatedTimeKeepsPaceWithTheWallClock) {
    StepClock clock;
    long long steps = 0;
    for (int frame = 0; frame < 600; ++frame) {  // 10 s at 60 fps, fast steps
        const StepClock::Plan plan = clock.advance(1.0 / 60.0, 0.001, 1e-6);
        EXPECT_FALSE(plan.behind);
        steps += plan.steps;
    }
    EXPECT_NEAR(static_cast<double>(steps) * 0.001, 10.0, 0.001 + 1e-9);  // within one step
    EXPECT_LT(clock.owed(), 0.001);
}

TEST(StepClock, ASlowMachineFallsBehindInsteadOfSpiralling) {
    StepClock clock(0.02);  // 20 ms of stepping per frame at most
    const StepClock::Plan plan = clock.advance(1.0 / 60.0, 0.001, 0.005);  // 5 ms per step
    EXPECT_EQ(plan.steps, 4);  // not the 16 that real time would need
    EXPECT_TRUE(plan.behind);
    // Owed to the next frames up to max_debt, the rest dropped.
    EXPECT_LE(clock.owed(), StepClock::max_debt + 0.001);
    for (int frame = 0; frame < 100; ++frame) clock.advance(1.0 / 60.0, 0.001, 0.005);
    EXPECT_LE(clock.owed(), StepClock::max_debt + 0.001);  // never more, however long
}

TEST(StepClock, AShortfallIsCaughtUpByFramesWithBudgetToSpare) {
    // 1 ms steps at 0.5 ms each: real time needs a quarter of the 25 ms budget. One frame
    // 60 ms late (a busy host) owes 60 steps more than the budget buys; the frames after it
    // pay them back, and over the second simulated time matches the wall clock.
    StepClock clock;
    long long steps = 0;
    double wall = 0.0;
    for (int frame = 0; frame < 60; ++frame) {
        const double elapsed = frame == 10 ? 0.08 : 1.0 / 60.0;
        const StepClock::Plan plan = clock.advance(elapsed, 0.001, 0.0005);
        EXPECT_EQ(plan.behind, frame == 10) << frame;
        steps += plan.steps;
        wall += elapsed;
    }
    EXPECT_NEAR(static_cast<double>(steps) * 0.001, wall, 0.001 + 1e-9);
}

TEST(StepClock, ALongStallIsNotCaughtUp) {
    StepClock clock;
    const StepClock::Plan plan = clock.advance(10.0, 0.001, 1e-6);  // a 10 s pause
    EXPECT_EQ(plan.steps, 250);                                     // a quarter second at most
}

TEST(StepClock, AnUnknownStepCostBuysOneStepToMeasureIt) {
    // The window's first frame, or the first after the cloth was rebuilt larger: a quarter
    // second is owed, but at an unmeasured cost it might be seconds of stepping.
    StepClock clock;
    const StepClock::Plan plan = clock.advance(0.25, 0.001, 0.0);
    EXPECT_EQ(plan.steps, 1);
    EXPECT_TRUE(plan.behind);
    EXPECT_LE(clock.owed(), StepClock::max_debt + 0.001);
}

TEST(StepClock, SteppingMayFillAFrameDownToThirtyFramesASecond) {
    // A 256² implicit sheet: 1/60 s steps of 13 ms, 6 ms of drawing and panel a frame. The
    // fixed 25 ms budget buys one step a frame, half of real time at any frame rate; two
    // steps and the drawing fit in a 30 fps frame (32 ms), so the clock takes them.
    const double dt = 1.0 / 60.0, step = 0.013, other = 0.006;
    StepClock fixed;
    long long fixed_steps = 0;
    for (int frame = 0; frame < 300; ++frame)
        fixed_steps += fixed.advance(step + other, dt, step).steps;  // other unknown
    EXPECT_EQ(fixed_steps, 300);  // one a frame: 5 s simulated in 5.7 s

    StepClock clock;
    EXPECT_NEAR(clock.budget(other), StepClock::floor_period - other, 1e-12);
    long long steps = 0;
    double wall = 0.0;
    for (int frame = 0; frame < 300; ++frame) {
        const double elapsed = 2 * step + other;  // as long as two steps and the rest take
        const StepClock::Plan plan = clock.advance(elapsed, dt, step, other);
        EXPECT_LE(plan.steps, 2) << frame;
        steps += plan.steps;
        wall += elapsed;
    }
    EXPECT_NEAR(static_cast<double>(steps) * dt, wall, dt + 1e-9);  // real time, within a step

    // A frame whose other work leaves less than the fixed budget keeps the fixed budget, so
    // a slow machine is never cut below it.
    EXPECT_DOUBLE_EQ(clock.budget(0.03), 1.0 / 40.0);
    EXPECT_DOUBLE_EQ(clock.budget(0.0), 1.0 / 40.0);
}

}  // namespace
}  // namespace weft::app
