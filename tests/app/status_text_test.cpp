// The wording of the demo's and the command line's status lines. Truths: English number
// agreement, and printf's own "%.1e" rounding to two significant digits written out by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "app/status_text.h"
#include "sim/core/energy.h"
#include "sim/core/simulation.h"
#include "sim/scene/scene.h"

namespace weft::app {
namespace {

TEST(StatusText, CountsTakeTheSingularOnlyForExactlyOne) {
    EXPECT_EQ(counted(1, "time", "times"), "1 time");
    EXPECT_EQ(counted(0, "time", "times"), "0 times");
    EXPECT_EQ(counted(2, "recovery", "recoveries"), "2 recoveries");
    EXPECT_EQ(counted(1, "recovery", "recoveries"), "1 recovery");
    EXPECT_EQ(counted(11, "event", "events"), "11 events");
}

TEST(StatusText, LinearSolveShowsIterationsAndTheResidualToTwoDigits) {
    EXPECT_EQ(linear_solve_text({23, 4.1e-3}), "solve: 23 iterations, residual 4.1e-03");
    EXPECT_EQ(linear_solve_text({1, 0.0123456}), "solve: 1 iteration, residual 1.2e-02");
    EXPECT_EQ(linear_solve_text({500, 9.96e-9}), "solve: 500 iterations, residual 1.0e-08");
    EXPECT_EQ(linear_solve_text({0, 0.0}), "solve: 0 iterations, residual 0.0e+00");
}

TEST(StatusText, StretchSaysWhatIsStretchedAndOverWhat) {
    EXPECT_EQ(stretch_text(1.376), "most stretched spring: rest + 37.6 %");
    EXPECT_EQ(stretch_text(1.0), "most stretched spring: rest + 0.0 %");
    EXPECT_EQ(stretch_text(0.98), "most stretched spring: rest - 2.0 %");
    EXPECT_EQ(stretch_text(std::nan("")), "most stretched spring: none (no springs)");
}

TEST(StatusText, TheMostStretchedSpringOfAHangingSheetIsSaidToBeBesideAPin) {
    // Hung by its two top corners, a sheet's weight goes through the springs at the pins:
    // at rest they are the most stretched ("37.6 %" puzzled without a place).
    Scene scene;
    scene.cloth.rows = 12;
    scene.cloth.cols = 12;
    scene.shear.enabled = true;
    scene.forces.air_drag = 0.02;
    Simulation simulation(scene);
    for (int s = 0; s < 4000; ++s) simulation.step();
    const Cloth& cloth = simulation.cloth();
    const EnergyAndStretch measures = measure_energy_and_stretch(cloth, simulation.force_field());
    const std::string place = stretch_place_text(cloth, measures.most_stretched);
    EXPECT_NE(place.find(", by a pin"), std::string::npos) << place;
    EXPECT_EQ(place.rfind("at (row ", 0), 0u) << place;
    // A spring between two free particles has no pin beside it; its first end is named.
    EXPECT_EQ(stretch_place_text(cloth, Spring{13, 14, 0.05}), "at (row 1, col 1)");
    // Indices the cloth does not have say nothing rather than something wrong.
    EXPECT_EQ(stretch_place_text(cloth, Spring{1000, 1, 0.05}), "");
}

TEST(StatusText, SignsTheWindowsFontLacksAreSpelledInAscii) {
    // The font draws "?" for these (the window said "diverged ... ? rolled back").
    EXPECT_EQ(ascii_text("a \u2014 b"), "a - b");
    EXPECT_EQ(ascii_text("rows \u00d7 cols = 5\u00b7m/s\u00b2"), "rows x cols = 5.m/s2");
    EXPECT_EQ(ascii_text("\u0394v at 45\u00b0\u2026"), "dv at 45 deg...");
    EXPECT_EQ(ascii_text("plain ASCII stays as it is: ~!@#"), "plain ASCII stays as it is: ~!@#");
    EXPECT_EQ(ascii_text(""), "");
    // A character outside the list is kept: the font's own fallback is no worse than a guess.
    EXPECT_EQ(ascii_text("caf\u00e9"), "caf\u00e9");
}

Scene small_sheet(Integrator integrator) {
    Scene scene;
    scene.cloth.rows = 4;
    scene.cloth.cols = 4;
    scene.solver = {integrator, 0.001};
    return scene;
}

TEST(StatusText, OnlyImplicitEulerHasALinearSolveToShow) {
    Simulation explicit_run(small_sheet(Integrator::symplectic_euler));
    explicit_run.step();
    EXPECT_FALSE(linear_solve_text(explicit_run).has_value());

    Simulation implicit_run(small_sheet(Integrator::implicit_euler));
    EXPECT_EQ(linear_solve_text(implicit_run), "solve: none yet");
    implicit_run.step();
    // Gravity pulls a sheet released at rest, so the first step has a system to solve.
    const Simulation::LinearSolve solve = implicit_run.last_linear_solve();
    EXPECT_GE(solve.iterations, 1);
    EXPECT_EQ(linear_solve_text(implicit_run), linear_solve_text(solve));
}

}  // namespace
}  // namespace weft::app
