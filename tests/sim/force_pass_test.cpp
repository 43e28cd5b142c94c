// The force pass against the design notes' formula and Newton's third law.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "loaded_cloth.h"
#include "sim/build/cloth_builder.h"
#include "sim/core/force_pass.h"

namespace weft {
namespace {

Scene sheet_with_all_families() {
    Scene scene;
    scene.cloth.rows = 7;
    scene.cloth.cols = 9;
    scene.structural = {true, 800.0, 0.5};
    scene.shear = {true, 400.0, 0.3};
    scene.bend = {true, 100.0, 0.1};
    return scene;
}

void scramble(Cloth& cloth, unsigned seed) {
    testing::scramble(cloth, seed, 0.02);
}

TEST(ForcePass, InternalSpringForcesSumToZero) {
    Cloth cloth = build_grid_cloth(sheet_with_all_families());
    scramble(cloth, 7);
    ForceField no_external;
    no_external.gravity = Vec3(0.0);
    std::vector<Vec3> forces(cloth.particle_count());
    accumulate_forces(cloth, no_external, cloth.positions, cloth.velocities, forces);
    Vec3 total(0.0);
    double magnitude = 0.0;
    for (const Vec3& f : forces) {
        total += f;
        magnitude += glm::length(f);
    }
    ASSERT_GT(magnitude, 1.0);  // the springs really are loaded
    EXPECT_LT(glm::length(total), 1e-12 * magnitude);
}

TEST(ForcePass, MatchesTheDesignFormulaSpringBySpring) {
    Cloth cloth = build_grid_cloth(sheet_with_all_families());
    scramble(cloth, 11);
    ForceField field;
    field.gravity = {0.5, -9.81, 0.25};
    field.air_drag = 0.03;
    field.wind = {1.0, 0.0, 2.0};
    std::vector<Vec3> forces(cloth.particle_count());
    accumulate_forces(cloth, field, cloth.positions, cloth.velocities, forces);

    // Independent evaluation: f = (k (|d| - L) + c ((v_j - v_i)·u)) u on i, -f on j.
    std::vector<Vec3> expected(cloth.particle_count());
    for (std::size_t p = 0; p < cloth.particle_count(); ++p)
        expected[p] = cloth.topology().masses[p] * field.gravity -
                      field.air_drag * (cloth.velocities[p] - field.wind);
    for (const SpringGroup& group : cloth.topology().spring_groups) {
        for (const Spring& s : group.springs) {
            const Vec3 d = cloth.positions[s.j] - cloth.positions[s.i];
            const Vec3 u = glm::normalize(d);
            const double magnitude =
                group.stiffness * (glm::length(d) - s.rest_length) +
                group.damping * glm::dot(cloth.velocities[s.j] - cloth.velocities[s.i], u);
            expected[s.i] += magnitude * u;
            expected[s.j] -= magnitude * u;
        }
    }
    for (std::size_t p = 0; p < cloth.particle_count(); ++p)
        EXPECT_LT(glm::length(forces[p] - expected[p]), 1e-12 * (1.0 + glm::length(expected[p])))
            << p;
}

TEST(ForcePass, StretchedSpringPullsItsEndsTogether) {
    Scene scene;
    scene.cloth.rows = 1;
    scene.cloth.cols = 2;
    scene.cloth.spacing = 1.0;
    scene.structural = {true, 10.0, 0.0};
    Cloth cloth = build_grid_cloth(scene);
    cloth.positions[1] = {1.5, 0.0, 0.0};  // stretched by 0.5 m
    ForceField no_external;
    no_external.gravity = Vec3(0.0);
    std::vector<Vec3> forces(2);
    accumulate_forces(cloth, no_external, cloth.positions, cloth.velocities, forces);
    EXPECT_EQ(forces[0], Vec3(5.0, 0.0, 0.0));  // towards particle 1: k · 0.5 m = 5 N
    EXPECT_EQ(forces[1], Vec3(-5.0, 0.0, 0.0));
}

}  // namespace
}  // namespace weft
