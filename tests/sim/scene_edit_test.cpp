// Typed live edits (scene_edit.h) against the scene loader: the loader is the truth for what
// a value of a key may be, so an edit must be taken exactly when the loader takes the same
// key and value in a file (as --set), and must give the scene the loader gives.
#include <gtest/gtest.h>

#include "sim/scene/scene_edit.h"
#include "sim/scene_io/scene_edit_toml.h"
#include "sim/scene_io/scene_loader.h"
#include "sim/scene_io/scene_writer.h"

namespace weft {
namespace {

Scene base_scene() {
    Scene scene;
    scene.cloth.rows = 12;
    scene.cloth.cols = 9;
    scene.cloth.pin_preset = PinPreset::list;
    scene.cloth.pin_list = {{0, 0}, {0, 8}};
    scene.shear.enabled = true;
    scene.tear_max_stretch = 1.8;
    scene.self_collision_thickness = 0.02;
    scene.colliders.resize(2);
    scene.colliders[1].type = ColliderType::plane;
    return scene;
}

// Each "KEY=VALUE" as --set takes it: some taken, some refused by the value's own rule, some
// by a rule that joins keys (rows × cols, pins inside the grid, thickness against spacing).
const char* const overrides[] = {
    "cloth.rows=40",
    "cloth.rows=0",
    "cloth.rows=4194305",
    "cloth.rows=1.5",
    "cloth.cols=3",  // leaves the pin at col 8 outside the grid
    "cloth.cols=5000000",
    "cloth.spacing=0.02",
    "cloth.spacing=0",
    "cloth.spacing=0.005",  // the 0.02 m thickness is then more than 2 spacings
    "cloth.particle_mass=1e-3",
    "cloth.particle_mass=-1",
    "cloth.layout=offset",
    "cloth.layout=hexagonal",
    "cloth.orientation=horizontal",
    "cloth.pins=\"top-row\"",
    "cloth.pins=[[11,8],[3,4]]",
    "cloth.pins=[[12,0]]",
    "cloth.pins=\"top-rows\"",
    "cloth.origin=[0,1,2]",
    "cloth.origin=[0,1]",
    "cloth.density=0.3",  // a mesh's key, on a grid
    "springs.structural.enabled=false",
    "springs.shear.enabled=false",
    "springs.bend.enabled=true",
    "springs.bend.enabled=1",
    "springs.shear.stiffness=250",
    "springs.shear.stiffness=-5",
    "springs.bend.damping=0",
    "springs.bend.damping=nan",
    "springs.structural.stiffness=inf",
    "tearing.max_stretch=1.3",
    "tearing.max_stretch=1",
    "strain_limit.max_strain=0.05",
    "strain_limit.max_strain=0",
    "strain_limit.max_strain=1.5",
    "strain_limit.max_stretch=0.2",  // the old name, read as max_strain
    "strain_limit.max_stretch=1.5",
    "self_collision.thickness=0.05",
    "self_collision.thickness=0.2",
    "forces.gravity=[0,-1.62,0]",
    "forces.gravity=[0,nan,0]",
    "forces.air_drag=0.01",
    "forces.air_drag=-0.01",
    "forces.wind=[3,0,-1]",
    "solver.integrator=rk4",
    "solver.integrator=leapfrog",
    "solver.dt=0.0005",
    "solver.dt=0",
    "camera.fov_degrees=179",
    "camera.fov_degrees=180",
    "camera.target=[1,1,1]",
};

TEST(SceneEdit, TakesExactlyWhatTheLoaderTakesAndGivesTheSameScene) {
    const Scene base = base_scene();
    const std::string base_toml = scene_to_toml(base);
    int taken = 0, refused = 0;
    for (const char* text : overrides) {
        const SceneLoadResult loaded = load_scene_text(base_toml, "base", {text});
        SceneError read_error;
        std::optional<SceneEdit> edit = scene_edit_from_override(text, read_error);
        Scene edited = base;
        const bool edit_taken = edit && !apply_scene_edits(edited, {&*edit, 1});
        EXPECT_EQ(edit_taken, loaded.ok()) << text;
        if (loaded.ok() && edit_taken) {
            EXPECT_TRUE(edited == *loaded.scene) << text;
            ++taken;
        } else if (!edit_taken) {
            EXPECT_TRUE(edited == base) << text << ": a refused edit changed the scene";
            ++refused;
        }
    }
    // Both verdicts are exercised.
    EXPECT_GE(taken, 20);
    EXPECT_GE(refused, 20);
}

TEST(SceneEdit, ARefusalIsTheLoadersSentence) {
    Scene scene = base_scene();
    const SceneEdit stiffness{SceneKey::shear_stiffness, -5.0};
    EXPECT_EQ(apply_scene_edits(scene, {&stiffness, 1}).value_or(""),
              "springs.shear.stiffness must be >= 0, got -5");
    const SceneLoadResult loaded =
        load_scene_text(scene_to_toml(scene), "base", {"springs.shear.stiffness=-5"});
    ASSERT_FALSE(loaded.ok());
    EXPECT_EQ(loaded.error->what, "springs.shear.stiffness must be >= 0, got -5");
}

TEST(SceneEdit, ABatchIsAllOrNothingAndJoinedRulesSeeItsResult) {
    Scene scene = base_scene();
    const Scene before = scene;
    // rows 3 alone would leave the pin at row 0 fine, cols 3 alone the pin at col 8 outside;
    // with the pins moved in the same batch, the grid is sound.
    const std::vector<SceneEdit> shrink = {
        {SceneKey::cloth_rows, std::int64_t{3}},
        {SceneKey::cloth_cols, std::int64_t{3}},
        {SceneKey::cloth_pins, GridPins{PinPreset::list, {{0, 0}, {0, 2}}}},
    };
    EXPECT_TRUE(apply_scene_edits(scene, {shrink.data(), 2}).has_value());
    EXPECT_TRUE(scene == before);
    EXPECT_FALSE(apply_scene_edits(scene, shrink));
    EXPECT_EQ(scene.cloth.cols, 3);
    // A taken edit then a refused one: neither.
    scene = before;
    const std::vector<SceneEdit> half = {{SceneKey::shear_stiffness, 10.0}, {SceneKey::dt, -1.0}};
    EXPECT_TRUE(apply_scene_edits(scene, half).has_value());
    EXPECT_TRUE(scene == before);
}

TEST(SceneEdit, CollidersAreEditedByIndexAndTheirRulesHold) {
    Scene scene = base_scene();
    const SceneEdit radius{SceneKey::collider_radius, 0.5, 0};
    EXPECT_FALSE(apply_scene_edits(scene, {&radius, 1}));
    EXPECT_EQ(scene.colliders[0].radius, 0.5);
    EXPECT_EQ(scene_edit_name(radius), "colliders.0.radius");
    const Scene before = scene;
    for (const SceneEdit& bad : {SceneEdit{SceneKey::collider_radius, 0.0, 0},
                                 SceneEdit{SceneKey::collider_restitution, 1.5, 1},
                                 SceneEdit{SceneKey::collider_normal, Vec3d{0, 0, 0}, 1},
                                 SceneEdit{SceneKey::collider_friction, 0.2, 2},
                                 SceneEdit{SceneKey::collider_radius, true, 0}}) {
        EXPECT_TRUE(apply_scene_edits(scene, {&bad, 1}).has_value()) << scene_edit_name(bad);
        EXPECT_TRUE(scene == before);
    }
}

TEST(SceneEdit, TheEditsBetweenTwoScenesMakeOneTheOther) {
    const Scene from = base_scene();
    Scene to = from;
    to.cloth.rows = 30;
    to.shear.stiffness = 123.0;
    to.bend.enabled = true;
    to.tear_max_stretch.reset();
    to.strain_limit_max_strain = 0.2;
    to.forces.wind = {1.0, 2.0, 3.0};
    to.solver.integrator = Integrator::implicit_euler;
    to.colliders[1].point = {0.0, -2.0, 0.0};
    to.camera.fov_degrees = 40.0;
    const std::optional<std::vector<SceneEdit>> edits = scene_edits_between(from, to);
    ASSERT_TRUE(edits);
    EXPECT_EQ(edits->size(), 9u);
    Scene reached = from;
    EXPECT_FALSE(apply_scene_edits(reached, *edits));
    EXPECT_TRUE(reached == to);
    EXPECT_TRUE(scene_edits_between(from, from)->empty());
    // What no edit reaches.
    Scene renamed = from;
    renamed.name = "other";
    EXPECT_FALSE(scene_edits_between(from, renamed));
    Scene fewer = from;
    fewer.colliders.pop_back();
    EXPECT_FALSE(scene_edits_between(from, fewer));
}

TEST(SceneEdit, AValueWrittenAsTomlReadsBackToTheSameBits) {
    const SceneValue values[] = {0.1 + 0.2,
                                 std::int64_t{4194304},
                                 false,
                                 Vec3d{1e-300, -0.0, 5e300},
                                 Integrator::rk4,
                                 Layout::offset,
                                 Orientation::horizontal,
                                 ContactResponse::repulsion,
                                 GridPins{PinPreset::list, {{1, 2}}},
                                 FeatureOff{}};
    const SceneKey keys[] = {SceneKey::dt,
                             SceneKey::cloth_cols,
                             SceneKey::shear_enabled,
                             SceneKey::gravity,
                             SceneKey::integrator,
                             SceneKey::cloth_layout,
                             SceneKey::cloth_orientation,
                             SceneKey::collider_response,
                             SceneKey::cloth_pins,
                             SceneKey::tear_max_stretch};
    for (std::size_t v = 0; v < std::size(values); ++v) {
        const SceneEdit edit{keys[v], values[v], 4};
        const std::string text = scene_edit_name(edit) + "=" + scene_value_toml(edit.value);
        SceneError error;
        const std::optional<SceneEdit> read = scene_edit_from_override(text, error);
        ASSERT_TRUE(read) << text << ": " << error.message();
        EXPECT_TRUE(*read == (SceneEdit{keys[v], values[v], is_collider_key(keys[v]) ? 4u : 0u}))
            << text;
    }
}

}  // namespace
}  // namespace weft
