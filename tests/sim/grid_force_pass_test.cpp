// The structured force pass (per-direction stencils over the grid) against the general one,
// spring by spring: the same forces to rounding, dead springs masked, any thread count and
// every kernel build giving the same bits.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

#include "loaded_cloth.h"
#include "sim/build/cloth_builder.h"
#include "sim/build/topology_edits.h"
#include "sim/core/force_pass.h"
#include "sim/grid/grid_force_pass.h"
#include "sim/integrators/integrator.h"
#include "test_scenes.h"

namespace weft {
namespace {

Scene grid_scene(int rows, int cols) {
    return testing::three_family_scene(rows, cols, 0.03);
}

using testing::same_bits;
using testing::windy_field;

void scramble(Cloth& cloth, unsigned seed) {
    testing::scramble(cloth, seed, 0.008);
}

std::vector<Vec3> forces_of(const Cloth& cloth, const ForceField& field, WorkerPool* pool = nullptr,
                            SimdLevel level = supported_simd_level()) {
    std::vector<Vec3> forces(cloth.particle_count());
    accumulate_forces(cloth, field, cloth.positions, cloth.velocities, forces, pool, level);
    return forces;
}

// The general pass's forces: the same cloth without its stencil.
std::vector<Vec3> general_forces_of(Cloth cloth, const ForceField& field) {
    cloth.edit_topology().grid_stencil = GridStencil{};
    return forces_of(cloth, field);
}

// Each particle's force agrees with the general pass's to a few rounding errors of the
// largest spring force that acts on it (the sums run in another order, and u = d (1/l)).
void expect_same_to_rounding(const Cloth& cloth, const std::vector<Vec3>& grid,
                             const std::vector<Vec3>& general) {
    std::vector<double> largest_term(cloth.particle_count(), 0.0);
    for (const SpringGroup& group : cloth.topology().spring_groups) {
        for (const Spring& s : group.springs) {
            const Vec3 d = cloth.positions[s.j] - cloth.positions[s.i];
            const double term =
                group.stiffness * std::abs(glm::length(d) - s.rest_length) +
                group.damping * glm::length(cloth.velocities[s.j] - cloth.velocities[s.i]);
            largest_term[s.i] = std::max(largest_term[s.i], term);
            largest_term[s.j] = std::max(largest_term[s.j], term);
        }
    }
    for (std::size_t p = 0; p < cloth.particle_count(); ++p) {
        const double scale = largest_term[p] + glm::length(general[p]) + 1e-300;
        ASSERT_LE(glm::length(grid[p] - general[p]), 1e-14 * scale) << "particle " << p;
    }
}

TEST(GridForcePass, TheGridBuilderGivesAStencilAndTheOffsetLayoutDoesNot) {
    Scene scene = grid_scene(6, 7);
    EXPECT_TRUE(grid_stencil_usable(build_grid_cloth(scene)));
    EXPECT_EQ(build_grid_cloth(scene).topology().grid_stencil.directions.size(), 6u);
    scene.cloth.layout = Layout::offset;
    EXPECT_FALSE(grid_stencil_usable(build_cloth(scene)));  // the general pass handles it
}

TEST(GridForcePass, MatchesTheGeneralPassToRounding) {
    for (auto [rows, cols] :
         {std::pair{1, 1}, {1, 9}, {9, 1}, {2, 2}, {3, 5}, {17, 23}, {40, 33}}) {
        Cloth cloth = build_grid_cloth(grid_scene(rows, cols));
        scramble(cloth, static_cast<unsigned>(rows * 100 + cols));
        ASSERT_TRUE(grid_stencil_usable(cloth));
        SCOPED_TRACE(std::to_string(rows) + "x" + std::to_string(cols));
        expect_same_to_rounding(cloth, forces_of(cloth, windy_field()),
                                general_forces_of(cloth, windy_field()));
    }
}

TEST(GridForcePass, MatchesTheGeneralPassWithSomeFamiliesAbsent) {
    Scene scene = grid_scene(12, 10);
    scene.shear.enabled = false;
    Cloth no_shear = build_grid_cloth(scene);
    scramble(no_shear, 3);
    ASSERT_EQ(no_shear.topology().grid_stencil.directions.size(), 4u);
    expect_same_to_rounding(no_shear, forces_of(no_shear, ForceField{}),
                            general_forces_of(no_shear, ForceField{}));
    scene.bend.enabled = false;
    Cloth structural_only = build_grid_cloth(scene);
    scramble(structural_only, 4);
    expect_same_to_rounding(structural_only, forces_of(structural_only, windy_field()),
                            general_forces_of(structural_only, windy_field()));
}

TEST(GridForcePass, DeadSpringsAreMaskedLikeRemovedOnes) {
    Cloth cloth = build_grid_cloth(grid_scene(20, 20));
    scramble(cloth, 5);
    // Cut a diagonal line of springs of every family, as tearing or the cut tool would.
    const std::size_t removed =
        remove_springs_if(cloth, [](const Spring& s) { return (s.i / 20 + s.i % 20) % 7 == 3; });
    ASSERT_GT(removed, 100u);
    ASSERT_TRUE(grid_stencil_usable(cloth));  // still the structured pass, with masks
    expect_same_to_rounding(cloth, forces_of(cloth, windy_field()),
                            general_forces_of(cloth, windy_field()));
}

TEST(GridForcePass, CoincidentEndsExertNoForceAndMakeNoNaN) {
    Scene scene = grid_scene(4, 4);
    Cloth cloth = build_grid_cloth(scene);
    cloth.positions[5] = cloth.positions[6];  // a structural spring of zero length
    const std::vector<Vec3> grid = forces_of(cloth, ForceField{});
    for (const Vec3& f : grid) ASSERT_TRUE(std::isfinite(f.x + f.y + f.z));
    expect_same_to_rounding(cloth, grid, general_forces_of(cloth, ForceField{}));
}

TEST(GridForcePass, StaleStencilFallsBackToTheGeneralPass) {
    Cloth cloth = build_grid_cloth(grid_scene(5, 5));
    cloth.edit_topology()
        .spring_groups[0]
        .springs.pop_back();  // edited behind topology_edits' back
    EXPECT_FALSE(grid_stencil_usable(cloth));
}

TEST(GridForcePass, AnyThreadCountGivesTheSameBits) {
    // Big enough for the rows to be split (4096 particles or more), with an odd row count.
    Cloth cloth = build_grid_cloth(grid_scene(71, 64));
    scramble(cloth, 9);
    remove_springs_if(cloth, [](const Spring& s) { return s.i % 97 == 5; });
    const std::vector<Vec3> one = forces_of(cloth, windy_field());
    for (int threads : {2, 3, 4, 7}) {
        WorkerPool pool(threads);
        EXPECT_TRUE(same_bits(forces_of(cloth, windy_field(), &pool), one)) << threads;
    }
}

TEST(GridForcePass, EveryKernelBuildGivesTheSameBits) {
    if (supported_simd_level() == SimdLevel::baseline) GTEST_SKIP() << "no AVX2 on this CPU";
    Cloth cloth = build_grid_cloth(grid_scene(33, 29));
    scramble(cloth, 13);
    std::vector<Vec3> baseline;
    baseline = forces_of(cloth, windy_field(), nullptr, SimdLevel::baseline);
    for (SimdLevel level : {SimdLevel::avx2, SimdLevel::avx512}) {
        if (level > supported_simd_level()) continue;
        EXPECT_TRUE(same_bits(forces_of(cloth, windy_field(), nullptr, level), baseline))
            << simd_level_name(level);
    }
}

TEST(GridForcePass, OverstretchTestFlagsOnlyLiveSpringsPastTheRatio) {
    Cloth cloth = build_grid_cloth(grid_scene(6, 6));
    EXPECT_FALSE(*grid_springs_maybe_longer_than(cloth, 5.0, nullptr, supported_simd_level()));
    cloth.positions[35] += Vec3(0.0, 0.0, 0.2);  // 6.7 spacings away from its neighbours
    EXPECT_TRUE(*grid_springs_maybe_longer_than(cloth, 5.0, nullptr, supported_simd_level()));
    // With every spring of that corner gone, nothing is left to overstretch.
    remove_springs_if(cloth, [](const Spring& s) { return s.j == 35 || s.i == 35; });
    EXPECT_FALSE(*grid_springs_maybe_longer_than(cloth, 5.0, nullptr, supported_simd_level()));
}

// The guard's one pass after a far move gives the next reference's headroom: the same
// numbers as spring by spring over the general arrays, on 1 to 3 threads, dead springs
// (torn or cut) left out.
TEST(GridForcePass, StretchHeadroomIsTheSpringBySpringMinimum) {
    Scene scene = grid_scene(70, 70);  // 4900 particles: enough for the threads
    scene.shear.enabled = true;
    scene.bend.enabled = true;
    Cloth cloth = build_grid_cloth(scene);
    for (std::size_t p = 0; p < cloth.particle_count(); ++p)  // uneven stretch everywhere
        cloth.positions[p] *= 1.0 + 0.3 * std::sin(0.37 * static_cast<double>(p));
    remove_springs_if(cloth, [](const Spring& s) { return s.i % 97 == 0; });
    const double ratio = 5.0;
    double headroom = std::numeric_limits<double>::infinity(), scale = 0.0;
    for (const SpringGroup& group : cloth.topology().spring_groups)
        for (const Spring& spring : group.springs) {
            const double length =
                glm::length(cloth.positions[spring.j] - cloth.positions[spring.i]);
            headroom = std::min(headroom, ratio * spring.rest_length - length);
            scale = std::max(scale, ratio * spring.rest_length);
        }
    for (SimdLevel level : {SimdLevel::baseline, SimdLevel::avx2, SimdLevel::avx512}) {
        if (level > supported_simd_level()) continue;
        for (int threads : {1, 2, 3}) {
            WorkerPool pool(threads);
            const auto grid = grid_stretch_headroom(cloth, ratio, &pool, level);
            ASSERT_TRUE(grid.has_value());
            EXPECT_EQ(grid->headroom, headroom) << threads << simd_level_name(level);
            EXPECT_EQ(grid->scale, scale) << threads << simd_level_name(level);
            EXPECT_EQ(grid->maybe_longer,
                      *grid_springs_maybe_longer_than(cloth, ratio, &pool, level));
        }
    }
    // Past the ratio: flagged, and the headroom negative.
    cloth.positions[35] += Vec3(0.0, 0.0, 2.0);
    const auto far = grid_stretch_headroom(cloth, ratio, nullptr, supported_simd_level());
    EXPECT_TRUE(far->maybe_longer);
    EXPECT_LT(far->headroom, 0.0);
}

// Implicit Euler judges a step by its linearisation's error over the springs it leaves past
// a ratio of their rest length (implicit_euler.cpp): the stencil's pass must give the same
// number as spring by spring over the general arrays, on 1 to 3 threads and every kernel
// build, dead springs left out, and 0 where no spring is past the ratio.
TEST(GridForcePass, LinearisationErrorIsTheSpringBySpringMaximum) {
    Cloth cloth = build_grid_cloth(grid_scene(70, 70));  // 4900 particles: the threads split
    const double ratio = 1.3;
    std::vector<Vec3> start = cloth.positions;
    EXPECT_EQ(*grid_linearisation_error(cloth, start, ratio, nullptr, supported_simd_level()), 0.0);
    // Linearised where the sheet lay flat, ended swirled: stretched past the ratio in places,
    // turned and compressed in others.
    for (std::size_t p = 0; p < cloth.particle_count(); ++p) {
        const double t = 0.37 * static_cast<double>(p);
        start[p] += Vec3(0.004 * std::sin(t), 0.003 * std::cos(1.3 * t), 0.0);
        cloth.positions[p] *= 1.0 + 0.3 * std::sin(t);
        cloth.positions[p].z += 0.01 * std::cos(0.11 * static_cast<double>(p));
    }
    remove_springs_if(cloth, [](const Spring& s) { return s.i % 97 == 0; });
    const double expected = largest_linearisation_error(cloth, start, ratio, nullptr);
    EXPECT_GT(expected, 0.1);  // far from what the step assumed: a step to be taken again
    for (SimdLevel level : {SimdLevel::baseline, SimdLevel::avx2, SimdLevel::avx512}) {
        if (level > supported_simd_level()) continue;
        for (int threads : {1, 2, 3}) {
            WorkerPool pool(threads);
            EXPECT_EQ(*grid_linearisation_error(cloth, start, ratio, &pool, level), expected)
                << threads << " threads, " << simd_level_name(level);
        }
    }
    // Without its stencil, the cloth has no stencil pass.
    cloth.edit_topology().grid_stencil = GridStencil{};
    EXPECT_FALSE(grid_linearisation_error(cloth, start, ratio, nullptr, supported_simd_level()));
}

}  // namespace
}  // namespace weft
