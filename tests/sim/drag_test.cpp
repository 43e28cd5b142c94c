// Dragging: the handle pulls the grabbed cloth to the target, with a capped force, and costs
// nothing when nobody drags.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "sim/cloth_builder.h"
#include "sim/drag.h"
#include "sim/force_pass.h"
#include "sim/simulation.h"

namespace weft {
namespace {

Scene sheet() {
    Scene scene;
    scene.cloth.rows = 8;
    scene.cloth.cols = 8;
    scene.cloth.spacing = 0.05;
    scene.shear.enabled = true;
    scene.forces.air_drag = 0.02;
    return scene;
}

TEST(Drag, GrabsOnlyFreeParticlesWithinTheRadiusWithFallingWeights) {
    const Cloth cloth = build_grid_cloth(sheet());
    const RayHit hit{0, 3 * 8 + 3, 1.0, cloth.positions[3 * 8 + 3]};
    const DragHandle drag = grab_cloth(cloth, hit, 0.08);
    ASSERT_TRUE(drag.active());
    for (std::size_t k = 0; k < drag.particles.size(); ++k) {
        const double distance = glm::length(cloth.positions[drag.particles[k]] - hit.point);
        EXPECT_LT(distance, 0.08);
        EXPECT_NEAR(drag.weights[k], std::pow(1.0 - distance * distance / (0.08 * 0.08), 2), 1e-12);
        EXPECT_FALSE(cloth.is_pinned(drag.particles[k]));
    }
    // A tiny radius still grabs the particle that was hit.
    const DragHandle small = grab_cloth(cloth, hit, 1e-6);
    ASSERT_EQ(small.particles.size(), 1u);
    EXPECT_EQ(small.particles[0], hit.particle);
}

TEST(Drag, PullsTheGrabbedPointToTheTarget) {
    Simulation simulation(sheet());
    const std::uint32_t grabbed = 7 * 8 + 4;  // bottom edge
    const Vec3 start = simulation.cloth().positions[grabbed];
    simulation.start_drag(grab_cloth(simulation.cloth(), {0, grabbed, 1.0, start}, 0.06));
    const Vec3 target = start + Vec3(0.0, 0.1, 0.2);
    simulation.move_drag_target(target);
    for (int s = 0; s < 2000; ++s) ASSERT_FALSE(simulation.step().diverged());
    // Held there against gravity and the springs, to within the sag of a soft hand: the
    // hand holds up much of the sheet's 6.3 N with a stiffness of about 150 N/m.
    EXPECT_LT(glm::length(simulation.cloth().positions[grabbed] - target), 0.03);
    // Released, it falls back under gravity.
    simulation.end_drag();
    for (int s = 0; s < 200; ++s) ASSERT_FALSE(simulation.step().diverged());
    EXPECT_LT(simulation.cloth().positions[grabbed].y, target.y - 0.01);
}

TEST(Drag, ForceIsCappedWhateverTheDistance) {
    const Cloth cloth = build_grid_cloth(sheet());
    const std::uint32_t grabbed = 5 * 8 + 5;
    DragHandle drag = grab_cloth(cloth, {0, grabbed, 1.0, cloth.positions[grabbed]}, 1e-6);
    drag.target += Vec3(1e6, 0.0, 0.0);  // a flick to the other side of the world
    std::vector<Vec3> forces(cloth.particle_count(), Vec3(0.0));
    accumulate_drag_forces(drag, cloth, cloth.positions, cloth.velocities, forces);
    EXPECT_NEAR(glm::length(forces[grabbed]),
                cloth.topology().masses[grabbed] * drag.max_acceleration, 1e-12);
}

TEST(Drag, AFastFlickDoesNotBlowUpTheCloth) {
    Simulation simulation(sheet());
    const std::uint32_t grabbed = 7 * 8 + 4;
    const Vec3 start = simulation.cloth().positions[grabbed];
    simulation.start_drag(grab_cloth(simulation.cloth(), {0, grabbed, 1.0, start}, 0.1));
    for (int frame = 0; frame < 200; ++frame) {
        // The target jumps 5 m back and forth every 1/60 s.
        simulation.move_drag_target(start + Vec3(frame % 2 ? 5.0 : -5.0, 0.0, 0.0));
        for (int s = 0; s < 16; ++s)
            ASSERT_FALSE(simulation.step().diverged()) << "frame " << frame;
    }
}

TEST(Drag, WithoutADragTheForcesAreUnchanged) {
    const Cloth cloth = build_grid_cloth(sheet());
    ForceField field;
    std::vector<Vec3> plain(cloth.particle_count()), with_idle_handle(cloth.particle_count());
    accumulate_forces(cloth, field, cloth.positions, cloth.velocities, plain);
    const DragHandle idle;
    field.drag = &idle;
    accumulate_forces(cloth, field, cloth.positions, cloth.velocities, with_idle_handle);
    EXPECT_EQ(plain, with_idle_handle);
}

}  // namespace
}  // namespace weft
