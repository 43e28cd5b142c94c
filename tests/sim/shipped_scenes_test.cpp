// Every scene in assets/scenes, as shipped: the directory is listed, so a scene added later is
// covered without editing this file.
//
// Truth: the scene's own dt against the linear step-limit estimate of its own cloth and
// method (stability_limit.h), the bound the demo's panel warns with in red. A shipped scene
// the panel flags as "may blow up" the moment it loads is a scene that breaks its promise.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "sim/core/simulation.h"
#include "sim/guards/divergence.h"
#include "sim/guards/stability_limit.h"
#include "sim/interaction/grab.h"
#include "sim/scene_io/scene_loader.h"

namespace weft {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> shipped_scenes() {
    std::vector<fs::path> scenes;
    for (const auto& entry :
         fs::directory_iterator(std::string(WEFT_SOURCE_DIR) + "/assets/scenes"))
        if (entry.path().extension() == ".toml") scenes.push_back(entry.path());
    return scenes;
}

// Cloth, not rubber: the shipped scenes of cloth-like materials, run for 3 s from their
// start, have no spring more than 5 % over its rest length. Left out: cloth_256 and
// drape_self_collision_64, the materials of cloth_128 and drape_self_collision at a finer
// grid, for their cost; and the scenes that say in their comments why they stretch more
// (large_rubber_sheet, course_pinned, drape_sphere_128).
TEST(ShippedScenes, TheClothScenesStretchAtMostFivePercentAtRest) {
    for (const char* file :
         {"hanging_sheet.toml", "all_springs.toml", "equilateral_sheet.toml",
          "structural_only.toml", "tearing_sheet.toml", "cloth_128.toml", "skirt.toml",
          "slope.toml", "stiff_sheet.toml", "tablecloth.toml", "round_tablecloth.toml",
          "sheet_on_sphere.toml", "drape_self_collision.toml", "self_fold.toml", "flag.toml",
          "flag_with_hole.toml"}) {
        SceneLoadResult loaded =
            load_scene_file(std::string(WEFT_SOURCE_DIR) + "/assets/scenes/" + file);
        ASSERT_TRUE(loaded.ok()) << file << ": " << loaded.error->message();
        Simulation simulation(*loaded.scene);
        while (simulation.time() < 3.0) ASSERT_FALSE(simulation.step().diverged()) << file;
        EXPECT_LE(largest_stretch_ratio(simulation.cloth()), 1.05) << file;
    }
}

TEST(ShippedScenes, NoneRunsAboveItsOwnStepLimitEstimate) {
    const std::vector<fs::path> scenes = shipped_scenes();
    ASSERT_GE(scenes.size(), 10u);  // the directory was found and read
    for (const fs::path& path : scenes) {
        SceneLoadResult loaded = load_scene_file(path.string());
        ASSERT_TRUE(loaded.ok()) << path << ": " << loaded.error->message();
        const Simulation simulation(*loaded.scene);
        // Implicit Euler's limit is infinite. Explicit Euler's is 0: without damping no step
        // is stable (the panel says so), so a shipped scene with it fails here on purpose;
        // it belongs in a --set override that shows the failure, as stiff_sheet.toml does.
        const double limit = estimated_step_limit(
            simulation.cloth(), simulation.force_field().air_drag, simulation.integrator());
        EXPECT_LE(simulation.dt(), limit)
            << path.filename() << " (" << integrator_name(simulation.integrator()) << "): dt "
            << simulation.dt() * 1e3 << " ms, limit estimate " << limit * 1e3 << " ms";
    }
}

TEST(ShippedScenes, NoneIsFlaggedByTheGuardsInItsFirstHalfSecond) {
    // The divergence and energy guards' false alarms: each scene as shipped, with its own
    // integrator and dt, for its first half second (the fall, the landing, the first swing:
    // where course_pinned.toml's energy grew from nowhere until position Verlet kept its
    // history through the strain limiter's corrections; drape_sphere_128.toml runs longer in
    // ContactsAtTheFrameStep).
    for (const fs::path& path : shipped_scenes()) {
        SceneLoadResult loaded = load_scene_file(path.string());
        ASSERT_TRUE(loaded.ok()) << path << ": " << loaded.error->message();
        Simulation simulation(*loaded.scene);
        while (simulation.time() < 0.5) {
            const StepReport report = simulation.step();
            ASSERT_FALSE(report.diverged()) << path.filename() << " at t = " << simulation.time()
                                            << " s: " << *report.divergence;
        }
    }
}

TEST(ShippedScenes, NoneWithTearingIsFlaggedWhileAHandRipsIt) {
    // The tearing guard's false alarms (runaway_tearing.h): every shipped scene that tears,
    // as shipped, after its first half second, a hand of the panel's largest radius (0.5 m)
    // on the middle of the bottom edge pulled away at 2.3 m/s for two seconds: the hardest
    // stable tearing measured at the scene's limit (121 springs within 0.05 s, away from the
    // hand's own patch). It must tear (so the guard had tears to judge) and never be flagged.
    int scenes_with_tearing = 0;
    for (const fs::path& path : shipped_scenes()) {
        SceneLoadResult loaded = load_scene_file(path.string());
        ASSERT_TRUE(loaded.ok()) << path << ": " << loaded.error->message();
        if (!loaded.scene->tear_max_stretch) continue;
        ++scenes_with_tearing;
        Simulation simulation(*loaded.scene);
        while (simulation.time() < 0.3) ASSERT_FALSE(simulation.step().diverged());
        const Cloth& cloth = simulation.cloth();
        const auto grabbed =
            static_cast<std::uint32_t>((cloth.rows - 1) * cloth.cols + cloth.cols / 2);
        const Vec3 start = cloth.positions[grabbed];
        simulation.start_grab(grab_cloth(cloth, {0, grabbed, 1.0, start}, 0.5));
        std::size_t torn = 0;
        for (int frame = 0; frame < 120; ++frame) {
            const double pulled = frame / 60.0;  // s
            simulation.pull_to(start + pulled * Vec3(0.5, -2.0, 1.0));
            const double frame_end = simulation.time() + 1.0 / 60.0;
            while (simulation.time() < frame_end) {
                const StepReport report = simulation.step();
                torn += report.springs_torn;
                ASSERT_FALSE(report.diverged())
                    << path.filename() << " at t = " << simulation.time()
                    << " s: " << *report.divergence;
            }
        }
        EXPECT_GT(torn, 0u) << path.filename();
    }
    EXPECT_GE(scenes_with_tearing, 1);  // tearing_sheet.toml at least
}

}  // namespace
}  // namespace weft
