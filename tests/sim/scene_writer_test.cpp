// Scene writing: what scene_to_toml writes, the loader reads back to the same Scene, field by
// field and bit for bit — for every scene that ships and for awkward values.
#include <gtest/gtest.h>

#include <filesystem>

#include "sim/scene_io/scene_loader.h"
#include "sim/scene_io/scene_writer.h"

namespace weft {
namespace {

Scene round_trip(const Scene& scene) {
    SceneLoadResult loaded = load_scene_text(scene_to_toml(scene), "written");
    EXPECT_TRUE(loaded.ok()) << loaded.error->message() << "\n" << scene_to_toml(scene);
    return loaded.ok() ? *loaded.scene : Scene{};
}

TEST(SceneWriter, EveryShippedSceneReadsBackEqual) {
    int scenes = 0;
    for (const auto& entry :
         std::filesystem::directory_iterator(std::string(WEFT_SOURCE_DIR) + "/assets/scenes")) {
        if (entry.path().extension() != ".toml") continue;
        SceneLoadResult loaded = load_scene_file(entry.path().string());
        ASSERT_TRUE(loaded.ok()) << entry.path();
        EXPECT_TRUE(round_trip(*loaded.scene) == *loaded.scene) << entry.path();
        ++scenes;
    }
    EXPECT_GE(scenes, 10);
}

TEST(SceneWriter, AwkwardValuesReadBackBitForBit) {
    Scene scene;
    scene.name = "quotes \" and \\ backslash, tab\t, \u00e9t\u00e9 \U0001F9F5";
    scene.cloth.rows = 3;
    scene.cloth.cols = 4;
    scene.cloth.spacing = 0.1 + 0.2;  // 0.30000000000000004
    scene.cloth.particle_mass = 1e-300;
    scene.cloth.layout = Layout::offset;
    scene.cloth.orientation = Orientation::horizontal;
    scene.cloth.origin = {-0.0, 1.0 / 3.0, 123456789.125};
    scene.cloth.pin_preset = PinPreset::list;
    scene.cloth.pin_list = {{0, 0}, {2, 3}, {1, 2}};
    scene.shear = {false, 5e-324, 0.0};  // off but with a material, kept for when it is on
    scene.bend = {true, 1e300, 2.5};
    scene.tear_max_stretch = 1.0000000000000002;
    scene.strain_limit_max_strain = 0.1;
    scene.self_collision_thickness = 0.0049999999999999999;
    scene.forces = {{0.0, -9.80665, 0.0}, 0.02, {1e-310, -2.0, 3.0}};
    scene.solver = {Integrator::velocity_verlet, 1.0 / 3000.0};
    ColliderSpec plane;
    plane.type = ColliderType::plane;
    plane.point = {0.0, -1.5, 0.0};
    plane.normal = {0.0, 1.0, 0.0};
    plane.response = ContactResponse::repulsion;
    plane.restitution = 1.0;
    plane.friction = 0.7;
    ColliderSpec sphere;
    sphere.center = {0.1, -0.7, 0.2};
    sphere.radius = 0.33;
    scene.colliders = {plane, sphere};
    scene.camera = {{1.0, 2.0, 3.0}, {0.0, -0.5, 0.0}, 35.5};
    EXPECT_TRUE(round_trip(scene) == scene) << scene_to_toml(scene);
    // Presets too.
    for (PinPreset preset : {PinPreset::none, PinPreset::top_corners, PinPreset::top_row}) {
        scene.cloth.pin_preset = preset;
        scene.cloth.pin_list.clear();
        EXPECT_TRUE(round_trip(scene) == scene);
    }
}

}  // namespace
}  // namespace weft
