// Colliders against exact truths: a ball dropped on a plane (restitution), sliding with
// Coulomb friction (deceleration μ g), resting in a repulsion layer (sag m g / k), and
// never ending a step inside a sphere.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <random>
#include <vector>

#include "sim/collision/colliders.h"

#include "sim/core/simulation.h"
#include "test_scenes.h"

namespace weft {
namespace {

// One free particle (rows = cols = 1, no pins) at `start` above a ground plane y = 0.
Scene one_particle(const Vec3d& start, ContactResponse response, double restitution,
                   double friction) {
    Scene scene;
    scene.cloth.rows = 1;
    scene.cloth.cols = 1;
    scene.cloth.origin = start;
    scene.cloth.pin_preset = PinPreset::none;
    scene.solver = {Integrator::symplectic_euler, 1e-4};
    ColliderSpec ground;
    ground.type = ColliderType::plane;
    ground.point = {0.0, 0.0, 0.0};
    ground.normal = {0.0, 1.0, 0.0};
    ground.response = response;
    ground.restitution = restitution;
    ground.friction = friction;
    scene.colliders = {ground};
    return scene;
}

TEST(ImpulseContact, ElasticBounceReturnsToTheDropHeight) {
    Simulation simulation(one_particle({0.0, 1.0, 0.0}, ContactResponse::impulse, 1.0, 0.0));
    double apex_after_bounce = 0.0;
    bool bounced = false;
    for (int s = 0; s < 9000; ++s) {  // 0.9 s: down (0.45 s) and back up (0.45 s)
        ASSERT_FALSE(simulation.step().diverged());
        const Vec3& x = simulation.cloth().positions[0];
        ASSERT_GE(x.y, 0.0);  // never ends a step below the ground
        if (simulation.cloth().velocities[0].y > 0.0) bounced = true;
        if (bounced) apex_after_bounce = std::max(apex_after_bounce, x.y);
    }
    EXPECT_TRUE(bounced);
    EXPECT_NEAR(apex_after_bounce, 1.0, 2e-3);  // symplectic Euler's O(h) energy error
}

TEST(ImpulseContact, InelasticContactStopsTheFall) {
    Simulation simulation(one_particle({0.0, 0.5, 0.0}, ContactResponse::impulse, 0.0, 0.0));
    ASSERT_TRUE(testing::run_steps(simulation, 5000));
    EXPECT_NEAR(simulation.cloth().positions[0].y, 0.0, 1e-12);
    EXPECT_NEAR(simulation.cloth().velocities[0].y, 0.0, 1e-3);  // one step of gravity at most
}

TEST(ImpulseContact, CoulombFrictionDeceleratesAtMuG) {
    const double mu = 0.3, v0 = 2.0, g = 9.81;
    Simulation simulation(one_particle({0.0, 0.0, 0.0}, ContactResponse::impulse, 0.0, mu));
    simulation.edit_cloth().velocities[0] = {v0, 0.0, 0.0};
    const double stop_time = v0 / (mu * g);  // 0.68 s
    ASSERT_TRUE(testing::run_steps(simulation, std::llround(0.5 * stop_time / 1e-4)));
    // Half way through the slide: v = v0 - μ g t, x = v0 t - ½ μ g t².
    const double t = simulation.time();
    EXPECT_NEAR(simulation.cloth().velocities[0].x, v0 - mu * g * t, 2e-3);
    EXPECT_NEAR(simulation.cloth().positions[0].x, v0 * t - 0.5 * mu * g * t * t, 2e-3);
    ASSERT_TRUE(testing::run_steps(simulation, std::llround(stop_time / 1e-4)));
    EXPECT_NEAR(simulation.cloth().velocities[0].x, 0.0, 1e-9);  // stopped, not reversed
    EXPECT_NEAR(simulation.cloth().positions[0].x, v0 * v0 / (2 * mu * g), 2e-3);
}

TEST(RepulsionContact, RestsAtTheStaticSagOfThePenaltySpring) {
    Simulation simulation(one_particle({0.0, 0.2, 0.0}, ContactResponse::repulsion, 0.0, 0.5));
    ASSERT_TRUE(testing::run_steps(simulation, 30000));  // 3 s: long settled
    // m g = m ω² depth  =>  depth = g / ω²; the particle rests at layer - depth above y = 0.
    const double depth = 9.81 / (repulsion_angular_frequency * repulsion_angular_frequency);
    EXPECT_NEAR(simulation.cloth().positions[0].y, repulsion_layer - depth, 1e-9);
}

TEST(ImpulseContact, ASheetDrapedOverASphereNeverEndsAStepInsideIt) {
    Scene scene;
    scene.cloth.rows = 16;
    scene.cloth.cols = 16;
    scene.cloth.orientation = Orientation::horizontal;
    scene.cloth.origin = {-0.375, 0.5, -0.375};
    scene.cloth.pin_preset = PinPreset::none;
    scene.shear.enabled = true;
    scene.forces.air_drag = 0.01;
    ColliderSpec sphere;
    sphere.center = {0.0, 0.0, 0.0};
    sphere.radius = 0.3;
    sphere.friction = 0.4;
    scene.colliders = {sphere};
    Simulation simulation(scene);
    std::size_t contacts = 0;
    for (int s = 0; s < 2000; ++s) {
        const StepReport report = simulation.step();
        ASSERT_FALSE(report.diverged());
        contacts += report.contacts;
        for (const Vec3& x : simulation.cloth().positions) ASSERT_GE(glm::length(x), 0.3 - 1e-12);
    }
    EXPECT_GT(contacts, 0u);
    // The middle of the sheet rests on top of the sphere.
    EXPECT_NEAR(simulation.cloth().positions[7 * 16 + 7].y, 0.3, 0.02);
}

// The contacts' scan tests blocks of particles before it looks at one; a level floor has a
// test of its own (one comparison a particle). Against signed_distance particle by particle,
// over particles on both sides, on the floor exactly, and with a coordinate that is not
// finite: every particle below the floor, and no other, is moved onto it.
TEST(ImpulseContact, ALevelFloorTakesExactlyTheParticlesBelowIt) {
    Collider floor;
    floor.type = ColliderType::plane;
    floor.point = {0.3, -0.25, 0.7};
    floor.normal = {0.0, 1.0, 0.0};
    std::mt19937 random(7);
    std::uniform_real_distribution<double> around(-1.0, 1.0);
    const std::size_t count = 203;  // several blocks and a part of one
    std::vector<Vec3> positions(count), velocities(count, Vec3(0.0, -1.0, 0.0));
    for (Vec3& x : positions) x = {around(random), -0.25 + 1e-3 * around(random), around(random)};
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double infinity = std::numeric_limits<double>::infinity();
    positions[5].y = -0.25;  // on the floor: not below it
    positions[40] = {nan, -0.5, 0.0};
    positions[41] = {0.0, -0.5, infinity};
    positions[42] = {0.0, nan, 0.0};
    positions[100].y = std::nextafter(-0.25, -1.0);
    const std::vector<double> inverse_masses(count, 1.0);
    std::vector<Vec3> expected = positions;
    std::size_t expected_moved = 0;
    for (Vec3& x : expected) {
        Vec3 n;
        const double distance = signed_distance(floor, x, n);
        if (distance < 0.0) {
            x -= distance * n;
            ++expected_moved;
        }
    }
    ASSERT_GT(expected_moved, 50u);
    const std::vector<Collider> colliders = {floor};
    const std::size_t moved = resolve_impulse_contacts(
        colliders, positions.data(), velocities.data(), inverse_masses.data(), 0, count);
    EXPECT_EQ(moved, expected_moved);
    for (std::size_t p = 0; p < count; ++p) {
        for (int k = 0; k < 3; ++k) {
            if (std::isnan(expected[p][k]))
                EXPECT_TRUE(std::isnan(positions[p][k])) << p;
            else
                EXPECT_EQ(positions[p][k], expected[p][k]) << p << " " << k;
        }
    }
}

}  // namespace
}  // namespace weft
