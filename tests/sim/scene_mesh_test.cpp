// Scene files with a mesh cloth: the [cloth] mesh keys, the OBJ found beside the scene, its
// errors reported at the OBJ's line, and the scene written back naming the same mesh.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include "sim/build/cloth_builder.h"
#include "sim/collision/colliders.h"
#include "sim/core/simulation.h"
#include "sim/guards/divergence.h"
#include "sim/scene/obj_reader.h"
#include "sim/scene_io/scene_loader.h"
#include "sim/scene_io/scene_writer.h"

namespace weft {
namespace {

namespace fs = std::filesystem;

// A scratch folder with a scene and its meshes, removed afterwards.
class SceneWithMesh : public ::testing::Test {
  protected:
    void SetUp() override {
        folder_ = fs::path(::testing::TempDir()) /
                  ("scene_mesh_test_" +
                   std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::create_directories(folder_ / "meshes");
        write("meshes/square.obj",
              "v 0 0 0\nv 0 -1 0\nv 1 -1 0\nv 1 0 0\ng sheet\nf 1 2 3 4\ng top\np 1 4\n");
    }
    void TearDown() override { fs::remove_all(folder_); }

    std::string write(const std::string& name, const std::string& text) {
        const fs::path path = folder_ / name;
        std::ofstream(path) << text;
        return path.string();
    }

    SceneLoadResult load(const std::string& cloth_keys,
                         const std::vector<std::string>& overrides = {}) {
        return load_scene_file(write("scene.toml", "[cloth]\n" + cloth_keys), overrides);
    }

    SceneError error_of(const std::string& cloth_keys,
                        const std::vector<std::string>& overrides = {}) {
        SceneLoadResult result = load(cloth_keys, overrides);
        EXPECT_FALSE(result.ok()) << "loaded, but should have failed:\n" << cloth_keys;
        return result.error.value_or(SceneError{"(none)", "(none)"});
    }

    std::string scene_path() const { return (folder_ / "scene.toml").string(); }
    std::string mesh_path(const std::string& name) const {
        return fs::absolute(folder_ / name).lexically_normal().string();
    }

    fs::path folder_;
};

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

TEST_F(SceneWithMesh, ReadsTheMeshBesideTheSceneFile) {
    SceneLoadResult result =
        load("mesh = \"meshes/square.obj\"\ndensity = 0.5\norigin = [0, 1, 0]\n");
    ASSERT_TRUE(result.ok()) << result.error->message();
    const ClothSpec& spec = result.scene->cloth;
    EXPECT_EQ(spec.mesh, mesh_path("meshes/square.obj"));  // absolute once loaded
    ASSERT_TRUE(spec.mesh_data.obj);
    EXPECT_EQ(spec.mesh_data.obj->vertices.size(), 4u);
    EXPECT_EQ(spec.density, 0.5);
    EXPECT_EQ(spec.pin_preset, PinPreset::none);  // no corners to pin by default
    const Cloth cloth = build_cloth(*result.scene);
    EXPECT_EQ(cloth.particle_count(), 4u);
    EXPECT_EQ(cloth.positions[1], Vec3(0.0, 0.0, 0.0));  // (0, -1, 0) moved up by the origin
    EXPECT_NEAR(cloth.topology().masses[0] + cloth.topology().masses[1] +
                    cloth.topology().masses[2] + cloth.topology().masses[3],
                0.5, 1e-15);
}

TEST_F(SceneWithMesh, PinsByVertexNumbersOrGroup) {
    SceneLoadResult listed = load("mesh = \"meshes/square.obj\"\npins = [1, 4]\n");
    ASSERT_TRUE(listed.ok()) << listed.error->message();
    EXPECT_EQ(build_cloth(*listed.scene).topology().pinned, (std::vector<std::uint32_t>{0, 3}));
    SceneLoadResult grouped = load("mesh = \"meshes/square.obj\"\npin_group = \"top\"\n");
    ASSERT_TRUE(grouped.ok()) << grouped.error->message();
    EXPECT_EQ(build_cloth(*grouped.scene).topology().pinned, (std::vector<std::uint32_t>{0, 3}));
}

TEST_F(SceneWithMesh, RefusesPinsThatAreNotInTheMesh) {
    SceneError error = error_of("mesh = \"meshes/square.obj\"\npins = [1, 9]\n");
    EXPECT_EQ(error.where, scene_path() + ":3:8");
    EXPECT_TRUE(contains(error.what, "pin 9")) << error.what;
    error = error_of("mesh = \"meshes/square.obj\"\npin_group = \"hem\"\n");
    EXPECT_EQ(error.where, scene_path() + ":3:13");
    EXPECT_TRUE(contains(error.what, "'hem'")) << error.what;
    error = error_of("mesh = \"meshes/square.obj\"\npins = \"top-corners\"\n");
    EXPECT_TRUE(contains(error.what, "vertex numbers")) << error.what;
    error = error_of("mesh = \"meshes/square.obj\"\npins = [[0, 0]]\n");
    EXPECT_TRUE(contains(error.what, "vertex number")) << error.what;
    error = error_of("mesh = \"meshes/square.obj\"\npins = [1]\npin_group = \"top\"\n");
    EXPECT_EQ(error.where, scene_path() + ":4:13");
}

TEST_F(SceneWithMesh, RefusesTheGridsKeysBesideAMesh) {
    for (const std::string key : {"rows = 3", "cols = 3", "layout = \"grid\"",
                                  "orientation = \"vertical\"", "spacing = 0.1"}) {
        const SceneError error = error_of("mesh = \"meshes/square.obj\"\n" + key + "\n");
        EXPECT_TRUE(error.where.starts_with(scene_path() + ":3:")) << error.message();
        EXPECT_TRUE(contains(error.what, "does not apply with cloth.mesh")) << error.what;
    }
    const SceneError set = error_of("mesh = \"meshes/square.obj\"\n", {"cloth.rows=5"});
    EXPECT_EQ(set.where, "--set cloth.rows");
    const SceneError density = error_of("rows = 3\ndensity = 0.1\n");
    EXPECT_EQ(density.where, scene_path() + ":3:11");
    EXPECT_TRUE(contains(density.what, "only to a mesh")) << density.what;
    EXPECT_TRUE(
        contains(error_of("mesh = \"meshes/square.obj\"\ndensity = 0\n").what, "cloth.density"));
}

// particle_mass instead of density: every vertex weighs the same, as a grid's particles do;
// both at once are refused at the second, and so is a mass that is not positive.
TEST_F(SceneWithMesh, WeighsEveryVertexAlikeGivenParticleMass) {
    SceneLoadResult result = load("mesh = \"meshes/square.obj\"\nparticle_mass = 0.02\n");
    ASSERT_TRUE(result.ok()) << result.error->message();
    EXPECT_TRUE(result.scene->cloth.mesh_particle_mass);
    const Cloth cloth = build_cloth(*result.scene);
    EXPECT_EQ(cloth.topology().masses, std::vector<double>(4, 0.02));
    EXPECT_EQ(cloth.topology().inverse_masses, std::vector<double>(4, 1.0 / 0.02));
    const std::string text = scene_to_toml(*result.scene);
    EXPECT_TRUE(contains(text, "particle_mass = 0.02")) << text;
    EXPECT_FALSE(contains(text, "density")) << text;
    SceneLoadResult again = load_scene_text(text, "panel");
    ASSERT_TRUE(again.ok()) << again.error->message() << "\n" << text;
    EXPECT_EQ(*again.scene, *result.scene);
    // Without it, density as before.
    SceneLoadResult density = load("mesh = \"meshes/square.obj\"\n");
    ASSERT_TRUE(density.ok()) << density.error->message();
    EXPECT_FALSE(density.scene->cloth.mesh_particle_mass);
    EXPECT_FALSE(*density.scene == *result.scene);

    SceneError both =
        error_of("mesh = \"meshes/square.obj\"\ndensity = 0.5\nparticle_mass = 0.02\n");
    EXPECT_EQ(both.where, scene_path() + ":4:17");
    EXPECT_TRUE(contains(both.what, "cannot both be given")) << both.what;
    both = error_of("mesh = \"meshes/square.obj\"\ndensity = 0.5\n", {"cloth.particle_mass=0.02"});
    EXPECT_EQ(both.where, "--set cloth.particle_mass");
    const SceneError zero = error_of("mesh = \"meshes/square.obj\"\nparticle_mass = 0\n");
    EXPECT_EQ(zero.where, scene_path() + ":3:17");
    EXPECT_TRUE(contains(zero.what, "cloth.particle_mass")) << zero.what;
}

TEST_F(SceneWithMesh, ABadMeshIsRefusedAtItsOwnLine) {
    write("meshes/bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
    SceneError error = error_of("mesh = \"meshes/bad.obj\"\n");
    EXPECT_EQ(error.where, mesh_path("meshes/bad.obj") + ":4");
    EXPECT_TRUE(contains(error.what, "'7'")) << error.what;
    write("meshes/fan.obj",
          "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n");
    error = error_of("mesh = \"meshes/fan.obj\"\n");
    EXPECT_EQ(error.where, mesh_path("meshes/fan.obj") + ":8");
    EXPECT_TRUE(contains(error.what, "more than two faces")) << error.what;
    // A missing file is said at the key that names it.
    error = error_of("mesh = \"meshes/none.obj\"\n");
    EXPECT_EQ(error.where, scene_path() + ":2:8");
    EXPECT_TRUE(contains(error.what, mesh_path("meshes/none.obj"))) << error.what;
}

TEST_F(SceneWithMesh, WrittenBackItLoadsAsTheSameSceneFromAnywhere) {
    SceneLoadResult result =
        load("mesh = \"meshes/square.obj\"\ndensity = 0.125\npin_group = \"top\"\n");
    ASSERT_TRUE(result.ok()) << result.error->message();
    const std::string text = scene_to_toml(*result.scene);
    EXPECT_FALSE(contains(text, "rows")) << text;
    // "panel" has no folder: the written path must not depend on the scene file's.
    SceneLoadResult again = load_scene_text(text, "panel");
    ASSERT_TRUE(again.ok()) << again.error->message() << "\n" << text;
    EXPECT_EQ(*again.scene, *result.scene);
    SceneLoadResult listed = load("mesh = \"meshes/square.obj\"\npins = [2, 3]\n");
    ASSERT_TRUE(listed.ok()) << listed.error->message();
    SceneLoadResult listed_again = load_scene_text(scene_to_toml(*listed.scene), "panel");
    ASSERT_TRUE(listed_again.ok()) << listed_again.error->message();
    EXPECT_EQ(listed_again.scene->cloth.pin_vertices, (std::vector<std::int64_t>{2, 3}));
    EXPECT_EQ(*listed_again.scene, *listed.scene);
}

}  // namespace
}  // namespace weft

namespace weft {
namespace {

// The shipped meshes, 2 s into their scenes: finite, held (the pinned vertices where they
// started), and the tablecloth and the skirt resting on their balls without sinking in: no
// vertex deeper inside a sphere or below the ground than a millimetre.
TEST(ShippedMeshes, HangAndDrapeWithoutSinkingIntoTheirColliders) {
    for (const char* name : {"round_tablecloth", "flag_with_hole", "skirt"}) {
        SceneLoadResult loaded =
            load_scene_file(std::string(WEFT_SOURCE_DIR "/assets/scenes/") + name + ".toml");
        ASSERT_TRUE(loaded.ok()) << loaded.error->message();
        Simulation simulation(*loaded.scene);
        const std::vector<Vec3> start = simulation.cloth().positions;
        const int steps = static_cast<int>(std::lround(2.0 / loaded.scene->solver.dt));
        std::size_t contacts = 0;
        for (int s = 0; s < steps; ++s) {
            const StepReport report = simulation.step();
            ASSERT_FALSE(report.diverged()) << name << " at step " << s;
            contacts += report.contacts;
        }
        const Cloth& cloth = simulation.cloth();
        for (std::uint32_t p : cloth.topology().pinned)
            EXPECT_EQ(cloth.positions[p], start[p]) << name;
        double deepest = 0.0;  // m
        for (const Collider& collider : simulation.colliders())
            for (const Vec3& x : cloth.positions) {
                Vec3 normal;
                deepest = std::max(deepest, -signed_distance(collider, x, normal));
            }
        EXPECT_LT(deepest, 1e-3) << name;
        // The two with a ball lie on it (the flag flies free, high above its floor).
        if (!loaded.scene->colliders.empty()) {
            EXPECT_GT(contacts, 1000u) << name;
        }
        if (std::string(name) != "round_tablecloth") {
            EXPECT_FALSE(cloth.topology().pinned.empty()) << name;
        }
    }
}

// Messages name a mesh's particles as its OBJ file numbers its vertices.
TEST(ShippedMeshes, MessagesNameVerticesByTheirNumberInTheFile) {
    SceneLoadResult loaded = load_scene_file(WEFT_SOURCE_DIR "/assets/scenes/skirt.toml");
    ASSERT_TRUE(loaded.ok()) << loaded.error->message();
    Cloth cloth = build_cloth(*loaded.scene);
    EXPECT_EQ(particle_name(cloth, 0), "vertex 1");
    cloth.positions[4].x = std::numeric_limits<double>::quiet_NaN();
    const std::optional<std::string> reason = find_divergence(cloth, true);
    ASSERT_TRUE(reason.has_value());
    EXPECT_EQ(reason->rfind("vertex 5 has a non-finite position", 0), 0u) << *reason;
}

}  // namespace
}  // namespace weft
