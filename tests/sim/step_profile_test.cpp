// The step's profile (step_profile.h): it counts what the run did, it reads no clock when off,
// and it never changes a bit of the state.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "app/profile_text.h"
#include "sim/core/simulation.h"
#include "sim/core/state_hash.h"
#include "sim/interaction/grab.h"
#include "sim/scene_io/scene_loader.h"

namespace weft {
namespace {

// cloth_128.toml's material at 32², by implicit Euler, grabbed at its bottom middle after 10
// steps and lifted fast enough that some steps split.
struct LiftedSheet {
    Simulation simulation;
    StepProfile profile;
    std::uint64_t iterations = 0, splits = 0, newton = 0, stopped_early = 0, held = 0;
    StepProfile at_step_20;  // the profile as it was after 20 steps
    std::uint64_t iterations_after_20 = 0;
    explicit LiftedSheet(bool profiling)
        : simulation(*load_scene_file(WEFT_SOURCE_DIR "/assets/scenes/cloth_128.toml",
                                      {"cloth.rows=32", "cloth.cols=32",
                                       "cloth.spacing=0.0371",           // m: 1.15 m / 31
                                       "cloth.particle_mass=0.000275"})  // kg: 0.2 kg/m² × spacing²
                          .scene) {
        simulation.set_profiling(profiling);
    }
    void run() {
        const std::uint32_t grabbed = 31 * 32 + 16;
        for (int step = 0; step < 40; ++step) {
            if (step == 10) {
                const Vec3 at = simulation.cloth().positions[grabbed];
                simulation.start_grab(grab_cloth(simulation.cloth(), {0, grabbed, 1.0, at}, 0.08));
            }
            if (step >= 10)
                simulation.pull_to(simulation.cloth().positions[grabbed] +
                                   Vec3(0.0, 0.08, 0.03));  // 4.9 m/s up
            const std::uint64_t evaluations = simulation.force_evaluations();
            const StepReport report = simulation.step();
            ASSERT_FALSE(report.diverged()) << step;
            iterations += static_cast<std::uint64_t>(simulation.last_linear_solve().iterations);
            splits += static_cast<std::uint64_t>(simulation.last_step_splits());
            newton += static_cast<std::uint64_t>(simulation.last_step_newton_iterations());
            stopped_early += static_cast<std::uint64_t>(simulation.last_step_tries_stopped_early());
            held += report.held ? 1 : 0;
            if (!simulation.profiling()) {
                EXPECT_EQ(report.times.total(), 0.0) << step;
            }
            profile.add(report.times, report.held, report.hand_slipped,
                        simulation.force_evaluations() - evaluations,
                        simulation.last_linear_solve().iterations, simulation.last_step_splits(),
                        simulation.last_step_newton_iterations(),
                        simulation.last_step_tries_stopped_early());
            if (step == 19) at_step_20 = profile;
            if (step >= 20)
                iterations_after_20 +=
                    static_cast<std::uint64_t>(simulation.last_linear_solve().iterations);
        }
    }
};

TEST(StepProfile, CountsWhatTheStepsDidAndChangesNoBit) {
    LiftedSheet plain(false), profiled(true);
    plain.run();
    profiled.run();
    EXPECT_EQ(hash_state(plain.simulation.cloth()), hash_state(profiled.simulation.cloth()));

    const StepProfile& profile = profiled.profile;
    EXPECT_EQ(profile.steps, 40u);
    EXPECT_EQ(profile.held_steps, profiled.held);
    EXPECT_GT(profile.held_steps, 0u);
    EXPECT_EQ(profile.solver_iterations, profiled.iterations);
    EXPECT_EQ(profile.splits, profiled.splits);
    EXPECT_EQ(profile.newton_iterations, profiled.newton);
    EXPECT_GT(profile.splits + profile.newton_iterations, 0u);
    EXPECT_EQ(profile.tries_stopped_early, profiled.stopped_early);
    // Under the hand the tries that fail mostly fail at the early judgement; every try
    // evaluates the forces once, and each step keeps one.
    EXPECT_GT(profile.tries_stopped_early, 0u);
    EXPECT_LE(profile.tries_stopped_early, profile.force_evaluations - profile.steps);
    EXPECT_EQ(profile.force_evaluations, profiled.simulation.force_evaluations());
    // Off, no clock is read: nothing is summed. (How long the phases took is the
    // benchmarks' to say, not a test's.)
    EXPECT_EQ(plain.profile.seconds.total(), 0.0);

    // The panel's last second: what was added since a copy taken before.
    const StepProfile later = profile.since(profiled.at_step_20);
    EXPECT_EQ(later.steps, 20u);
    EXPECT_EQ(later.solver_iterations, profiled.iterations_after_20);
    EXPECT_NEAR(later.seconds.total() + profiled.at_step_20.seconds.total(),
                profile.seconds.total(), 1e-12);
    const std::string panel = app::profile_panel_text(later);
    EXPECT_EQ(
        panel.rfind("20 steps, " + std::to_string(later.held_steps) + " held by the hand\n", 0), 0u)
        << panel;
    EXPECT_NE(panel.find("a step: "), std::string::npos) << panel;

    const std::string text = app::profile_text(profile, 1.0 / 60.0, 2);
    EXPECT_NE(text.find("profile: 40 steps of 16.67 ms on 2 threads"), std::string::npos) << text;
    EXPECT_NE(
        text.find("implicit solve: " + std::to_string(profile.solver_iterations) + " iterations"),
        std::string::npos)
        << text;
}

}  // namespace
}  // namespace weft
