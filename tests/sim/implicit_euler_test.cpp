// Implicit Euler: its exact discrete energy decay on the oscillator, its linear solve against
// a dense system built from finite differences of the force pass, and its stability far past
// the explicit methods' limit.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <random>
#include <vector>

#include "sim/build/cloth_builder.h"
#include "sim/core/force_pass.h"
#include "sim/core/simulation.h"
#include "sim/guards/divergence.h"
#include "sim/guards/stability_limit.h"
#include "sim/scene_io/scene_loader.h"
#include "test_scenes.h"

namespace weft {
namespace {

TEST(ImplicitEuler, OscillationEnergyDecaysByExactlyOnePlusHOmegaSquaredPerStep) {
    // Backward Euler on a linear oscillator: (v² + ω² z²) shrinks by 1 / (1 + h²ω²) each
    // step. The hanging spring is linear, so the once-linearised step is exact here. The
    // general path solves in double to 1e-8; the structured one in single precision.
    const testing::HangingSpring spring;
    const double dt = 1e-3;
    Simulation simulation(spring.scene(Integrator::implicit_euler, dt),
                          testing::general_implicit_path());
    // The spring swings past 1.3 rest lengths: the step must not be split (implicit_euler.cpp)
    // for the map to be the one step's.
    ImplicitSolveSettings unsplit;
    unsplit.split_stretch_ratio = 0.0;
    simulation.set_implicit_solve_settings(unsplit);
    auto oscillation_energy = [&] {
        const double z = simulation.cloth().positions[1].y - spring.equilibrium();
        const double v = simulation.cloth().velocities[1].y;
        return 0.5 * spring.mass * v * v + 0.5 * spring.stiffness * z * z;
    };
    const double initial = oscillation_energy();
    const double decay = 1.0 / (1.0 + dt * dt * spring.omega0() * spring.omega0());
    ASSERT_TRUE(testing::run_steps(simulation, 2000));
    EXPECT_NEAR(oscillation_energy() / (initial * std::pow(decay, 2000.0)), 1.0, 1e-9);
    EXPECT_LT(oscillation_energy(), 0.5 * initial);  // it really lost energy
}

// Coordinate k % 3 of a particle's vector: dense matrices index coordinates 0..3n-1.
double& component(Vec3& v, std::size_t k) {
    return v[static_cast<int>(k % 3)];
}
double component(const Vec3& v, std::size_t k) {
    return v[static_cast<int>(k % 3)];
}

// Central differences of the force pass: ∂f/∂x and ∂f/∂v as dense matrices (3n × 3n).
std::vector<double> jacobian(const Cloth& cloth, const ForceField& field, bool by_velocity) {
    const std::size_t n = 3 * cloth.particle_count();
    std::vector<double> matrix(n * n);
    std::vector<Vec3> plus(cloth.particle_count()), minus(cloth.particle_count());
    const double epsilon = 1e-6;
    for (std::size_t column = 0; column < n; ++column) {
        std::vector<Vec3> x = cloth.positions, v = cloth.velocities;
        std::vector<Vec3>& varied = by_velocity ? v : x;
        component(varied[column / 3], column) += epsilon;
        accumulate_forces(cloth, field, x, v, plus);
        component(varied[column / 3], column) -= 2 * epsilon;
        accumulate_forces(cloth, field, x, v, minus);
        for (std::size_t row = 0; row < n; ++row)
            matrix[row * n + column] =
                (component(plus[row / 3], row) - component(minus[row / 3], row)) / (2 * epsilon);
    }
    return matrix;
}

// Relative residual of the step just taken against (M - h Jv - h² Jx) Δv = h f(x*, v0), the
// first Newton iterate, linearised at x* = x0 + h v0 (pins stay), with the Jacobians at x*
// from central differences of the force pass, over the free particles.
double baraff_witkin_residual(const Scene& scene, double speed_scale,
                              double stated_tolerance = implicit_cg_tolerance,
                              const SimulationOptions& options = {}) {
    const double dt = scene.solver.dt;
    Simulation simulation(scene, options);
    ImplicitSolveSettings settings;
    settings.fixed_tolerance = stated_tolerance;
    simulation.set_implicit_solve_settings(settings);
    // Stretch every spring (so the clamped transverse term is exact) and stir.
    Cloth& cloth = simulation.edit_cloth();
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> jitter(-0.003, 0.003), speed(-speed_scale, speed_scale);
    for (std::size_t p = 0; p < cloth.particle_count(); ++p) {
        cloth.positions[p] = 1.2 * cloth.positions[p] + Vec3(jitter(rng), jitter(rng), jitter(rng));
        if (!cloth.is_pinned(p)) cloth.velocities[p] = Vec3(speed(rng), speed(rng), speed(rng));
    }
    const Cloth before = simulation.cloth();
    Cloth predicted = before;
    for (std::size_t p = 0; p < predicted.particle_count(); ++p)
        if (!predicted.is_pinned(p)) predicted.positions[p] += dt * predicted.velocities[p];
    const std::vector<double> jx = jacobian(predicted, simulation.force_field(), false);
    const std::vector<double> jv = jacobian(predicted, simulation.force_field(), true);
    std::vector<Vec3> f0(before.particle_count());
    accumulate_forces(predicted, simulation.force_field(), predicted.positions,
                      predicted.velocities, f0);
    EXPECT_FALSE(simulation.step().diverged());
    EXPECT_LE(simulation.last_linear_solve().relative_residual, stated_tolerance);
    EXPECT_GT(simulation.last_linear_solve().iterations, 0);

    const std::size_t n = 3 * before.particle_count();
    double residual_squared = 0.0, rhs_squared = 0.0;
    for (std::size_t row = 0; row < n; ++row) {
        if (before.is_pinned(row / 3)) continue;
        double lhs = before.topology().masses[row / 3] *
                     (component(simulation.cloth().velocities[row / 3], row) -
                      component(before.velocities[row / 3], row));
        double rhs = dt * component(f0[row / 3], row);
        for (std::size_t column = 0; column < n; ++column) {
            const double dv = component(simulation.cloth().velocities[column / 3], column) -
                              component(before.velocities[column / 3], column);
            lhs -= (dt * jv[row * n + column] + dt * dt * jx[row * n + column]) * dv;
        }
        residual_squared += (lhs - rhs) * (lhs - rhs);
        rhs_squared += rhs * rhs;
    }
    return std::sqrt(residual_squared / rhs_squared);
}

Scene small_sheet_for_the_solve(double spring_damping) {
    Scene scene;
    scene.cloth.rows = 4;
    scene.cloth.cols = 4;
    scene.structural = {true, 800.0, spring_damping};
    scene.shear = {true, 400.0, spring_damping};
    scene.bend = {true, 100.0, spring_damping};
    scene.forces.air_drag = 0.05;
    scene.solver = {Integrator::implicit_euler, 0.01};
    return scene;
}

TEST(ImplicitEuler, ItsSolveSatisfiesTheBaraffWitkinSystemToTheStatedTolerance) {
    // The method drops the position derivative of the spring dampers (as Baraff & Witkin
    // do), so the finite-difference truth is exact only where that term vanishes: moving
    // particles with undamped springs (drag only), and damped springs at rest. The solver's
    // tolerance is 1e-8; finite differences add about 1e-8.
    const SimulationOptions general = testing::general_implicit_path();
    EXPECT_LT(
        baraff_witkin_residual(small_sheet_for_the_solve(0.0), 0.5, implicit_cg_tolerance, general),
        1e-6);
    EXPECT_LT(
        baraff_witkin_residual(small_sheet_for_the_solve(0.5), 0.0, implicit_cg_tolerance, general),
        1e-6);
}

TEST(ImplicitEuler, TheStructuredSolveSatisfiesTheBaraffWitkinSystemToItsTolerance) {
    // The same dense truth for the grid path, in single precision: asked for 1e-5, it meets
    // the true (double, finite-difference) system to about that, not to float's 1e-7 alone.
    EXPECT_LT(baraff_witkin_residual(small_sheet_for_the_solve(0.0), 0.5, 1e-5), 3e-5);
    EXPECT_LT(baraff_witkin_residual(small_sheet_for_the_solve(0.5), 0.0, 1e-5), 3e-5);
}

TEST(ImplicitEuler, StaysBoundedFarPastTheExplicitLimitOnAStiffSheet) {
    Scene scene;
    scene.cloth.rows = 16;
    scene.cloth.cols = 16;
    scene.cloth.pin_preset = PinPreset::top_row;
    scene.structural = {true, 20000.0, 0.5};
    scene.shear = {true, 10000.0, 0.5};
    scene.bend = {true, 2000.0, 0.1};
    const double limit = stable_step_limit(Integrator::symplectic_euler,
                                           highest_angular_frequency(build_grid_cloth(scene)));
    for (double multiple : {10.0, 100.0}) {
        scene.solver = {Integrator::symplectic_euler, multiple * limit};
        Simulation explicit_run(scene);
        EXPECT_FALSE(testing::run_steps(explicit_run, 200)) << multiple;  // blows up
        scene.solver.integrator = Integrator::implicit_euler;
        Simulation implicit_run(scene);
        ASSERT_TRUE(testing::run_steps(implicit_run, 200)) << multiple;
        double largest = 0.0;
        for (const SpringGroup& g : implicit_run.cloth().topology().spring_groups)
            for (const Spring& s : g.springs)
                largest = std::max(largest, glm::length(implicit_run.cloth().positions[s.j] -
                                                        implicit_run.cloth().positions[s.i]) /
                                                s.rest_length);
        EXPECT_LT(largest, 1.1) << multiple;  // a stiff sheet hangs nearly unstretched
    }
}

// cloth_128.toml's material at 64² (the same sheet, a quarter of the particles), released flat
// at dt = 1/15 s: in its first linearised step the sheet falls g h² = 4.4 cm, 2.4 spacings,
// everywhere but at the pins, for the springs at rest have no stiffness across themselves.
struct FlatReleaseAtALargeStep {
    Simulation simulation;
    FlatReleaseAtALargeStep(double split_stretch_ratio, int newton_iterations)
        : simulation(*load_scene_file(WEFT_SOURCE_DIR "/assets/scenes/cloth_128.toml",
                                      {"cloth.rows=64", "cloth.cols=64",
                                       "cloth.spacing=0.018254",         // m: 1.15 m / 63
                                       "cloth.particle_mass=0.0000666",  // kg: 0.2 kg/m² × spacing²
                                       "solver.dt=0.0666666666666667"})
                          .scene) {
        ImplicitSolveSettings settings;
        settings.split_stretch_ratio = split_stretch_ratio;
        settings.newton_iterations = newton_iterations;
        simulation.set_implicit_solve_settings(settings);
    }
};

TEST(ImplicitEulerSplit, AStepThatWouldOverstretchASpringIsTakenInHalves) {
    // Taken whole, the first step leaves the springs beside the pins 2.5 rest lengths long
    // and the sheet runs away: the linearisation, not the solve, fails it.
    FlatReleaseAtALargeStep whole(0.0, 0);
    bool diverged = false;
    double whole_largest = 0.0;
    for (int step = 0; step < 23 && !diverged; ++step) {
        diverged = whole.simulation.step().diverged();
        whole_largest = std::max(whole_largest, largest_stretch_ratio(whole.simulation.cloth()));
    }
    EXPECT_TRUE(diverged || whole_largest > 2.0) << whole_largest;

    // Split where the linearisation failed, no step ends with a spring past 1.3 rest lengths
    // (halving three times over is enough here), so the sheet falls, swings and settles.
    FlatReleaseAtALargeStep split(1.3, 0);
    int splits = 0;
    for (int step = 0; step < 23; ++step) {  // 1.5 s
        ASSERT_FALSE(split.simulation.step().diverged()) << step;
        splits += split.simulation.last_step_splits();
        EXPECT_LE(largest_stretch_ratio(split.simulation.cloth()), 1.3) << step;
    }
    EXPECT_GT(splits, 0);
    // Only the steps that needed it were split: far fewer than the steps taken times eight.
    EXPECT_LT(splits, 23);
}

TEST(ImplicitEulerSplit, NewtonIterationsTakeThePlaceOfSplits) {
    // The same release, linearised again where a failed step ended before it is split: the
    // sheet falls and settles, with fewer splits.
    auto run = [](int newton_iterations, int& splits, int& newton) {
        FlatReleaseAtALargeStep release(1.3, newton_iterations);
        splits = newton = 0;
        for (int step = 0; step < 23; ++step) {
            const StepReport report = release.simulation.step();
            EXPECT_FALSE(report.diverged()) << step;
            splits += release.simulation.last_step_splits();
            newton += release.simulation.last_step_newton_iterations();
        }
    };
    int splits_alone = 0, newton_alone = 0, splits = 0, newton = 0;
    run(0, splits_alone, newton_alone);
    run(3, splits, newton);
    EXPECT_EQ(newton_alone, 0);
    EXPECT_GT(newton, 0);
    EXPECT_LT(splits, splits_alone);
}

// A try judged early (ImplicitSolveSettings::early_judgement) stops only when another try
// follows it: the last one a step may take (no Newton iteration left, no halving) is kept
// whatever its judgement, so it must run its whole solve. The same release without halves:
// with one Newton iteration, that iteration is the last try and never stops early; with two,
// the first of them does.
TEST(ImplicitEulerSplit, TheLastTryAStepMayTakeIsNeverStoppedEarly) {
    auto run = [](int newton_iterations, int& newton, int& stopped_early) {
        FlatReleaseAtALargeStep release(1.3, newton_iterations);
        ImplicitSolveSettings settings;
        settings.newton_iterations = newton_iterations;
        settings.max_split_depth = 0;
        release.simulation.set_implicit_solve_settings(settings);
        newton = stopped_early = 0;
        for (int step = 0; step < 23; ++step) {
            ASSERT_FALSE(release.simulation.step().diverged()) << step;
            newton += release.simulation.last_step_newton_iterations();
            stopped_early += release.simulation.last_step_tries_stopped_early();
        }
    };
    int newton = 0, stopped_early = 0;
    run(1, newton, stopped_early);
    EXPECT_GT(newton, 0);
    EXPECT_EQ(stopped_early, 0);
    run(2, newton, stopped_early);
    EXPECT_GT(stopped_early, 0);
}

}  // namespace
}  // namespace weft
