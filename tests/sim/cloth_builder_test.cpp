// The grid builder: particle placement, pins, and exactly the springs the scene asks for.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "sim/build/cloth_builder.h"
#include "sim/core/simulation.h"

namespace weft {
namespace {

std::size_t group_size(const Cloth& cloth, SpringFamily family) {
    const SpringGroup* group = cloth.find_group(family);
    return group ? group->springs.size() : 0;
}

TEST(GridBuilder, AbsentSpringFamiliesAddNoSprings) {
    Scene scene;
    scene.cloth.rows = 6;
    scene.cloth.cols = 9;
    const Cloth structural_only = build_grid_cloth(scene);
    ASSERT_EQ(structural_only.topology().spring_groups.size(), 1u);
    EXPECT_EQ(group_size(structural_only, SpringFamily::structural), 6u * 8 + 5u * 9);
    EXPECT_EQ(structural_only.find_group(SpringFamily::shear), nullptr);
    EXPECT_EQ(structural_only.find_group(SpringFamily::bend), nullptr);

    scene.shear.enabled = true;
    scene.bend.enabled = true;
    const Cloth all = build_grid_cloth(scene);
    EXPECT_EQ(group_size(all, SpringFamily::shear), 2u * 5 * 8);
    EXPECT_EQ(group_size(all, SpringFamily::bend), 6u * 7 + 4u * 9);
}

TEST(GridBuilder, RestLengthsAreTheFlatDistances) {
    Scene scene;
    scene.cloth.rows = 4;
    scene.cloth.cols = 5;
    scene.cloth.spacing = 0.2;
    scene.shear.enabled = true;
    scene.bend.enabled = true;
    const Cloth cloth = build_grid_cloth(scene);
    const double expected[] = {0.2, 0.2 * std::sqrt(2.0), 0.4};
    for (const SpringGroup& group : cloth.topology().spring_groups)
        for (const Spring& spring : group.springs)
            EXPECT_NEAR(spring.rest_length, expected[static_cast<int>(group.family)], 1e-15);
}

TEST(GridBuilder, PlacesParticlesByOrientationFromTheOrigin) {
    Scene scene;
    scene.cloth.rows = 3;
    scene.cloth.cols = 4;
    scene.cloth.spacing = 0.5;
    scene.cloth.origin = {1.0, 2.0, 3.0};
    const Cloth vertical = build_grid_cloth(scene);
    EXPECT_EQ(vertical.positions[2 * 4 + 3], Vec3(1.0 + 1.5, 2.0 - 1.0, 3.0));
    scene.cloth.orientation = Orientation::horizontal;
    const Cloth horizontal = build_grid_cloth(scene);
    EXPECT_EQ(horizontal.positions[2 * 4 + 3], Vec3(1.0 + 1.5, 2.0, 3.0 + 1.0));
}

TEST(GridBuilder, PinPresetsPinExactlyTheirParticles) {
    Scene scene;
    scene.cloth.rows = 3;
    scene.cloth.cols = 4;
    EXPECT_EQ(build_grid_cloth(scene).topology().pinned, (std::vector<std::uint32_t>{0, 3}));
    scene.cloth.pin_preset = PinPreset::top_row;
    EXPECT_EQ(build_grid_cloth(scene).topology().pinned, (std::vector<std::uint32_t>{0, 1, 2, 3}));
    scene.cloth.pin_preset = PinPreset::none;
    EXPECT_TRUE(build_grid_cloth(scene).topology().pinned.empty());
    scene.cloth.pin_preset = PinPreset::list;
    scene.cloth.pin_list = {{2, 1}, {1, 3}};
    const Cloth listed = build_grid_cloth(scene);
    EXPECT_EQ(listed.topology().pinned, (std::vector<std::uint32_t>{7, 9}));
    EXPECT_EQ(listed.topology().inverse_masses[7], 0.0);
    EXPECT_EQ(listed.topology().inverse_masses[0], 1.0 / scene.cloth.particle_mass);
}

TEST(GridBuilder, TrianglesTileEveryCellFacingTheFront) {
    Scene scene;
    scene.cloth.rows = 3;
    scene.cloth.cols = 3;
    const Cloth cloth = build_grid_cloth(scene);
    ASSERT_EQ(cloth.topology().triangles.size(), 2u * 2 * 2);
    double area = 0.0;
    for (const Triangle& t : cloth.topology().triangles) {
        const Vec3 normal = glm::cross(cloth.positions[t.b] - cloth.positions[t.a],
                                       cloth.positions[t.c] - cloth.positions[t.a]);
        EXPECT_GT(normal.z, 0.0);  // counter-clockwise seen from +z, the front of a vertical sheet
        area += 0.5 * glm::length(normal);
    }
    EXPECT_NEAR(area, 4 * scene.cloth.spacing * scene.cloth.spacing, 1e-15);
}

}  // namespace
}  // namespace weft

namespace weft {
namespace {

Scene offset_scene(int rows, int cols) {
    Scene scene;
    scene.cloth.rows = rows;
    scene.cloth.cols = cols;
    scene.cloth.spacing = 0.1;
    scene.cloth.layout = Layout::offset;
    scene.shear.enabled = true;
    scene.bend.enabled = true;
    return scene;
}

TEST(OffsetBuilder, StructuralSpringsAllHaveTheSpacingAsRestLength) {
    const Cloth cloth = build_offset_cloth(offset_scene(9, 8));
    const double expected[] = {0.1, 0.1 * std::sqrt(3.0), 0.2};  // structural, shear, bend
    for (const SpringGroup& group : cloth.topology().spring_groups) {
        ASSERT_FALSE(group.springs.empty());
        for (const Spring& s : group.springs)
            EXPECT_NEAR(s.rest_length, expected[static_cast<int>(group.family)], 1e-15)
                << spring_family_name(group.family) << " " << s.i << "-" << s.j;
    }
}

TEST(OffsetBuilder, InnerParticlesHaveSixNeighboursOfEachFamily) {
    const Cloth cloth = build_offset_cloth(offset_scene(9, 9));
    for (const SpringGroup& group : cloth.topology().spring_groups) {
        std::vector<int> degree(cloth.particle_count(), 0);
        for (const Spring& s : group.springs) ++degree[s.i], ++degree[s.j];
        EXPECT_EQ(degree[4 * 9 + 4], 6) << spring_family_name(group.family);  // the centre
        EXPECT_EQ(degree[5 * 9 + 4], 6) << spring_family_name(group.family);  // an odd row
    }
}

TEST(OffsetBuilder, TrianglesAreEquilateralFrontFacingAndTileTheSheet) {
    const Cloth cloth = build_offset_cloth(offset_scene(7, 6));
    // Every row pair holds 2 (cols - 1) triangles.
    ASSERT_EQ(cloth.topology().triangles.size(), 6u * 2 * 5);
    double area = 0.0;
    for (const Triangle& t : cloth.topology().triangles) {
        const Vec3 a = cloth.positions[t.a], b = cloth.positions[t.b], c = cloth.positions[t.c];
        for (double side : {glm::length(b - a), glm::length(c - b), glm::length(a - c)})
            EXPECT_NEAR(side, 0.1, 1e-15);
        const Vec3 normal = glm::cross(b - a, c - a);
        EXPECT_GT(normal.z, 0.0);
        area += 0.5 * glm::length(normal);
    }
    EXPECT_NEAR(area, 60 * std::sqrt(3.0) / 4.0 * 0.01, 1e-12);
}

TEST(OffsetBuilder, TheSimulationRunsTheOffsetLayout) {
    Scene scene = offset_scene(12, 12);
    scene.forces.air_drag = 0.02;
    Simulation simulation(scene);
    EXPECT_EQ(simulation.cloth().topology().spring_groups[0].springs.size(),
              build_offset_cloth(scene).topology().spring_groups[0].springs.size());
    for (int s = 0; s < 2000; ++s) ASSERT_FALSE(simulation.step().diverged());
}

}  // namespace
}  // namespace weft
