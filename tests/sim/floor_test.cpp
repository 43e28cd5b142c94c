// The floor (sim/floor.h): the ground drawn under the cloth is a plane collider with
// friction. Truths: nothing passes below it, a dropped sheet and a piece cut off come to rest
// on it (their kinetic energy goes to zero, as friction and damping take it), it costs the
// scene's bits nothing until the cloth reaches it, and a scene may do without it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "sim/collision/floor.h"
#include "sim/core/energy.h"
#include "sim/core/simulation.h"
#include "sim/core/state_hash.h"
#include "sim/scene_io/scene_loader.h"
#include "sim/scene_io/scene_writer.h"

namespace weft {
namespace {

// A 16 x 16 sheet, flat and unpinned, half a metre above where its floor goes.
Scene dropped_sheet() {
    Scene scene;
    scene.cloth.rows = scene.cloth.cols = 16;
    scene.cloth.spacing = 0.04;
    scene.cloth.orientation = Orientation::horizontal;
    scene.cloth.origin = {-0.3, 0.0, -0.3};
    scene.cloth.pin_preset = PinPreset::none;
    scene.shear.enabled = true;
    scene.forces.air_drag = 0.002;
    return scene;
}

double lowest_y(const Cloth& cloth) {
    double lowest = cloth.positions[0].y;
    for (const Vec3& x : cloth.positions) lowest = std::min(lowest, x.y);
    return lowest;
}

double fastest(const Cloth& cloth) {
    double speed = 0.0;
    for (const Vec3& v : cloth.velocities) speed = std::max(speed, glm::length(v));
    return speed;
}

TEST(Floor, ADroppedSheetRestsOnItAfterFiveSeconds) {
    for (Integrator integrator : {Integrator::symplectic_euler, Integrator::implicit_euler}) {
        Scene scene = dropped_sheet();
        scene.solver = {integrator, integrator == Integrator::implicit_euler ? 1.0 / 60.0 : 0.001};
        Simulation simulation(scene);
        // A tenth of a metre below the sheet (at y = 0) and the origin.
        const double floor = floor_height(simulation.cloth(), {});
        EXPECT_DOUBLE_EQ(floor, -0.1);
        ASSERT_EQ(simulation.colliders().size(), 1u);
        EXPECT_TRUE(is_ground_plane(simulation.colliders()[0]));
        double deepest = 0.0;  // m below the floor
        while (simulation.time() < 5.0) {
            ASSERT_FALSE(simulation.step().diverged()) << integrator_name(integrator);
            deepest = std::max(deepest, floor - lowest_y(simulation.cloth()));
        }
        EXPECT_LT(deepest, 1e-3) << integrator_name(integrator);
        // On it, not hovering: every particle within a spring's sag of it.
        for (const Vec3& x : simulation.cloth().positions)
            ASSERT_LT(x.y - floor, 0.005) << integrator_name(integrator);
        EXPECT_LT(fastest(simulation.cloth()), 0.01) << integrator_name(integrator);  // m/s
    }
}

// A piece cut off the hanging sheet lands and stops; before the floor it fell for ever.
TEST(Floor, APieceCutOffLandsAndStops) {
    Scene scene;
    scene.cloth.rows = scene.cloth.cols = 12;
    scene.cloth.spacing = 0.05;
    scene.cloth.pin_preset = PinPreset::top_row;
    scene.shear.enabled = true;
    Simulation simulation(scene);
    const double floor = floor_height(simulation.cloth(), {});
    while (simulation.time() < 0.5) ASSERT_FALSE(simulation.step().diverged());
    const std::uint32_t cols = 12;
    simulation.cut_springs([&](const Spring& s) { return (s.i / cols <= 5) != (s.j / cols <= 5); });
    double deepest = 0.0;
    while (simulation.time() < 5.5) {
        ASSERT_FALSE(simulation.step().diverged());
        deepest = std::max(deepest, floor - lowest_y(simulation.cloth()));
    }
    EXPECT_LT(deepest, 1e-3);
    EXPECT_LT(lowest_y(simulation.cloth()) - floor, 0.005);  // the piece lies on the floor
    EXPECT_LT(fastest(simulation.cloth()), 0.01);
}

// Until the cloth reaches it, the floor changes nothing: the same bits as without it.
TEST(Floor, CostsTheBitsNothingUntilTheClothReachesIt) {
    for (Integrator integrator :
         {Integrator::symplectic_euler, Integrator::rk4, Integrator::implicit_euler}) {
        Scene with = dropped_sheet();
        with.solver = {integrator, integrator == Integrator::implicit_euler ? 1.0 / 60.0 : 0.001};
        Scene without = with;
        without.floor_enabled = false;
        Simulation a(with), b(without);
        ASSERT_TRUE(b.colliders().empty());
        while (a.time() < 0.1) {  // 5 cm of fall: 5 cm short of the floor
            a.step();
            b.step();
        }
        EXPECT_EQ(hash_state(a.cloth()), hash_state(b.cloth())) << integrator_name(integrator);
    }
}

TEST(Floor, ASceneWithoutOneFallsThrough) {
    Scene scene = dropped_sheet();
    scene.floor_enabled = false;
    Simulation simulation(scene);
    while (simulation.time() < 1.0) ASSERT_FALSE(simulation.step().diverged());
    EXPECT_LT(lowest_y(simulation.cloth()), -2.0);
}

// A scene's own ground plane is its floor; no second one is added under it. A sphere stands
// on the floor that is added.
TEST(Floor, AGroundPlaneOfTheScenesOwnIsTheFloorAndABallStandsOnTheOneAdded) {
    Scene scene = dropped_sheet();
    ColliderSpec ground;
    ground.type = ColliderType::plane;
    ground.point = {0.0, -0.25, 0.0};
    scene.colliders = {ground};
    Simulation grounded(scene);
    ASSERT_EQ(grounded.colliders().size(), 1u);
    EXPECT_EQ(floor_height(grounded.cloth(), grounded.colliders()), -0.25);

    ColliderSpec ball;
    ball.center = {0.0, -0.5, 0.0};
    ball.radius = 0.3;
    scene.colliders = {ball};
    Simulation on_ball(scene);
    ASSERT_EQ(on_ball.colliders().size(), 2u);
    EXPECT_DOUBLE_EQ(on_ball.colliders()[1].point.y, -0.8);  // the ball's bottom
}

TEST(Floor, TheSceneSaysWhetherItHasOne) {
    SceneLoadResult off = load_scene_text("[floor]\nenabled = false\n", "off.toml");
    ASSERT_TRUE(off.ok()) << off.error->message();
    EXPECT_FALSE(off.scene->floor_enabled);
    EXPECT_TRUE(load_scene_text("", "default.toml").scene->floor_enabled);
    // Written only when off, and read back as it was.
    EXPECT_EQ(scene_to_toml(Scene{}).find("[floor]"), std::string::npos);
    SceneLoadResult again = load_scene_text(scene_to_toml(*off.scene), "again.toml");
    ASSERT_TRUE(again.ok());
    EXPECT_TRUE(*again.scene == *off.scene);
    // --set, and bad input named where and what.
    SceneLoadResult set = load_scene_text("", "set.toml", {"floor.enabled=false"});
    ASSERT_TRUE(set.ok());
    EXPECT_FALSE(set.scene->floor_enabled);
    SceneLoadResult typo = load_scene_text("[floor]\nenabeld = false\n", "typo.toml");
    ASSERT_FALSE(typo.ok());
    EXPECT_NE(typo.error->message().find("typo.toml:2:1"), std::string::npos)
        << typo.error->message();
    SceneLoadResult wrong = load_scene_text("[floor]\nenabled = 1\n", "wrong.toml");
    ASSERT_FALSE(wrong.ok());
    EXPECT_NE(wrong.error->message().find("floor.enabled"), std::string::npos)
        << wrong.error->message();
}

// Switched off and on while running: the floor comes and goes, and the cloth is the same.
TEST(Floor, SwitchesLiveWithoutRebuildingTheCloth) {
    Simulation simulation(dropped_sheet());
    while (simulation.time() < 0.05) simulation.step();
    const std::uint64_t hash = hash_state(simulation.cloth());
    Scene off = simulation.scene();
    off.floor_enabled = false;
    simulation.set_parameters(off);
    EXPECT_TRUE(simulation.colliders().empty());
    EXPECT_EQ(hash_state(simulation.cloth()), hash);
    Scene on = off;
    on.floor_enabled = true;
    simulation.set_parameters(on);
    ASSERT_EQ(simulation.colliders().size(), 1u);
    EXPECT_DOUBLE_EQ(simulation.colliders()[0].point.y, -0.1);  // where it was, not lower
}

}  // namespace
}  // namespace weft
