// The divergence and energy guards: blown-up states are caught with a reason, sound ones
// are not.
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "sim/build/cloth_builder.h"
#include "sim/core/simulation.h"
#include "sim/grid/grid_force_pass.h"
#include "sim/guards/divergence.h"
#include "sim/scene_io/scene_loader.h"
#include "test_scenes.h"

namespace weft {
namespace {

Scene stiff_undamped_sheet(Integrator integrator, double dt) {
    Scene scene;
    scene.cloth.rows = 16;
    scene.cloth.cols = 16;
    scene.structural = {true, 20000.0, 0.0};
    scene.shear = {true, 10000.0, 0.0};
    scene.solver = {integrator, dt};
    return scene;
}

TEST(DivergenceGuard, AOneColumnSheetWithBendSpringsIsJudgedLikeAnyOther) {
    // One column: the row directions (0, 1) and (0, 2) have no spring at all. The structured
    // stretch test once took cols - 2 < 0 as its column range and read past the sheet.
    Scene scene = testing::hanging_chain(6, 0.01, 50.0, 0.2, 0.05);
    scene.shear.enabled = true;
    scene.bend.enabled = true;
    Simulation simulation(scene);
    ASSERT_FALSE(simulation.step().diverged());
    EXPECT_EQ(
        grid_springs_maybe_longer_than(simulation.cloth(), 2.0, nullptr, supported_simd_level()),
        false);
    Cloth& chain = simulation.edit_cloth();
    for (std::size_t p = 0; p < chain.particle_count(); ++p) chain.positions[p].y *= 7.0;
    EXPECT_EQ(
        grid_springs_maybe_longer_than(simulation.cloth(), 2.0, nullptr, supported_simd_level()),
        true);
    EXPECT_TRUE(find_divergence(simulation.cloth(), true, nullptr).has_value());
}

TEST(DivergenceGuard, CatchesExplicitEulerOnAStiffUndampedSheet) {
    Simulation simulation(stiff_undamped_sheet(Integrator::explicit_euler, 5e-4));
    std::optional<std::string> reason;
    for (int s = 0; s < 1000 && !reason; ++s) reason = simulation.step().divergence;
    ASSERT_TRUE(reason.has_value());
    EXPECT_NE(reason->find("particle (row "), std::string::npos) << *reason;
}

TEST(DivergenceGuard, StaysQuietWhileAStableRunSettles) {
    // Same sheet, symplectic Euler, inside its stability limit (h ω_max < 2).
    Simulation simulation(stiff_undamped_sheet(Integrator::symplectic_euler, 2e-4));
    EXPECT_TRUE(testing::run_steps(simulation, 2000));
}

TEST(DivergenceGuard, ReportsNonFiniteValuesAndRunawayStretch) {
    Scene scene;
    scene.cloth.rows = 3;
    scene.cloth.cols = 3;
    Cloth cloth = build_grid_cloth(scene);
    EXPECT_FALSE(find_divergence(cloth, true).has_value());

    Cloth with_nan = cloth;
    with_nan.velocities[4].y = std::numeric_limits<double>::quiet_NaN();
    auto reason = find_divergence(with_nan, true);
    ASSERT_TRUE(reason.has_value());
    EXPECT_NE(reason->find("row 1, col 1"), std::string::npos) << *reason;
    EXPECT_NE(reason->find("velocity"), std::string::npos) << *reason;

    Cloth stretched = cloth;
    stretched.positions[8].x += 5.5 * scene.cloth.spacing;  // the (2,1)-(2,2) spring: 6.5x
    reason = find_divergence(stretched, true);
    ASSERT_TRUE(reason.has_value());
    EXPECT_NE(reason->find("rest length"), std::string::npos) << *reason;
    // With tearing on, a long spring is not divergence: it is about to break.
    EXPECT_FALSE(find_divergence(stretched, false).has_value());
    stretched.positions[8].x -= 2.0 * scene.cloth.spacing;  // now 4.5x: still sound
    EXPECT_FALSE(find_divergence(stretched, true).has_value());
}

TEST(DivergenceGuard, TheBoundedGuardGivesTheFullScansVerdictEveryStep) {
    // A stiff sheet blowing up under explicit Euler, and a stable one swinging: after every
    // step the guard that skips the spring scan while its bound holds must say exactly what
    // the full scan says, message included.
    for (auto [integrator, dt] : {std::pair{Integrator::explicit_euler, 5e-4},
                                  std::pair{Integrator::symplectic_euler, 2e-4}}) {
        Simulation simulation(stiff_undamped_sheet(integrator, dt));
        DivergenceGuard guard;
        for (int s = 0; s < 1500; ++s) {
            simulation.step();
            const std::optional<std::string> full = find_divergence(simulation.cloth(), true);
            ASSERT_EQ(guard.check(simulation.cloth(), true), full) << "step " << s;
            if (full) break;
        }
    }
}

TEST(DivergenceGuard, TheBoundedGuardSeesAStretchAfterALongQuietRun) {
    Scene scene;
    scene.cloth.rows = 8;
    scene.cloth.cols = 8;
    Simulation simulation(scene);
    DivergenceGuard guard;
    for (int s = 0; s < 200; ++s) {
        simulation.step();
        ASSERT_FALSE(guard.check(simulation.cloth(), true).has_value());
    }
    Cloth stretched = simulation.cloth();
    stretched.positions[63] += Vec3(0.0, 0.0, 6.0 * scene.cloth.spacing);
    EXPECT_EQ(guard.check(stretched, true), find_divergence(stretched, true));
    EXPECT_TRUE(guard.check(stretched, true).has_value());
    Cloth with_nan = simulation.cloth();
    with_nan.velocities[10].y = std::numeric_limits<double>::quiet_NaN();
    EXPECT_TRUE(guard.check(with_nan, false).has_value());
}

TEST(DivergenceGuard, ARunawayStretchMadeByAContactIsCaughtInTheStepThatMadeIt) {
    // The fused step sweeps for the guard on its way; a contact that moves particles after
    // it must check them itself (sweep_watch.h), or the guard, trusting the step's sweep,
    // misses what the contact did. A ball is moved under a quiet sheet so that it takes
    // in a patch: the patch is thrown onto the ball's surface, whose radius is 10 spacings,
    // and springs across it become many rest lengths long.
    Scene scene;
    scene.cloth.rows = 16;
    scene.cloth.cols = 16;
    scene.solver = {Integrator::symplectic_euler, 2e-4};
    ColliderSpec ball;
    ball.center = {0.0, -100.0, 0.0};
    ball.radius = 10.0 * scene.cloth.spacing;
    scene.colliders = {ball};
    Simulation simulation(scene);
    ASSERT_TRUE(simulation.options().fused_grid_steps);
    ASSERT_TRUE(testing::run_steps(simulation, 50));

    Scene moved = simulation.scene();
    const Vec3 particle = simulation.cloth().positions[8 * 16 + 8];
    const Vec3 inside = particle - Vec3(0.3, 0.2, 0.4) * scene.cloth.spacing;
    moved.colliders[0].center = {inside.x, inside.y, inside.z};
    simulation.set_parameters(moved);
    const StepReport report = simulation.step();
    EXPECT_GT(report.contacts, 0u);
    ASSERT_TRUE(report.divergence.has_value());
    EXPECT_NE(report.divergence->find("rest length"), std::string::npos) << *report.divergence;
}

TEST(EnergyGuard, CatchesExplicitEulerOnTheSheetOnASphereByTheEnergyItGains) {
    // Explicit Euler on sheet_on_sphere.toml in a heavy material (4 kg/m² on 800 N/m springs,
    // dt 0.5 ms) gains energy from 0.45 s (+45 J by 0.5 s, the sheet's energy scale
    // M (|g| L + ½ (1 m/s)²) being 109 J); no spring passes the runaway stretch until 0.655 s.
    // The shipped cotton-like sheet instead stretches past the runaway bound first.
    std::vector<std::string> overrides = testing::heavy_sheet_on_sphere;
    overrides.push_back("solver.integrator=explicit-euler");
    SceneLoadResult loaded = load_scene_file(
        std::string(WEFT_SOURCE_DIR) + "/assets/scenes/sheet_on_sphere.toml", overrides);
    ASSERT_TRUE(loaded.ok()) << loaded.error->message();
    Simulation simulation(*loaded.scene);
    StepReport report;
    while (!report.diverged() && simulation.time() < 1.0) report = simulation.step();
    ASSERT_TRUE(report.diverged());
    EXPECT_NE(report.divergence->find("energy grew"), std::string::npos) << *report.divergence;
    // Simulated time, not the clock: before the stretch check would see it (0.655 s), and
    // not while it fell and landed soundly.
    EXPECT_LT(simulation.time(), 0.6);
    EXPECT_GT(simulation.time(), 0.4);
}

TEST(EnergyGuard, TheWindsWorkIsNotCountedAsAGain) {
    // A free sheet in a strong wind and no gravity: the wind's drag speeds it up from rest,
    // its energy growing by the wind's work alone, which the guard integrates.
    Scene scene;
    scene.cloth.rows = scene.cloth.cols = 8;
    scene.cloth.pin_preset = PinPreset::none;
    scene.forces.gravity = {0.0, 0.0, 0.0};
    scene.forces.air_drag = 0.05;
    scene.forces.wind = {20.0, 0.0, 0.0};
    scene.solver = {Integrator::symplectic_euler, 1e-3};
    Simulation simulation(scene);
    for (int s = 0; s < 2000; ++s) ASSERT_FALSE(simulation.step().diverged()) << "step " << s;
    EXPECT_GT(simulation.cloth().velocities[0].x, 15.0);  // it did pick up the wind's speed
}

}  // namespace
}  // namespace weft
