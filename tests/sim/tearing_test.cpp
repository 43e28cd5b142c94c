// Tearing: springs past the limit break, all judged on one state, survivors keep their order.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "sim/build/cloth_builder.h"
#include "sim/constraints/tearing.h"
#include "sim/core/simulation.h"
#include "test_scenes.h"

namespace weft {
namespace {

TEST(Tearing, BreaksExactlyTheSpringsPastTheLimit) {
    Scene scene;
    scene.cloth.rows = 1;
    scene.cloth.cols = 4;
    scene.cloth.spacing = 1.0;
    Cloth cloth = build_grid_cloth(scene);
    // Spring 0-1 at 1.7x, spring 1-2 at 1.5x (after particle 1 moved), spring 2-3 at 1.6x + ε.
    cloth.positions = {{0, 0, 0}, {1.7, 0, 0}, {3.2, 0, 0}, {4.8 + 1e-9, 0, 0}};
    EXPECT_EQ(tear_overstretched_springs(cloth, 1.6), 2u);
    const auto& survivors = cloth.topology().spring_groups[0].springs;
    ASSERT_EQ(survivors.size(), 1u);
    EXPECT_EQ(survivors[0].i, 1u);
    EXPECT_EQ(survivors[0].j, 2u);
}

TEST(Tearing, AHeavyPullTearsTheSheetInsteadOfDiverging) {
    Scene scene;
    scene.cloth.rows = 10;
    scene.cloth.cols = 10;
    scene.cloth.pin_preset = PinPreset::top_row;
    scene.forces.gravity = {0.0, -2000.0, 0.0};  // far more than the springs can hold
    scene.tear_max_stretch = 1.5;
    Simulation simulation(scene);
    const std::size_t initial = simulation.cloth().spring_count();
    std::size_t torn = 0;
    for (int s = 0; s < 3000; ++s) {
        StepReport report = simulation.step();
        ASSERT_FALSE(report.diverged()) << *report.divergence;
        torn += report.springs_torn;
    }
    EXPECT_GT(torn, 0u);
    EXPECT_EQ(simulation.cloth().spring_count(), initial - torn);
    // Every triangle left has all of its structural edges (and so is drawn and pickable).
    const Cloth& cloth = simulation.cloth();
    EXPECT_LT(cloth.topology().triangles.size(), 2u * 9 * 9);
    auto is_spring = [&](std::uint32_t a, std::uint32_t b) {
        for (const Spring& s : cloth.topology().spring_groups[0].springs)
            if ((s.i == a && s.j == b) || (s.i == b && s.j == a)) return true;
        return false;
    };
    for (const Triangle& t : cloth.topology().triangles) {
        // Each grid triangle has one horizontal and one vertical structural edge and a diagonal.
        int structural_edges = is_spring(t.a, t.b) + is_spring(t.b, t.c) + is_spring(t.c, t.a);
        EXPECT_EQ(structural_edges, 2);
    }
    // What is left is within the limit.
    for (const Spring& s : simulation.cloth().topology().spring_groups[0].springs)
        EXPECT_LE(
            glm::length(simulation.cloth().positions[s.j] - simulation.cloth().positions[s.i]),
            1.5 * s.rest_length);
}

}  // namespace
}  // namespace weft
