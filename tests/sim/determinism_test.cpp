// Determinism: the same scene and input give the same state, bit for bit, run after run —
// tearing and pulling included.
#include <gtest/gtest.h>

#include <utility>

#include "same_bits.h"
#include "sim/core/simulation.h"
#include "sim/core/state_hash.h"
#include "sim/grid/grid_force_pass.h"
#include "sim/scene_io/scene_loader.h"
#include "test_scenes.h"

namespace weft {
namespace {

// The tearing sheet in a strong wind, dragged by a corner, for 2 s with every integrator,
// its force pass split between `threads` threads.
std::uint64_t final_hash(Integrator integrator, int threads = 1) {
    SceneLoadResult loaded = load_scene_file(WEFT_SOURCE_DIR "/assets/scenes/tearing_sheet.toml",
                                             {"forces.wind=[4,0,6]"});
    EXPECT_TRUE(loaded.ok());
    Scene scene = *loaded.scene;
    scene.solver = {integrator, 2.5e-4};
    Simulation simulation(scene);
    simulation.set_thread_count(threads);
    const std::uint32_t corner =
        static_cast<std::uint32_t>(simulation.cloth().particle_count() - 1);
    const Vec3 start = simulation.cloth().positions[corner];
    simulation.start_grab(grab_cloth(simulation.cloth(), {0, corner, 1.0, start}, 0.1));
    std::size_t torn = 0;
    for (int frame = 0; frame < 120; ++frame) {
        simulation.pull_to(start + Vec3(0.02 * frame, -0.03 * frame, 0.01 * frame));
        for (int s = 0; s < 66; ++s) {
            const StepReport report = simulation.step();
            torn += report.springs_torn;
            if (report.diverged()) return 0;
        }
    }
    EXPECT_GT(torn, 0u) << integrator_name(integrator);  // the run does exercise tearing
    return hash_state(simulation.cloth());
}

TEST(Determinism, RepeatedRunsGiveTheSameStateBitForBit) {
    for (Integrator integrator : testing::all_integrators) {
        if (integrator == Integrator::explicit_euler) continue;  // diverges in this wind
        const std::uint64_t first = final_hash(integrator);
        ASSERT_NE(first, 0u) << integrator_name(integrator) << " diverged";
        EXPECT_EQ(final_hash(integrator), first) << integrator_name(integrator);
    }
}

// A 96x96 sheet with all spring families in a wind strong enough to tear it, stepped at
// 0.2 ms: big enough that the force pass and every spring colour are split between threads.
Scene large_tearing_sheet(Layout layout, Integrator integrator) {
    Scene scene;
    scene.cloth.rows = 96;
    scene.cloth.cols = 96;
    scene.cloth.spacing = 0.012;
    scene.cloth.particle_mass = 0.0006;
    scene.cloth.layout = layout;
    scene.shear.enabled = true;
    scene.bend.enabled = true;
    scene.structural.damping = scene.shear.damping = 0.03;
    scene.bend.damping = 0.006;
    scene.forces.wind = {3.0, 0.0, 4.0};
    scene.forces.air_drag = 0.001;
    scene.tear_max_stretch = 1.15;
    scene.solver = {integrator, 2e-4};
    return scene;
}

TEST(Determinism, OneTwoAndFourThreadsGiveTheSameStateBitForBit) {
    // The tearing sheet is 24x24: its colours are below the threshold for splitting, so use
    // a sheet big enough that every colour is split between the threads.
    const Scene scene = large_tearing_sheet(Layout::grid, Integrator::symplectic_euler);
    std::uint64_t reference = 0;
    std::size_t torn = 0;
    for (int threads : {1, 2, 4}) {
        Simulation simulation(scene);
        simulation.set_thread_count(threads);
        ASSERT_EQ(simulation.thread_count(), threads);
        torn = 0;
        for (int s = 0; s < 400; ++s) {
            const StepReport report = simulation.step();
            ASSERT_FALSE(report.diverged());
            torn += report.springs_torn;
        }
        const std::uint64_t hash = hash_state(simulation.cloth());
        if (threads == 1) reference = hash;
        EXPECT_EQ(hash, reference) << threads << " threads";
    }
    EXPECT_GT(torn, 0u);  // tearing (and the recolouring after it) is part of the run
}

// The large tearing sheet (structured force pass), or its offset-layout twin (general pass),
// run for 400 steps with `threads` threads; 0 if it diverged.
std::uint64_t large_sheet_hash(int threads, Layout layout = Layout::grid,
                               Integrator integrator = Integrator::symplectic_euler,
                               const SimulationOptions& options = {}) {
    Simulation simulation(large_tearing_sheet(layout, integrator), options);
    simulation.set_thread_count(threads);
    for (int s = 0; s < 400; ++s)
        if (simulation.step().diverged()) return 0;
    return hash_state(simulation.cloth());
}

TEST(Determinism, EveryIntegratorGivesTheSameBitsOnOneAndTwoThreads) {
    // The parallel particle loops of each method and the structured force pass at its stage
    // states.
    for (Integrator integrator : testing::all_integrators) {
        if (integrator == Integrator::explicit_euler) continue;  // diverges in this wind
        const std::uint64_t one = large_sheet_hash(1, Layout::grid, integrator);
        ASSERT_NE(one, 0u) << integrator_name(integrator);
        EXPECT_EQ(large_sheet_hash(2, Layout::grid, integrator), one)
            << integrator_name(integrator);
    }
}

TEST(Determinism, TheGeneralPassOnAnOffsetSheetGivesTheSameBitsOnAnyThreadCount) {
    testing::expect_same_bits_on_any_thread_count(
        [](int threads) { return large_sheet_hash(threads, Layout::offset); });
}

TEST(Determinism, TheDrapeOnTheBallWithSelfCollisionGivesTheSameBitsOnAnyThreadCount) {
    // 64² particles: enough for the contacts with the ball and the ground, the moves the
    // self-collision pass measures and its list's rebuild to be split between threads. 0.22 s:
    // the sheet has reached the ball (0.05 m below it at the start) and folds over it.
    testing::expect_same_bits_on_any_thread_count([](int threads) -> std::uint64_t {
        SceneLoadResult loaded =
            load_scene_file(WEFT_SOURCE_DIR "/assets/scenes/drape_self_collision_64.toml");
        EXPECT_TRUE(loaded.ok());
        Simulation simulation(*loaded.scene);
        simulation.set_thread_count(threads);
        std::size_t contacts = 0;
        for (int s = 0; s < 1200; ++s) {
            const StepReport report = simulation.step();
            if (report.diverged()) return 0;
            contacts += report.contacts;
        }
        EXPECT_GT(contacts, 0u);
        return hash_state(simulation.cloth());
    });
}

TEST(Determinism, TheDrapesContactsOnTheFusedStepsRowsGiveTheSeparatePassesBits) {
    // With the fused step, each thread resolves the contacts and measures the moves of the
    // rows it has just stepped (simulation.cpp, OnSteppedRows); without it, the step, the
    // contacts and self-collision's measure are three passes. Same state, same contacts.
    auto run = [](bool fused) {
        SceneLoadResult loaded =
            load_scene_file(WEFT_SOURCE_DIR "/assets/scenes/drape_self_collision_64.toml");
        EXPECT_TRUE(loaded.ok());
        Simulation simulation(*loaded.scene, testing::fused_grid_steps(fused));
        simulation.set_thread_count(2);
        std::size_t contacts = 0;
        for (int s = 0; s < 1200; ++s) {
            const StepReport report = simulation.step();
            if (report.diverged()) break;
            contacts += report.contacts;
        }
        return std::pair{hash_state(simulation.cloth()), contacts};
    };
    const auto fused = run(true);
    const auto separate = run(false);
    EXPECT_GT(fused.second, 1000u);
    EXPECT_EQ(fused, separate);
}

TEST(Determinism, EveryKernelBuildGivesTheSameStateBitForBit) {
    testing::expect_same_bits_on_every_kernel_build([](const SimulationOptions& options) {
        return large_sheet_hash(2, Layout::grid, Integrator::symplectic_euler, options);
    });
}

TEST(Determinism, TheHashSeesEveryBit) {
    Scene scene;
    scene.cloth.rows = 3;
    scene.cloth.cols = 3;
    Simulation simulation(scene);
    const std::uint64_t before = hash_state(simulation.cloth());
    simulation.edit_cloth().velocities[4].z = std::nextafter(0.0, 1.0);  // the smallest change
    EXPECT_NE(hash_state(simulation.cloth()), before);
}

}  // namespace
}  // namespace weft
