// Every integrator against the closed-form motion of a mass hanging from a spring.
#include <gtest/gtest.h>

#include "sim/core/simulation.h"
#include "test_scenes.h"

namespace weft {
namespace {

using testing::HangingSpring;

struct OscillatorCase {
    Integrator integrator;
    double dt;  // s, small enough for this method's order to reach the tolerance
};

void PrintTo(const OscillatorCase& c, std::ostream* out) {
    *out << integrator_name(c.integrator) << " at dt = " << c.dt << " s";
}

class HangingSpringMatchesClosedForm : public ::testing::TestWithParam<OscillatorCase> {};

TEST_P(HangingSpringMatchesClosedForm, OverThreeUndampedPeriods) {
    const HangingSpring spring;
    const OscillatorCase c = GetParam();
    // The closed form to the test's tolerance needs implicit Euler's double-precision path
    // (at dt = 1 µs the structured solve's single precision is coarser than the method).
    Simulation simulation(spring.scene(c.integrator, c.dt), testing::general_implicit_path());
    const double amplitude = spring.mass * spring.gravity / spring.stiffness;  // m
    const long long steps = std::llround(1.0 / c.dt);  // T = 1 s, about 3.2 periods
    double worst = 0.0;
    for (long long s = 1; s <= steps; ++s) {
        ASSERT_FALSE(simulation.step().diverged());
        const double t = static_cast<double>(s) * c.dt;
        worst = std::max(worst, std::abs(simulation.cloth().positions[1].y - spring.position(t)));
    }
    // The free particle stays on the vertical line through the pin.
    EXPECT_EQ(simulation.cloth().positions[1].x, 0.0);
    EXPECT_EQ(simulation.cloth().positions[1].z, 0.0);
    EXPECT_LT(worst, 1e-3 * amplitude) << integrator_name(c.integrator);
    EXPECT_NEAR(simulation.cloth().velocities[1].y, spring.velocity(1.0),
                2e-3 * amplitude * spring.omega0());
}

TEST_P(HangingSpringMatchesClosedForm, WithSpringDampingAndDrag) {
    HangingSpring spring;
    spring.damping = 0.4;  // γ = (0.4 + 0.2) / 0.2 = 3 /s: visibly decaying
    spring.air_drag = 0.2;
    const OscillatorCase c = GetParam();
    // The closed form to the test's tolerance needs implicit Euler's double-precision path
    // (at dt = 1 µs the structured solve's single precision is coarser than the method).
    Simulation simulation(spring.scene(c.integrator, c.dt), testing::general_implicit_path());
    const double amplitude = spring.mass * spring.gravity / spring.stiffness;
    const long long steps = std::llround(1.0 / c.dt);
    double worst = 0.0;
    for (long long s = 1; s <= steps; ++s) {
        ASSERT_FALSE(simulation.step().diverged());
        const double t = static_cast<double>(s) * c.dt;
        worst = std::max(worst, std::abs(simulation.cloth().positions[1].y - spring.position(t)));
    }
    EXPECT_LT(worst, 1e-3 * amplitude) << integrator_name(c.integrator);
}

INSTANTIATE_TEST_SUITE_P(Each, HangingSpringMatchesClosedForm,
                         ::testing::Values(OscillatorCase{Integrator::explicit_euler, 1e-6},
                                           OscillatorCase{Integrator::symplectic_euler, 1e-5},
                                           OscillatorCase{Integrator::verlet, 1e-3},
                                           OscillatorCase{Integrator::velocity_verlet, 1e-3},
                                           OscillatorCase{Integrator::rk4, 1e-2},
                                           OscillatorCase{Integrator::implicit_euler, 1e-6}),
                         testing::IntegratorParamName());

TEST(Simulation, PinnedParticlesNeverMoveUnderAnyIntegrator) {
    for (Integrator integrator : testing::all_integrators) {
        Scene scene;
        scene.cloth.rows = 6;
        scene.cloth.cols = 5;
        scene.shear.enabled = true;
        scene.bend.enabled = true;
        scene.forces.air_drag = 0.05;
        scene.forces.wind = {3.0, 0.0, 4.0};
        scene.solver = {integrator, 5e-4};
        Simulation simulation(scene);
        const Cloth initial = simulation.cloth();
        ASSERT_TRUE(testing::run_steps(simulation, 2000)) << integrator_name(integrator);
        for (std::uint32_t p : initial.topology().pinned) {
            EXPECT_EQ(simulation.cloth().positions[p], initial.positions[p]);
            EXPECT_EQ(simulation.cloth().velocities[p], Vec3(0.0));
        }
        // ...while the free ones did move in the wind.
        EXPECT_GT(std::abs(simulation.cloth().positions.back().z - initial.positions.back().z),
                  0.01);
    }
}

}  // namespace
}  // namespace weft
