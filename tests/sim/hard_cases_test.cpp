// Hard cases for the numerics: each run either stays finite and within stretch bounds, or is
// caught by the divergence guard at the first step that goes wrong — never NaN spreading.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "sim/build/cloth_builder.h"
#include "sim/core/simulation.h"
#include "sim/guards/divergence.h"
#include "sim/guards/stability_limit.h"
#include "test_scenes.h"

namespace weft {
namespace {

bool all_finite(const Cloth& cloth) {
    for (std::size_t p = 0; p < cloth.particle_count(); ++p)
        for (int k = 0; k < 3; ++k)
            if (!std::isfinite(cloth.positions[p][k]) || !std::isfinite(cloth.velocities[p][k]))
                return false;
    return true;
}

// Steps until diverged or `steps`; checks that the guard fired on the first unsound state
// (the state before it was finite) and returns whether it fired.
bool run_watching(Simulation& simulation, long long steps) {
    for (long long s = 0; s < steps; ++s) {
        const bool finite_before = all_finite(simulation.cloth());
        if (simulation.step().diverged()) {
            EXPECT_TRUE(finite_before) << "non-finite values were stepped on silently";
            return true;
        }
        EXPECT_TRUE(all_finite(simulation.cloth()))
            << "non-finite state not reported at step " << s;
    }
    return false;
}

Scene stiff_light_sheet(double stiffness, double mass) {
    Scene scene;
    scene.cloth.rows = 12;
    scene.cloth.cols = 12;
    scene.cloth.particle_mass = mass;
    scene.structural = {true, stiffness, 0.0};
    scene.shear = {true, stiffness / 2, 0.0};
    scene.bend = {true, stiffness / 8, 0.0};
    return scene;
}

TEST(HardCases, VeryStiffSpringsAreStableBelowTheLimitAndCaughtAboveIt) {
    for (double stiffness : {1e5, 1e6}) {
        Scene scene = stiff_light_sheet(stiffness, 0.01);
        const double limit = stable_step_limit(Integrator::symplectic_euler,
                                               highest_angular_frequency(build_grid_cloth(scene)));
        scene.solver = {Integrator::symplectic_euler, 0.9 * limit};
        Simulation below(scene);
        EXPECT_FALSE(run_watching(below, std::llround(0.1 / scene.solver.dt))) << stiffness;
        EXPECT_LT(largest_stretch_ratio(below.cloth()), 1.05);  // stiff springs barely stretch
        scene.solver.dt = 1.2 * limit;
        Simulation above(scene);
        EXPECT_TRUE(run_watching(above, std::llround(0.1 / scene.solver.dt))) << stiffness;
    }
}

TEST(HardCases, VeryLightParticlesAreStableBelowTheLimitAndCaughtAboveIt) {
    Scene scene = stiff_light_sheet(800.0, 1e-5);  // 10 mg particles
    const double limit = stable_step_limit(Integrator::velocity_verlet,
                                           highest_angular_frequency(build_grid_cloth(scene)));
    scene.solver = {Integrator::velocity_verlet, 0.9 * limit};
    Simulation below(scene);
    EXPECT_FALSE(run_watching(below, std::llround(0.05 / scene.solver.dt)));
    scene.solver.dt = 1.2 * limit;
    Simulation above(scene);
    EXPECT_TRUE(run_watching(above, std::llround(0.05 / scene.solver.dt)));
}

TEST(HardCases, ALargeSheetWithAllFamiliesStaysSound) {
    Scene scene;
    scene.cloth.rows = 128;
    scene.cloth.cols = 128;
    scene.cloth.spacing = 0.01;
    scene.cloth.particle_mass = 0.0004;  // 4 kg/m², a heavy sheet (large_rubber_sheet.toml's)
    scene.cloth.pin_preset = PinPreset::top_row;
    // Damping scaled with the mass, so the damping rates are large_rubber_sheet.toml's.
    scene.structural = {true, 800.0, 0.02};
    scene.shear = {true, 400.0, 0.02};
    scene.bend = {true, 100.0, 0.004};
    scene.forces.air_drag = 0.0008;
    // The demo's conservative estimate, which counts the damping: at 0.9 of it, stable.
    const double limit = estimated_step_limit(build_grid_cloth(scene), scene.forces.air_drag,
                                              Integrator::symplectic_euler);
    scene.solver = {Integrator::symplectic_euler, 0.9 * limit};
    Simulation simulation(scene);
    EXPECT_FALSE(run_watching(simulation, 500));
    EXPECT_LT(largest_stretch_ratio(simulation.cloth()), 1.2);
}

TEST(HardCases, ACornerPulledFastAndFarStaysSoundOrIsCaught) {
    Scene scene;
    scene.cloth.rows = 16;
    scene.cloth.cols = 16;
    scene.shear.enabled = true;
    scene.solver = {Integrator::symplectic_euler, 1e-3};
    Simulation simulation(scene);
    const std::uint32_t corner = 15 * 16 + 15;
    const Vec3 start = simulation.cloth().positions[corner];
    simulation.start_grab(grab_cloth(simulation.cloth(), {0, corner, 1.0, start}, 0.1));
    simulation.pull_to(start + Vec3(10.0, -10.0, 10.0));  // 17 m away, at once
    const bool caught = run_watching(simulation, 2000);
    if (!caught) {
        EXPECT_LT(largest_stretch_ratio(simulation.cloth()), runaway_stretch_ratio);
    }
}

TEST(HardCases, ATearingCascadeStaysSound) {
    Scene scene;
    scene.cloth.rows = 24;
    scene.cloth.cols = 24;
    scene.cloth.pin_preset = PinPreset::top_row;
    scene.shear.enabled = true;
    scene.bend.enabled = true;
    scene.tear_max_stretch = 1.3;
    scene.forces.gravity = {0.0, -400.0, 0.0};  // enough to rip the sheet apart
    scene.floor_enabled = false;                // and let it fall
    Simulation simulation(scene);
    const std::size_t initial = simulation.cloth().spring_count();
    const double initial_bottom = simulation.cloth().positions.back().y;
    EXPECT_FALSE(run_watching(simulation, 3000));
    // The sheet ripped off along its pinned row and fell: a whole row of springs broke...
    EXPECT_LE(simulation.cloth().spring_count(), initial - 24);
    EXPECT_LT(simulation.cloth().positions.back().y, initial_bottom - 10.0);
    // ...and every spring that is left is within the limit.
    EXPECT_LE(largest_stretch_ratio(simulation.cloth()), 1.3);
}

TEST(HardCases, DtJustPastTheLimitIsCaughtForEveryMethod) {
    Scene scene = stiff_light_sheet(800.0, 0.01);
    const double omega = highest_angular_frequency(build_grid_cloth(scene));
    for (Integrator integrator : {Integrator::symplectic_euler, Integrator::verlet,
                                  Integrator::velocity_verlet, Integrator::rk4}) {
        scene.solver = {integrator, 1.15 * stable_step_limit(integrator, omega)};
        Simulation simulation(scene);
        EXPECT_TRUE(run_watching(simulation, 5000)) << integrator_name(integrator);
    }
}

}  // namespace
}  // namespace weft
