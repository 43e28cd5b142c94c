// Static equilibrium of a damped hanging chain: spring s (counted from the pin) carries the
// weight of the particles below it, so its exact length is L + (N - s) m g / k. Every stable
// integrator must come to rest exactly there: at the equilibrium the acceleration is zero,
// which is a fixed point of every method.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "sim/core/simulation.h"
#include "test_scenes.h"

namespace weft {
namespace {

TEST(HangingChain, ComesToRestAtTheExactStaticExtensionOfEachSpring) {
    const int particles = 8;
    const double mass = 0.01, stiffness = 50.0, rest_length = 0.05, gravity = 9.81;
    for (Integrator integrator : testing::all_integrators) {
        Scene scene = testing::hanging_chain(particles, mass, stiffness, 0.2, rest_length, 0.05);
        scene.forces.gravity = {0.0, -gravity, 0.0};
        scene.solver = {integrator, 1e-3};
        Simulation simulation(scene);
        ASSERT_TRUE(testing::run_steps(simulation, 30'000)) << integrator_name(integrator);  // 30 s

        const Cloth& chain = simulation.cloth();
        for (int s = 1; s < particles; ++s) {
            const double length = glm::length(chain.positions[s] - chain.positions[s - 1]);
            const double exact = rest_length + (particles - s) * mass * gravity / stiffness;
            EXPECT_NEAR(length, exact, 1e-10) << integrator_name(integrator) << " spring " << s;
        }
        for (int p = 0; p < particles; ++p) {
            EXPECT_EQ(chain.positions[p].x, 0.0);  // hangs straight down
            EXPECT_LT(glm::length(chain.velocities[p]), 1e-9);
        }
    }
}

}  // namespace
}  // namespace weft
