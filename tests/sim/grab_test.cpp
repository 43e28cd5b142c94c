// The hand (grab.h): held particles go where the hand takes them in every integrator, the
// rest of the cloth answers, a release hands back the hand's velocity, and a hand beyond the
// cloth's reach loses its grip instead of stretching the cloth without bound.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>
#include <string>

#include "sim/build/cloth_builder.h"
#include "sim/core/simulation.h"
#include "sim/guards/divergence.h"
#include "sim/interaction/grab.h"
#include "sim/scene_io/scene_loader.h"

namespace weft {
namespace {

Scene sheet(Integrator integrator = Integrator::symplectic_euler, double dt = 0.001) {
    Scene scene;
    scene.cloth.rows = 8;
    scene.cloth.cols = 8;
    scene.cloth.spacing = 0.05;
    scene.shear.enabled = true;
    scene.forces.air_drag = 0.02;
    scene.solver.integrator = integrator;
    scene.solver.dt = dt;
    return scene;
}

// Each method at a step it is stable at on this sheet (explicit Euler only for a few steps).
const std::pair<Integrator, double> methods[] = {{Integrator::explicit_euler, 0.0002},
                                                 {Integrator::symplectic_euler, 0.001},
                                                 {Integrator::verlet, 0.001},
                                                 {Integrator::velocity_verlet, 0.001},
                                                 {Integrator::rk4, 0.001},
                                                 {Integrator::implicit_euler, 1.0 / 60.0}};

TEST(Grab, GrabsOnlyFreeParticlesWithinTheRadiusWithFallingWeights) {
    const Cloth cloth = build_grid_cloth(sheet());
    const RayHit hit{0, 3 * 8 + 3, 1.0, cloth.positions[3 * 8 + 3]};
    const Grab grab = grab_cloth(cloth, hit, 0.12);
    ASSERT_TRUE(grab.active());
    ASSERT_FALSE(grab.followers.empty());
    auto weight_at = [&](std::uint32_t p) {
        const double distance = glm::length(cloth.positions[p] - hit.point);
        EXPECT_LT(distance, 0.12);
        EXPECT_FALSE(cloth.is_pinned(p));
        return std::pow(1.0 - distance * distance / (0.12 * 0.12), 2);
    };
    for (std::size_t k = 0; k < grab.particles.size(); ++k) {
        EXPECT_NEAR(grab.weights[k], weight_at(grab.particles[k]), 1e-12);
        EXPECT_GE(grab.weights[k], 0.5);
    }
    for (std::size_t k = 0; k < grab.followers.size(); ++k) {
        EXPECT_NEAR(grab.follower_weights[k], weight_at(grab.followers[k]), 1e-12);
        EXPECT_LT(grab.follower_weights[k], 0.5);
    }
    // Every free particle within the radius is in one list or the other.
    std::size_t within = 0;
    for (std::size_t p = 0; p < cloth.particle_count(); ++p)
        within += glm::length(cloth.positions[p] - hit.point) < 0.12 && !cloth.is_pinned(p);
    EXPECT_EQ(grab.particles.size() + grab.followers.size(), within);
    // A tiny radius still grabs the particle that was hit.
    const Grab small = grab_cloth(cloth, hit, 1e-6);
    ASSERT_EQ(small.particles.size(), 1u);
    EXPECT_EQ(small.particles[0], hit.particle);
    // Its grip springs are exactly the springs with one end at it: 2 structural, 2 shear
    // inside an 8 x 8 sheet, none to itself.
    EXPECT_EQ(small.grip_springs.size(), 8u);
    for (const Grab::GripSpring& spring : small.grip_springs) {
        EXPECT_EQ(spring.held, hit.particle);
        EXPECT_NE(spring.other, hit.particle);
    }
}

// A lift of the bottom edge's middle, one target a 60 Hz frame, with as many steps a frame
// as the method's dt asks: at every frame's end the grabbed particle is where the hand is,
// whatever the method, and the rest of the sheet came along (its centre rose).
TEST(Grab, TheGrabbedPointIsWhereTheHandIsInEveryMethod) {
    for (const auto& [integrator, dt] : methods) {
        Simulation simulation(sheet(integrator, dt));
        const std::uint32_t grabbed = 7 * 8 + 4;
        const Vec3 start = simulation.cloth().positions[grabbed];
        const double centre_before = simulation.cloth().positions[4 * 8 + 4].y;
        simulation.start_grab(grab_cloth(simulation.cloth(), {0, grabbed, 1.0, start}, 0.06));
        const int steps_a_frame = std::max(1, static_cast<int>(std::lround(1.0 / 60.0 / dt)));
        const int frames = integrator == Integrator::explicit_euler ? 6 : 18;
        for (int frame = 1; frame <= frames; ++frame) {
            const Vec3 hand = start + (0.4 * frame / frames) * Vec3(0.0, 1.0, 0.0);  // 1.3 m/s
            simulation.pull_to(hand);
            for (int s = 0; s < steps_a_frame; ++s)
                ASSERT_FALSE(simulation.step().diverged()) << integrator_name(integrator);
            EXPECT_LT(glm::length(simulation.cloth().positions[grabbed] - hand), 1e-12)
                << integrator_name(integrator) << ", frame " << frame;
        }
        if (integrator != Integrator::explicit_euler) {
            EXPECT_GT(simulation.cloth().positions[4 * 8 + 4].y, centre_before + 0.02)
                << integrator_name(integrator);
        }
    }
}

// Within a frame of several steps the hand moves evenly, not in one jump: the grabbed
// particle's velocity is the hand's (distance over the frame's time) at every step.
TEST(Grab, TheHandMovesEvenlyThroughTheStepsOfAFrame) {
    Simulation simulation(sheet());
    const std::uint32_t grabbed = 7 * 8 + 4;
    const Vec3 start = simulation.cloth().positions[grabbed];
    simulation.start_grab(grab_cloth(simulation.cloth(), {0, grabbed, 1.0, start}, 0.06));
    for (int s = 0; s < 20; ++s) ASSERT_FALSE(simulation.step().diverged());  // 20 ms held still
    const Vec3 velocity(0.0, 0.9, 0.3);                                       // m/s
    for (int frame = 1; frame <= 5; ++frame) {
        simulation.pull_to(start + (frame * 0.02) * velocity);  // one frame, 20 steps
        for (int s = 0; s < 20; ++s) {
            ASSERT_FALSE(simulation.step().diverged());
            if (frame > 1) {  // the first frame's interval is the pause before it
                EXPECT_LT(glm::length(simulation.cloth().velocities[grabbed] - velocity), 1e-9)
                    << "frame " << frame << ", step " << s;
            }
        }
    }
}

// A fling flies: let go mid-sweep, the grabbed particle leaves with the hand's velocity.
TEST(Grab, ReleaseHandsBackTheHandsVelocity) {
    for (const auto& [integrator, dt] : methods) {
        if (integrator == Integrator::explicit_euler) continue;
        Simulation simulation(sheet(integrator, dt));
        const std::uint32_t grabbed = 7 * 8 + 4;
        const Vec3 start = simulation.cloth().positions[grabbed];
        simulation.start_grab(grab_cloth(simulation.cloth(), {0, grabbed, 1.0, start}, 0.06));
        const int steps_a_frame = std::max(1, static_cast<int>(std::lround(1.0 / 60.0 / dt)));
        const Vec3 hand_velocity(0.0, 1.8, -0.6);  // m/s
        for (int frame = 1; frame <= 8; ++frame) {
            simulation.pull_to(start + (frame * steps_a_frame * dt) * hand_velocity);
            for (int s = 0; s < steps_a_frame; ++s) ASSERT_FALSE(simulation.step().diverged());
        }
        simulation.let_go();
        EXPECT_LT(glm::length(simulation.cloth().velocities[grabbed] - hand_velocity),
                  1e-6 * glm::length(hand_velocity))
            << integrator_name(integrator);
        // One small step on, it has gone on the way the hand went (implicit Euler's frame
        // step lets the sheet pull it back within the step).
        if (integrator == Integrator::implicit_euler) continue;
        const Vec3 released_at = simulation.cloth().positions[grabbed];
        ASSERT_FALSE(simulation.step().diverged());
        EXPECT_GT(glm::dot(simulation.cloth().positions[grabbed] - released_at, hand_velocity), 0.0)
            << integrator_name(integrator);
    }
}

// A follower of weight w closes the fraction w of the gap between its velocity and the
// hand's in each 1/60 s, whatever the step: checked over one frame of 1, 4 and 16 steps.
TEST(Grab, FollowersCloseTheirWeightOfTheGapToTheHandsVelocityEachFrame) {
    for (const int steps : {1, 4, 16}) {
        Cloth cloth = build_grid_cloth(sheet());
        const std::uint32_t grabbed = 4 * 8 + 4;
        Grab grab = grab_cloth(cloth, {0, grabbed, 1.0, cloth.positions[grabbed]}, 0.12);
        ASSERT_FALSE(grab.followers.empty());
        const double dt = 1.0 / 60.0 / steps;
        const Vec3 hand_velocity(0.5, 1.0, 0.0);
        move_hand(grab, grab.hand + (1.0 / 60.0) * hand_velocity, 0.0, 1.0 / 60.0);
        for (const std::uint32_t p : grab.followers) cloth.velocities[p] = Vec3(0.0, 0.0, -2.0);
        for (int s = 0; s < steps; ++s) {
            prescribe_hand_motion(grab, cloth, dt);
            EXPECT_LT(glm::length(grab.hand_velocity - hand_velocity), 1e-9);
            start_hand_motion(grab, cloth, dt);
        }
        for (std::size_t k = 0; k < grab.followers.size(); ++k) {
            const double w = grab.follower_weights[k];
            const Vec3 expected =
                hand_velocity + (1.0 - w) * (Vec3(0.0, 0.0, -2.0) - hand_velocity);
            EXPECT_LT(glm::length(cloth.velocities[grab.followers[k]] - expected), 1e-9)
                << steps << " steps, weight " << w;
        }
        for (std::size_t k = 0; k < grab.particles.size(); ++k)
            EXPECT_EQ(cloth.velocities[grab.particles[k]], grab.velocities[k]);
    }
}

// The hand thrown far beyond the cloth's reach, back and forth: the cloth goes taut, the
// grip slips before any spring at the hand passes grip_stretch rest lengths by much, and
// nothing diverges, in every method. Implicit Euler's frame-sized steps may carry the sheet
// after the hand with no spring at it past grip_stretch; then the grip holds, and what is
// asked is that no spring anywhere passed grip_stretch.
TEST(Grab, AHandBeyondReachSlipsInsteadOfStretchingTheCloth) {
    for (const auto& [integrator, dt] : methods) {
        if (integrator == Integrator::explicit_euler) continue;
        Simulation simulation(sheet(integrator, dt));
        const std::uint32_t grabbed = 7 * 8 + 4;
        const Vec3 start = simulation.cloth().positions[grabbed];
        simulation.start_grab(grab_cloth(simulation.cloth(), {0, grabbed, 1.0, start}, 0.1));
        const int steps_a_frame = std::max(1, static_cast<int>(std::lround(1.0 / 60.0 / dt)));
        bool slipped = false;
        double largest_stretch = 0.0;
        for (int frame = 1; frame <= 120; ++frame) {
            // 5 m either side every 1/60 s.
            simulation.pull_to(start + Vec3(frame % 2 ? 5.0 : -5.0, 0.0, 0.0));
            for (int s = 0; s < steps_a_frame; ++s) {
                const StepReport report = simulation.step();
                ASSERT_FALSE(report.diverged())
                    << integrator_name(integrator) << ": " << *report.divergence;
                slipped = slipped || report.hand_slipped;
                largest_stretch =
                    std::max(largest_stretch, largest_stretch_ratio(simulation.cloth()));
            }
        }
        if (integrator == Integrator::implicit_euler && !slipped) {
            EXPECT_TRUE(simulation.grab().active());
            EXPECT_LT(largest_stretch, Grab::default_grip_stretch);
            continue;
        }
        EXPECT_TRUE(slipped) << integrator_name(integrator);
        EXPECT_FALSE(simulation.grab().active()) << integrator_name(integrator);
        EXPECT_LT(largest_stretch, runaway_stretch_ratio) << integrator_name(integrator);
    }
}

// Thrown far beyond reach, a frame-sized implicit step under the hand fails every try of its
// linearisation. Where the grip has slipped by then, the step is not split down to its
// deepest level first (dozens of solves for a step thrown away): the held step's tries and
// the step taken again without the hand are all it costs.
TEST(Grab, ImplicitEulerLetsGoBeyondReachWithoutSplittingTheHeldStep) {
    SceneLoadResult loaded =
        load_scene_file(std::string(WEFT_SOURCE_DIR) + "/assets/scenes/cloth_128.toml",
                        {"cloth.rows=64", "cloth.cols=64",
                         "cloth.spacing=0.018254",         // m: 1.15 m / 63
                         "cloth.particle_mass=0.0000666",  // kg: 0.2 kg/m² × spacing²
                         "solver.dt=0.0333333333333333"});
    ASSERT_TRUE(loaded.ok());
    Simulation simulation(*loaded.scene);
    while (simulation.time() < 0.5) ASSERT_FALSE(simulation.step().diverged());
    const Cloth& cloth = simulation.cloth();
    const auto grabbed = static_cast<std::uint32_t>((cloth.rows - 1) * cloth.cols + cloth.cols / 2);
    const Vec3 start = cloth.positions[grabbed];
    simulation.start_grab(grab_cloth(cloth, {0, grabbed, 1.0, start}, 0.08));
    simulation.pull_to(start + Vec3(-0.8, -0.6, 0.8));
    bool slipped = false;
    for (int step = 0; step < 10 && !slipped; ++step) {
        const std::uint64_t before = simulation.force_evaluations();
        const StepReport report = simulation.step();
        ASSERT_FALSE(report.diverged()) << *report.divergence;
        slipped = report.hand_slipped;
        if (slipped) {
            const int tries = 1 + ImplicitSolveSettings{}.newton_iterations;
            EXPECT_LE(simulation.force_evaluations() - before,
                      static_cast<std::uint64_t>(2 * tries));
        }
    }
    EXPECT_TRUE(slipped);
}

// Within reach the grip holds: a slow lift of a corner never slips.
TEST(Grab, TheGripHoldsWithinReach) {
    Simulation simulation(sheet());
    const std::uint32_t grabbed = 7 * 8 + 0;
    const Vec3 start = simulation.cloth().positions[grabbed];
    simulation.start_grab(grab_cloth(simulation.cloth(), {0, grabbed, 1.0, start}, 0.06));
    for (int frame = 1; frame <= 60; ++frame) {
        simulation.pull_to(start + (0.3 * frame / 60.0) * Vec3(0.0, 1.0, 1.0));
        for (int s = 0; s < 17; ++s) {
            const StepReport report = simulation.step();
            ASSERT_FALSE(report.diverged());
            ASSERT_FALSE(report.hand_slipped) << "frame " << frame;
        }
    }
    EXPECT_TRUE(simulation.grab().active());
}

}  // namespace
}  // namespace weft

namespace weft {
namespace {

struct SweepResult {
    double lag_at_stop = 0.0;  // m, grabbed particle to the hand when the hand stops
    double largest_stretch = 0.0;
    bool slipped = false;
    std::size_t torn = 0;
    std::string divergence;
    int splits = 0;
};

// Hangs the scene for `settle` s, grabs the middle of the bottom row, and moves the hand
// along path(t) (t in s from the grab) for `duration` s, one target a 1/60 s frame.
template <class Path>
SweepResult sweep(const Scene& scene, double settle, double duration, Path path) {
    SweepResult result;
    Simulation simulation(scene);
    while (simulation.time() < settle) {
        const StepReport report = simulation.step();
        if (report.diverged()) {
            result.divergence = "settling: " + *report.divergence;
            return result;
        }
    }
    const Cloth& cloth = simulation.cloth();
    const auto grabbed = static_cast<std::uint32_t>((cloth.rows - 1) * cloth.cols + cloth.cols / 2);
    const Vec3 start = cloth.positions[grabbed];
    simulation.start_grab(grab_cloth(cloth, {0, grabbed, 1.0, start}, 0.08));
    EXPECT_TRUE(simulation.grab().active());
    const int frames = static_cast<int>(std::lround(duration * 60.0));
    Vec3 hand = start;
    for (int frame = 1; frame <= frames; ++frame) {
        hand = start + path(frame / 60.0);
        simulation.pull_to(hand);
        const double frame_end = settle + frame / 60.0 - 1e-9;
        while (simulation.time() < frame_end) {
            const StepReport report = simulation.step();
            result.splits += simulation.last_step_splits();
            result.slipped = result.slipped || report.hand_slipped;
            result.torn += report.springs_torn;
            result.largest_stretch =
                std::max(result.largest_stretch, largest_stretch_ratio(simulation.cloth()));
            if (report.diverged()) {
                result.divergence = *report.divergence;
                return result;
            }
        }
    }
    result.lag_at_stop = glm::length(simulation.cloth().positions[grabbed] - hand);
    return result;
}

Scene shipped(const char* file) {
    SceneLoadResult loaded =
        load_scene_file(std::string(WEFT_SOURCE_DIR) + "/assets/scenes/" + file);
    EXPECT_TRUE(loaded.ok()) << file;
    return loaded.ok() ? *loaded.scene : Scene{};
}

// The hand's sweeps of the bottom edge's middle, within the sheet's reach: a lift of 0.72 m
// in 0.3 s (2.4 m/s) and a flick of 0.76 m across in 0.15 s (5 m/s).
Vec3 lift(double t) {
    return Vec3(0.0, 2.4 * t, 0.0);
}
Vec3 flick(double t) {
    return Vec3(5.0 * t, 0.0, 0.0);
}
// Far beyond reach: from the grab point to 1.6 m apart and back and forth, a leg every 0.1 s,
// 0.6 m below and 0.8 m in front of it (the sheet hangs 1.15 m from its pins).
Vec3 fling(double t) {
    const Vec3 a(-0.8, -0.6, 0.8), b(0.8, -0.6, 0.8);
    if (t <= 0.1) return (t / 0.1) * a;
    const double leg = std::fmod(t - 0.1, 0.2);
    const double s = leg < 0.1 ? leg / 0.1 : 2.0 - leg / 0.1;  // 0 at a, 1 at b
    return a + s * (b - a);
}

// The default scene (explicit) and the cotton-like 128² sheet (implicit Euler at one step a
// frame), hung for 1.5 s first: when the hand stops, the grabbed point is with it.
TEST(Grab, TheGrabbedPointKeepsUpWithALiftAndAFlickOnTheShippedCloths) {
    for (const char* file : {"hanging_sheet.toml", "cloth_128.toml"}) {
        const Scene scene = shipped(file);
        const SweepResult lifted = sweep(scene, 1.5, 0.3, lift);
        EXPECT_EQ(lifted.divergence, "") << file;
        EXPECT_FALSE(lifted.slipped) << file;
        EXPECT_LT(lifted.lag_at_stop, 0.05) << file;
        const SweepResult flicked = sweep(scene, 1.5, 0.15, flick);
        EXPECT_EQ(flicked.divergence, "") << file;
        EXPECT_FALSE(flicked.slipped) << file;
        EXPECT_LT(flicked.lag_at_stop, 0.10) << file;
    }
}

// The same on cloths of these materials that are not the shipped files: other sizes and
// another grab radius' worth of sheet.
TEST(Grab, TheGrabbedPointKeepsUpOnOtherSheetsOfTheSameMaterials) {
    Scene cotton = shipped("cloth_128.toml");  // 0.2 kg/m², implicit Euler at 1/60 s
    cotton.cloth.rows = cotton.cloth.cols = 48;
    cotton.cloth.spacing = 1.15 / 47.0;
    cotton.cloth.particle_mass = 0.2 * cotton.cloth.spacing * cotton.cloth.spacing;
    Scene light = shipped("hanging_sheet.toml");  // the default's material, 16 x 32
    light.cloth.rows = 16;
    light.cloth.cols = 32;
    for (const Scene& scene : {cotton, light}) {
        const SweepResult lifted = sweep(scene, 1.0, 0.3, lift);
        EXPECT_EQ(lifted.divergence, "") << scene.name;
        EXPECT_LT(lifted.lag_at_stop, 0.05) << scene.name;
        const SweepResult flicked = sweep(scene, 1.0, 0.15, flick);
        EXPECT_EQ(flicked.divergence, "") << scene.name;
        EXPECT_LT(flicked.lag_at_stop, 0.10) << scene.name;
    }
}

// Flings far beyond reach neither diverge (which would set the demo's recovery off) nor
// hold on: the grip slips or the sheet tears.
class Flings : public testing::TestWithParam<const char*> {};

// One shipped cloth a test, so that ctest runs them side by side. The 256² sheet, the slowest,
// settles for half a second and is flung for three swings.
TEST_P(Flings, FarBeyondReachNeitherDivergeNorHoldOn) {
    const Scene scene = shipped(GetParam());
    const bool large = scene.cloth.rows >= 256;
    const SweepResult flung = sweep(scene, large ? 0.5 : 1.0, large ? 0.4 : 1.0, fling);
    EXPECT_EQ(flung.divergence, "");
    EXPECT_TRUE(flung.slipped || flung.torn > 0);
    EXPECT_LT(flung.largest_stretch, runaway_stretch_ratio);
}

INSTANTIATE_TEST_SUITE_P(ShippedCloths, Flings,
                         testing::Values("hanging_sheet.toml", "tearing_sheet.toml",
                                         "cloth_128.toml", "cloth_256.toml"),
                         [](const testing::TestParamInfo<const char*>& param) {
                             const std::string file = param.param;
                             return file.substr(0, file.find('.'));
                         });

}  // namespace
}  // namespace weft
