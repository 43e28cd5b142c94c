// Switching spring families off and on while the cloth runs (the demo's panel): off costs
// nothing and gives exactly the forces of a cloth built without the family; on restores it
// as it was; a family switched on after a cut does not sew the cut together.
#include <gtest/gtest.h>

#include <vector>

#include "sim/build/cloth_builder.h"
#include "sim/core/simulation.h"

namespace weft {
namespace {

Scene sheet_with_shear() {
    Scene scene;
    scene.cloth.rows = 9;
    scene.cloth.cols = 11;
    scene.shear.enabled = true;
    scene.forces.air_drag = 0.02;
    return scene;
}

std::vector<Vec3> forces_on(const Cloth& cloth, const ForceField& field) {
    std::vector<Vec3> forces(cloth.particle_count());
    accumulate_forces(cloth, field, cloth.positions, cloth.velocities, forces);
    return forces;
}

TEST(SpringFamilyToggle, OffGivesExactlyTheForcesOfAClothBuiltWithoutTheFamily) {
    Simulation simulation(sheet_with_shear());
    for (int s = 0; s < 200; ++s) simulation.step();  // a deformed, moving state
    simulation.set_family_enabled(SpringFamily::shear, false);
    EXPECT_EQ(simulation.cloth().find_group(SpringFamily::shear), nullptr);
    EXPECT_FALSE(simulation.scene().shear.enabled);

    Scene without = sheet_with_shear();
    without.shear.enabled = false;
    Cloth reference = build_cloth(without);
    reference.positions = simulation.cloth().positions;
    reference.velocities = simulation.cloth().velocities;
    EXPECT_EQ(simulation.cloth().spring_count(), reference.spring_count());
    const std::vector<Vec3> got = forces_on(simulation.cloth(), simulation.force_field());
    const std::vector<Vec3> expected = forces_on(reference, simulation.force_field());
    for (std::size_t p = 0; p < got.size(); ++p) EXPECT_EQ(got[p], expected[p]) << p;
}

TEST(SpringFamilyToggle, OnAgainRestoresTheFamilyWithItsMaterial) {
    Simulation simulation(sheet_with_shear());
    const SpringGroup before = *simulation.cloth().find_group(SpringFamily::shear);
    simulation.set_family_enabled(SpringFamily::shear, false);
    simulation.set_spring_material(SpringFamily::shear, 123.0, 0.25);  // edited while off
    simulation.set_family_enabled(SpringFamily::shear, true);
    const SpringGroup* after = simulation.cloth().find_group(SpringFamily::shear);
    ASSERT_NE(after, nullptr);
    ASSERT_EQ(after->springs.size(), before.springs.size());
    for (std::size_t s = 0; s < before.springs.size(); ++s) {
        EXPECT_EQ(after->springs[s].i, before.springs[s].i);
        EXPECT_EQ(after->springs[s].j, before.springs[s].j);
        EXPECT_EQ(after->springs[s].rest_length, before.springs[s].rest_length);
    }
    EXPECT_EQ(after->stiffness, 123.0);
    EXPECT_EQ(after->damping, 0.25);
    // Groups stay in family order, so the force pass sums in the same order as a fresh build.
    EXPECT_EQ(simulation.cloth().topology().spring_groups.front().family, SpringFamily::structural);
}

TEST(SpringFamilyToggle, AFamilySwitchedOnAfterACutDoesNotJoinTheCut) {
    Scene scene = sheet_with_shear();
    scene.shear.enabled = false;
    Simulation simulation(scene);
    const int rows = scene.cloth.rows, cols = scene.cloth.cols, cut_after = 5;
    // Cut every structural spring between column 5 and column 6: the sheet is in two pieces.
    const std::size_t cut = simulation.cut_springs([&](const Spring& s) {
        return static_cast<int>(s.i % cols) == cut_after &&
               static_cast<int>(s.j % cols) == cut_after + 1;
    });
    ASSERT_EQ(cut, static_cast<std::size_t>(rows));

    simulation.set_family_enabled(SpringFamily::shear, true);
    simulation.set_family_enabled(SpringFamily::bend, true);
    // Shear: both diagonals of every cell, less the two of each cell row that span the cut.
    const std::size_t shear_whole = 2u * (rows - 1) * (cols - 1);
    EXPECT_EQ(simulation.cloth().find_group(SpringFamily::shear)->springs.size(),
              shear_whole - 2u * (rows - 1));
    // Bend: two spacings along rows and columns, less (r,4)-(r,6) and (r,5)-(r,7) per row.
    const std::size_t bend_whole = rows * (cols - 2) + (rows - 2) * cols;
    EXPECT_EQ(simulation.cloth().find_group(SpringFamily::bend)->springs.size(),
              bend_whole - 2u * rows);
    for (const SpringGroup& group : simulation.cloth().topology().spring_groups)
        for (const Spring& s : group.springs) {
            const bool left_i = static_cast<int>(s.i % cols) <= cut_after;
            const bool left_j = static_cast<int>(s.j % cols) <= cut_after;
            EXPECT_EQ(left_i, left_j) << spring_family_name(group.family) << " " << s.i << "-"
                                      << s.j << " crosses the cut";
        }
}

TEST(SpringFamilyToggle, StructuralSpringsCannotBeSwitchedOff) {
    Simulation simulation(sheet_with_shear());
    const std::size_t count = simulation.cloth().spring_count();
    simulation.set_family_enabled(SpringFamily::structural, false);
    EXPECT_EQ(simulation.cloth().spring_count(), count);
    EXPECT_TRUE(simulation.scene().structural.enabled);
}

}  // namespace
}  // namespace weft
