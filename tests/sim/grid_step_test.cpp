// The fused symplectic Euler step (grid_force_pass.h: the step taken inside the structured
// force pass) against the separate force pass and step loop it replaces: the same bits, the
// same findings of the divergence guard's sweep, and no step taken where the pass does not
// compute every force.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

#include "loaded_cloth.h"
#include "sim/build/cloth_builder.h"
#include "sim/build/topology_edits.h"
#include "sim/collision/colliders.h"
#include "sim/core/simulation.h"
#include "sim/core/state_hash.h"
#include "sim/grid/grid_force_pass.h"
#include "sim/integrators/integrator.h"
#include "sim/interaction/grab.h"
#include "sim/scene_io/scene_loader.h"
#include "test_scenes.h"

namespace weft {
namespace {

// Big enough for the rows to be split between threads (4096 particles or more), an odd row
// count, all three families, its top corners pinned.
Cloth loaded_sheet() {
    Cloth cloth = testing::three_family_sheet(71, 64);
    testing::scramble(cloth, 21, 0.005);
    for (std::uint32_t p : cloth.topology().pinned)
        cloth.velocities[p] = Vec3(0.0);                                      // pins stay put
    remove_springs_if(cloth, [](const Spring& s) { return s.i % 89 == 3; });  // torn ones
    return cloth;
}

using testing::same_bits;
using testing::windy_field;

constexpr double step_dt = 2e-4;  // s

// The separate path: the force pass, then step_symplectic_euler's own loop.
Cloth separately_stepped(Cloth cloth, const ForceField& field) {
    IntegratorWorkspace work;
    work.settings.options.fused_grid_steps = false;
    work.resize(cloth.particle_count(), Integrator::symplectic_euler);
    step_symplectic_euler(cloth, field, step_dt, work);
    return cloth;
}

Cloth fused_stepped(Cloth cloth, const ForceField& field, WorkerPool* pool,
                    const SweepRequest* sweep = nullptr, ParticleSweep* found = nullptr) {
    std::vector<Vec3> next_positions, next_velocities;
    EXPECT_TRUE(step_grid_symplectic_euler(cloth, field, step_dt, next_positions, next_velocities,
                                           sweep, found, pool, supported_simd_level()));
    return cloth;
}

TEST(FusedGridStep, GivesTheSeparateStepsBitsOnAnyThreadCount) {
    const Cloth start = loaded_sheet();
    const Cloth expected = separately_stepped(start, windy_field());
    ASSERT_FALSE(same_bits(expected.positions, start.positions));  // it did move
    for (int threads : {1, 2, 3}) {
        WorkerPool pool(threads);
        const Cloth fused = fused_stepped(start, windy_field(), &pool);
        EXPECT_TRUE(same_bits(fused.positions, expected.positions)) << threads;
        EXPECT_TRUE(same_bits(fused.velocities, expected.velocities)) << threads;
    }
    // Pinned particles stay exactly where they were.
    const Cloth fused = fused_stepped(start, windy_field(), nullptr);
    ASSERT_FALSE(start.topology().pinned.empty());
    for (std::uint32_t p : start.topology().pinned)
        EXPECT_EQ(fused.positions[p], start.positions[p]);
}

TEST(FusedGridStep, WithoutAirDragToo) {
    const Cloth start = loaded_sheet();
    ForceField still;
    const Cloth expected = separately_stepped(start, still);
    EXPECT_TRUE(same_bits(fused_stepped(start, still, nullptr).positions, expected.positions));
}

// The guard's sweep done in the pass finds what sweep_particles finds on the new state.
TEST(FusedGridStep, ItsSweepFindsWhatTheSeparateSweepFinds) {
    const Cloth start = loaded_sheet();
    const Cloth moved = separately_stepped(start, windy_field());
    // The median squared distance a particle moved in the step: some are farther, some not.
    std::vector<double> distances;
    for (std::size_t p = 0; p < start.particle_count(); ++p) {
        const Vec3 d = moved.positions[p] - start.positions[p];
        distances.push_back(d.x * d.x + d.y * d.y + d.z * d.z);
    }
    std::nth_element(distances.begin(), distances.begin() + distances.size() / 2, distances.end());
    const double median = distances[distances.size() / 2];
    WorkerPool pool(2);
    for (double limit : {median, 1e3 * median, std::numeric_limits<double>::infinity()}) {
        const SweepRequest request{start.positions.data(), limit};
        ParticleSweep found;
        fused_stepped(start, windy_field(), &pool, &request, &found);
        const ParticleSweep expected =
            sweep_particles(moved.positions, start.positions, moved.velocities, limit, nullptr,
                            supported_simd_level());
        EXPECT_EQ(found.moved, expected.moved) << limit;
        EXPECT_EQ(found.non_finite, expected.non_finite) << limit;
        EXPECT_EQ(found.moved, limit == median) << limit;
        EXPECT_FALSE(found.non_finite);
    }
    // A non-finite velocity anywhere reaches the new state, and the sweep says so.
    Cloth broken = start;
    broken.velocities[start.particle_count() - 7].y = std::numeric_limits<double>::quiet_NaN();
    const SweepRequest request{start.positions.data(), std::numeric_limits<double>::infinity()};
    ParticleSweep found;
    fused_stepped(broken, windy_field(), &pool, &request, &found);
    EXPECT_TRUE(found.non_finite);
}

// The sweep tests each coordinate on its own (no shuffles): it must flag every particle
// that moved the limit or more, in any direction, and none that moved under 1/√3 of it.
TEST(FusedGridStep, ItsSweepFlagsEveryParticleThatMovedTheLimitAndNoneUnderAThirdOfIt) {
    const double limit = 0.01;  // m
    for (SimdLevel level : {SimdLevel::baseline, SimdLevel::avx2, SimdLevel::avx512}) {
        if (level > supported_simd_level()) continue;
        int cases = 0;
        for (int i = 0; i < 400; ++i) {
            // Directions spread over the sphere, diagonals included (the hardest case: each
            // component is limit / √3 at |d| = limit); lengths from 0.5 to 1.5 limits.
            const double z = -1.0 + 2.0 * ((i * 37) % 101) / 100.0;
            const double angle = 0.731 * i;
            Vec3 direction(std::sqrt(1.0 - z * z) * std::cos(angle),
                           std::sqrt(1.0 - z * z) * std::sin(angle), z);
            if (i % 8 == 0) direction = glm::normalize(Vec3(1.0, i % 16 ? -1.0 : 1.0, 1.0));
            const double length = limit * (0.5 + (i % 41) / 40.0);
            // A row of 5 particles, the moved one among four that stay (any lane).
            std::vector<Vec3> reference(5, Vec3(0.25, -0.5, 1.0));
            std::vector<Vec3> positions = reference;
            positions[i % 5] += length * direction;
            const std::vector<Vec3> velocities(5, Vec3(0.1, -0.2, 0.3));
            const ParticleSweep found =
                sweep_particles(positions, reference, velocities, limit * limit, nullptr, level);
            const Vec3 d = positions[i % 5] - reference[i % 5];
            const double moved_squared = glm::dot(d, d);
            if (moved_squared >= limit * limit) {
                EXPECT_TRUE(found.moved) << i;
            }
            if (moved_squared < limit * limit / 3.0 * (1.0 - 1e-6)) {
                EXPECT_FALSE(found.moved) << i;
            }
            EXPECT_FALSE(found.non_finite);
            cases += moved_squared >= limit * limit ? 1 : 0;
        }
        EXPECT_GT(cases, 100) << simd_level_name(level);
    }
}

// Repulsion contacts are forces the pass does not compute: it declines the step and leaves
// the state alone.
TEST(FusedGridStep, DeclinesWhenTheFieldHasForcesThePassDoesNotCompute) {
    Cloth cloth = loaded_sheet();
    const Cloth start = cloth;
    std::vector<Vec3> next_positions, next_velocities;
    Collider sphere;
    sphere.radius = 0.2;
    sphere.response = ContactResponse::repulsion;
    ForceField field = windy_field();
    field.colliders = {&sphere, 1};
    EXPECT_FALSE(step_grid_symplectic_euler(cloth, field, step_dt, next_positions, next_velocities,
                                            nullptr, nullptr, nullptr, supported_simd_level()));
    EXPECT_TRUE(same_bits(cloth.positions, start.positions));
    EXPECT_TRUE(same_bits(cloth.velocities, start.velocities));
}

// Whole simulations, with the guard taking the sweep from the step: the same states and the
// same verdicts as with the separate step and sweep — on the sphere (contacts move particles
// after the step, so the step's sweep must not be used then) and on a sheet that diverges.
std::pair<std::uint64_t, std::string> run(const char* scene_file,
                                          std::vector<std::string> overrides, bool fused) {
    SceneLoadResult loaded = load_scene_file(scene_file, overrides);
    EXPECT_TRUE(loaded.ok()) << loaded.error->message();
    Simulation simulation(*loaded.scene, testing::fused_grid_steps(fused));
    std::string verdict;
    for (int s = 0; s < 1500 && verdict.empty(); ++s) {
        const StepReport report = simulation.step();
        if (report.diverged()) verdict = *report.divergence + " at step " + std::to_string(s);
    }
    return {hash_state(simulation.cloth()), verdict};
}

TEST(FusedGridStep, SimulationsGiveTheSameStatesAndVerdicts) {
    const char* sphere = WEFT_SOURCE_DIR "/assets/scenes/sheet_on_sphere.toml";
    const auto on_sphere = run(sphere, {"solver.integrator=\"symplectic-euler\""}, true);
    EXPECT_EQ(on_sphere, run(sphere, {"solver.integrator=\"symplectic-euler\""}, false));
    EXPECT_TRUE(on_sphere.second.empty()) << on_sphere.second;

    const char* hanging = WEFT_SOURCE_DIR "/assets/scenes/hanging_sheet.toml";
    const std::vector<std::string> too_long = {"solver.integrator=\"symplectic-euler\"",
                                               "solver.dt=0.004"};
    const auto diverging = run(hanging, too_long, true);
    EXPECT_EQ(diverging, run(hanging, too_long, false));
    EXPECT_FALSE(diverging.second.empty());
}

}  // namespace
}  // namespace weft
