// The linear stability prediction against the exact spectrum of a chain, and the measured
// stability limit of the methods against the prediction.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "sim/build/cloth_builder.h"
#include "sim/core/simulation.h"
#include "sim/guards/stability_limit.h"
#include "test_scenes.h"

namespace weft {
namespace {

// n free particles between two pinned ones, at rest length: the longitudinal modes of a
// fixed-fixed chain, ω_j = 2 √(k/m) sin(j π / (2 (n + 1))), j = 1..n.
Scene fixed_chain(int free_particles, double stiffness, double mass) {
    Scene scene;
    scene.cloth.rows = free_particles + 2;
    scene.cloth.cols = 1;
    scene.cloth.particle_mass = mass;
    scene.cloth.pin_preset = PinPreset::list;
    scene.cloth.pin_list = {{0, 0}, {free_particles + 1, 0}};
    scene.structural = {true, stiffness, 0.0};
    scene.forces.gravity = {0.0, 0.0, 0.0};
    return scene;
}

TEST(StabilityLimit, PowerIterationFindsTheChainsHighestMode) {
    const int n = 12;
    const double k = 300.0, m = 0.02;
    const Cloth chain = build_grid_cloth(fixed_chain(n, k, m));
    const double exact = 2.0 * std::sqrt(k / m) * std::sin(n * M_PI / (2.0 * (n + 1)));
    EXPECT_NEAR(highest_angular_frequency(chain), exact, 1e-5 * exact);
    // Gershgorin bound: 2 (k + k) / m for an inner particle.
    EXPECT_NEAR(angular_frequency_bound(chain), std::sqrt(4.0 * k / m), 1e-12);
    EXPECT_GE(angular_frequency_bound(chain), exact);
}

TEST(StabilityLimit, TheDampedEstimateIsTheExactBoundForOneDampedSpring) {
    // One free particle on one spring: ω² = k/m and c = (damping + air_drag)/m exactly, and
    // symplectic Euler is stable iff h²ω² + 2hc < 4 (Jury's conditions on its 2x2 map).
    Scene scene = fixed_chain(1, 300.0, 0.02);
    scene.cloth.rows = 2;  // a pin and one free particle
    scene.cloth.pin_list = {{0, 0}};
    scene.structural.damping = 0.3;
    scene.forces.air_drag = 0.1;
    const Cloth one = build_grid_cloth(scene);
    // The bound counts a spring twice (its diagonal and off-diagonal entries, even when the
    // other end is pinned): ω² <= 2k/m, c <= (2c + drag)/m — safe, and here exactly known.
    const double omega_squared = 2.0 * 300.0 / 0.02, damping = (2.0 * 0.3 + 0.1) / 0.02;
    const double h = estimated_step_limit(one, 0.1, Integrator::symplectic_euler);
    EXPECT_NEAR(h * h * omega_squared + 2.0 * h * damping, 4.0, 1e-12);
    EXPECT_NEAR(estimated_step_limit(one, 0.1, Integrator::rk4), std::sqrt(2.0) * h, 1e-15);
    EXPECT_EQ(estimated_step_limit(one, 0.1, Integrator::explicit_euler), 0.0);
}

TEST(StabilityLimit, StepLimitsAreTheMethodsStabilityIntervals) {
    EXPECT_EQ(stable_step_limit(Integrator::symplectic_euler, 100.0), 0.02);
    EXPECT_EQ(stable_step_limit(Integrator::verlet, 100.0), 0.02);
    EXPECT_EQ(stable_step_limit(Integrator::velocity_verlet, 100.0), 0.02);
    EXPECT_NEAR(stable_step_limit(Integrator::rk4, 100.0), 0.028284271247461905, 1e-15);
    EXPECT_EQ(stable_step_limit(Integrator::explicit_euler, 100.0), 0.0);
}

// Runs the chain from a small deterministic kick; true if the motion stays small (linear
// stability: an unstable mode grows without bound, a stable one never exceeds its start by
// much). Amplitude is the criterion, not the divergence guard: a large chain motion turns
// nonlinear (springs fold through zero length) and can stay bounded far from the linear regime.
bool stays_stable(Integrator integrator, double dt, long long steps) {
    Scene scene = fixed_chain(12, 300.0, 0.02);
    scene.solver = {integrator, dt};
    Simulation simulation(scene);
    const std::vector<Vec3> rest = simulation.cloth().positions;
    const double kick = 1e-5;  // m
    Cloth& cloth = simulation.edit_cloth();
    for (std::size_t p = 1; p + 1 < cloth.particle_count(); ++p)
        cloth.positions[p].y += kick * std::sin(1.7 * static_cast<double>(p));
    for (long long s = 0; s < steps; ++s) {
        if (simulation.step().diverged()) return false;
        for (std::size_t p = 0; p < rest.size(); ++p)
            if (glm::length(simulation.cloth().positions[p] - rest[p]) > 100.0 * kick) return false;
    }
    return true;
}

TEST(StabilityLimit, MethodsAreStableJustBelowThePredictedLimitAndNotJustAbove) {
    const double omega = highest_angular_frequency(build_grid_cloth(fixed_chain(12, 300.0, 0.02)));
    for (Integrator integrator : {Integrator::symplectic_euler, Integrator::verlet,
                                  Integrator::velocity_verlet, Integrator::rk4}) {
        const double limit = stable_step_limit(integrator, omega);
        EXPECT_TRUE(stays_stable(integrator, 0.97 * limit, 20000)) << integrator_name(integrator);
        EXPECT_FALSE(stays_stable(integrator, 1.03 * limit, 20000))
            << integrator_name(integrator) << " at " << 1.03 * limit;
    }
}

}  // namespace
}  // namespace weft
