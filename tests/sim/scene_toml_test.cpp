// Scene loading: every key is read, every bad input names where and what.
#include <gtest/gtest.h>

#include <filesystem>

#include "sim/collision/colliders.h"
#include "sim/scene_io/scene_loader.h"

namespace weft {
namespace {

SceneLoadResult load(const std::string& text, const std::vector<std::string>& overrides = {}) {
    return load_scene_text(text, "test.toml", overrides);
}

// The error of a load that must fail.
SceneError error_of(const std::string& text, const std::vector<std::string>& overrides = {}) {
    SceneLoadResult result = load(text, overrides);
    EXPECT_FALSE(result.ok()) << "loaded, but should have failed:\n" << text;
    return result.error.value_or(SceneError{"(none)", "(none)"});
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

TEST(SceneLoader, AnEmptyFileGivesTheDefaults) {
    SceneLoadResult result = load("");
    ASSERT_TRUE(result.ok()) << result.error->message();
    const Scene& scene = *result.scene;
    EXPECT_EQ(scene.cloth.rows, 24);
    EXPECT_EQ(scene.cloth.cols, 24);
    EXPECT_EQ(scene.cloth.spacing, 0.05);
    EXPECT_EQ(scene.cloth.pin_preset, PinPreset::top_corners);
    EXPECT_TRUE(scene.structural.enabled);
    EXPECT_FALSE(scene.shear.enabled);
    EXPECT_FALSE(scene.bend.enabled);
    EXPECT_FALSE(scene.tear_max_stretch.has_value());
    EXPECT_EQ(scene.solver.integrator, Integrator::symplectic_euler);
    EXPECT_EQ(scene.solver.dt, 0.001);
    EXPECT_TRUE(result.warnings.empty());
}

TEST(SceneLoader, EveryShippedSceneLoads) {
    int count = 0;
    for (const auto& entry :
         std::filesystem::directory_iterator(WEFT_SOURCE_DIR "/assets/scenes")) {
        if (entry.path().extension() != ".toml") continue;
        SceneLoadResult result = load_scene_file(entry.path().string());
        EXPECT_TRUE(result.ok()) << entry.path() << ": " << result.error->message();
        EXPECT_TRUE(result.warnings.empty()) << entry.path();
        ++count;
    }
    EXPECT_GE(count, 3);
}

TEST(SceneLoader, ReadsEveryKey) {
    SceneLoadResult result = load(R"(
name = "Everything"
[cloth]
rows = 5
cols = 7
spacing = 0.1
particle_mass = 2
layout = "offset"
orientation = "horizontal"
origin = [1, 2.5, -3]
pins = [[0, 0], [4, 6]]
[springs.structural]
stiffness = 10.0
damping = 0.25
[springs.shear]
stiffness = 20.0
damping = 0.5
[springs.bend]
enabled = true
stiffness = 30.0
damping = 0.75
[tearing]
max_stretch = 2.0
[strain_limit]
max_strain = 0.2
[self_collision]
thickness = 0.02
[forces]
gravity = [0, -1.5, 0]
air_drag = 0.3
wind = [4, 0, 5]
[solver]
integrator = "rk4"
dt = 0.0025
[[colliders]]
type = "plane"
point = [0, -1, 0]
normal = [0, 2, 0]
response = "repulsion"
restitution = 0.5
friction = 0.1
[[colliders]]
type = "sphere"
center = [0, -0.5, 0]
radius = 0.25
[camera]
position = [1, 2, 3]
target = [0, 0.5, 0]
fov_degrees = 70
)");
    ASSERT_TRUE(result.ok()) << result.error->message();
    const Scene& s = *result.scene;
    EXPECT_EQ(s.name, "Everything");
    EXPECT_EQ(s.cloth.rows, 5);
    EXPECT_EQ(s.cloth.cols, 7);
    EXPECT_EQ(s.cloth.spacing, 0.1);
    EXPECT_EQ(s.cloth.particle_mass, 2.0);
    EXPECT_EQ(s.cloth.layout, Layout::offset);
    EXPECT_EQ(s.cloth.orientation, Orientation::horizontal);
    EXPECT_EQ(s.cloth.origin, (Vec3d{1.0, 2.5, -3.0}));
    EXPECT_EQ(s.cloth.pin_preset, PinPreset::list);
    ASSERT_EQ(s.cloth.pin_list.size(), 2u);
    EXPECT_EQ(s.cloth.pin_list[1].row, 4);
    EXPECT_EQ(s.cloth.pin_list[1].col, 6);
    EXPECT_EQ(s.structural.stiffness, 10.0);
    EXPECT_EQ(s.structural.damping, 0.25);
    EXPECT_TRUE(s.shear.enabled);
    EXPECT_EQ(s.shear.stiffness, 20.0);
    EXPECT_EQ(s.shear.damping, 0.5);
    EXPECT_TRUE(s.bend.enabled);
    EXPECT_EQ(s.bend.stiffness, 30.0);
    EXPECT_EQ(s.bend.damping, 0.75);
    EXPECT_EQ(s.tear_max_stretch, 2.0);
    EXPECT_EQ(s.strain_limit_max_strain, 0.2);
    EXPECT_EQ(s.self_collision_thickness, 0.02);
    EXPECT_EQ(s.forces.gravity, (Vec3d{0.0, -1.5, 0.0}));
    EXPECT_EQ(s.forces.air_drag, 0.3);
    EXPECT_EQ(s.forces.wind, (Vec3d{4.0, 0.0, 5.0}));
    EXPECT_EQ(s.solver.integrator, Integrator::rk4);
    EXPECT_EQ(s.solver.dt, 0.0025);
    ASSERT_EQ(s.colliders.size(), 2u);
    EXPECT_EQ(s.colliders[0].type, ColliderType::plane);
    EXPECT_EQ(s.colliders[0].normal, (Vec3d{0.0, 2.0, 0.0}));  // as written, so it saves back
    EXPECT_EQ(make_colliders(s.colliders)[0].normal, Vec3(0.0, 1.0, 0.0));  // normalised
    EXPECT_EQ(s.colliders[0].response, ContactResponse::repulsion);
    EXPECT_EQ(s.colliders[0].restitution, 0.5);
    EXPECT_EQ(s.colliders[0].friction, 0.1);
    EXPECT_EQ(s.colliders[1].type, ColliderType::sphere);
    EXPECT_EQ(s.colliders[1].radius, 0.25);
    EXPECT_EQ(s.camera.position, (Vec3d{1.0, 2.0, 3.0}));
    EXPECT_EQ(s.camera.fov_degrees, 70.0);
    EXPECT_TRUE(result.warnings.empty());
}

TEST(SceneLoader, UnknownKeyNamesItsPositionAndSuggestsTheNearest) {
    const SceneError error = error_of("[springs.structural]\nstiffness = 1\nstifness = 3\n");
    EXPECT_EQ(error.where, "test.toml:3:1");
    EXPECT_TRUE(contains(error.what, "unknown key 'stifness'")) << error.what;
    EXPECT_TRUE(contains(error.what, "did you mean 'stiffness'")) << error.what;
    EXPECT_EQ(error.message(), "error: test.toml:3:1: " + error.what);
}

TEST(SceneLoader, UnknownTableIsRefused) {
    const SceneError error = error_of("\n[solvr]\ndt = 0.1\n");
    EXPECT_EQ(error.where, "test.toml:2:2");
    EXPECT_TRUE(contains(error.what, "did you mean 'solver'")) << error.what;
}

TEST(SceneLoader, WrongTypesAreRefused) {
    EXPECT_TRUE(contains(error_of("[cloth]\nrows = \"ten\"\n").what,
                         "cloth.rows must be an integer, got a string"));
    EXPECT_EQ(error_of("[cloth]\nrows = 2.5\n").where, "test.toml:2:8");
    EXPECT_TRUE(contains(error_of("[solver]\ndt = \"fast\"\n").what, "solver.dt must be a number"));
    EXPECT_TRUE(contains(error_of("[forces]\ngravity = [0, -9.81]\n").what, "array of 3 numbers"));
    EXPECT_TRUE(contains(error_of("cloth = 3\n").what, "cloth must be a table"));
    EXPECT_TRUE(contains(error_of("[springs.bend]\nenabled = 1\n").what, "true or false"));
}

TEST(SceneLoader, OutOfRangeValuesAreRefused) {
    EXPECT_EQ(error_of("[solver]\ndt = -0.001\n").where, "test.toml:2:6");
    EXPECT_TRUE(contains(error_of("[solver]\ndt = 0\n").what, "solver.dt must be > 0, got 0"));
    EXPECT_TRUE(
        contains(error_of("[cloth]\nparticle_mass = 0\n").what, "cloth.particle_mass must be > 0"));
    EXPECT_TRUE(contains(error_of("[cloth]\nspacing = -1\n").what, "cloth.spacing must be > 0"));
    EXPECT_TRUE(contains(error_of("[cloth]\nrows = 0\n").what, "cloth.rows must be between 1"));
    EXPECT_TRUE(contains(error_of("[cloth]\ncols = -3\n").what, "cloth.cols must be between 1"));
    EXPECT_TRUE(contains(error_of("[springs.shear]\nstiffness = -1\n").what, "must be >= 0"));
    EXPECT_TRUE(contains(error_of("[tearing]\nmax_stretch = 1\n").what, "must be > 1"));
    EXPECT_TRUE(contains(error_of("[[colliders]]\nrestitution = 1.5\n").what, "must be <= 1"));
    EXPECT_TRUE(contains(error_of("[[colliders]]\nnormal = [0, 0, 0]\n").what, "must not be zero"));
    // Its square overflows: it could not be normalised.
    EXPECT_TRUE(contains(error_of("[[colliders]]\nnormal = [1e200, 0, 0]\n").what, "overflows"));
    EXPECT_TRUE(contains(error_of("[solver]\ndt = nan\n").what, "finite"));
    EXPECT_TRUE(contains(error_of("[forces]\nwind = [0, inf, 0]\n").what, "finite"));
    EXPECT_TRUE(
        contains(error_of("[springs.structural]\nenabled = false\n").what, "cannot be disabled"));
}

// [strain_limit] max_strain is a strain (0.1: within 10 % of rest length); its old name
// max_stretch, which [tearing] uses for a ratio of lengths, invited 1.5 for "150 %", which
// limited nothing. A strain of 100 % or more is refused under either name; the old name still
// loads, meaning the same strain, with a warning that names where it is.
TEST(SceneLoader, TheStrainLimitIsAStrainBelowOneUnderItsNewNameOrItsOld) {
    EXPECT_TRUE(contains(error_of("[strain_limit]\nmax_strain = 1.5\n").what,
                         "strain_limit.max_strain must be < 1, got 1.5"));
    EXPECT_TRUE(contains(error_of("[strain_limit]\nmax_strain = 1\n").what, "must be < 1"));
    EXPECT_TRUE(contains(error_of("[strain_limit]\nmax_stretch = 1.5\n").what,
                         "strain_limit.max_stretch must be < 1, got 1.5"));
    EXPECT_TRUE(contains(error_of("[strain_limit]\nmax_strain = 0\n").what, "must be > 0"));
    EXPECT_TRUE(contains(error_of("[strain_limit]\nmax_strain = 0.1\nmax_stretch = 0.1\n").what,
                         "give max_strain alone"));

    const SceneLoadResult current = load_scene_text("[strain_limit]\nmax_strain = 0.1\n", "a.toml");
    ASSERT_TRUE(current.ok());
    EXPECT_EQ(current.scene->strain_limit_max_strain, 0.1);
    EXPECT_TRUE(current.warnings.empty());

    const SceneLoadResult old = load_scene_text("[strain_limit]\nmax_stretch = 0.1\n", "old.toml");
    ASSERT_TRUE(old.ok());
    EXPECT_EQ(old.scene->strain_limit_max_strain, 0.1);
    ASSERT_EQ(old.warnings.size(), 1u);
    EXPECT_TRUE(contains(old.warnings[0], "old.toml:2:15")) << old.warnings[0];
    EXPECT_TRUE(contains(old.warnings[0], "old name of strain_limit.max_strain"))
        << old.warnings[0];

    const SceneLoadResult set = load_scene_text("", "a.toml", {"strain_limit.max_stretch=0.2"});
    ASSERT_TRUE(set.ok());
    EXPECT_EQ(set.scene->strain_limit_max_strain, 0.2);
    ASSERT_EQ(set.warnings.size(), 1u);
    EXPECT_TRUE(contains(set.warnings[0], "--set strain_limit.max_stretch")) << set.warnings[0];
}

TEST(SceneLoader, AGridTooLargeForMemoryIsRefusedWithoutAllocating) {
    const SceneError error = error_of("[cloth]\nrows = 100000\ncols = 100000\n");
    EXPECT_EQ(error.where, "test.toml:2:8");
    EXPECT_TRUE(contains(error.what, "4194304")) << error.what;
    // Larger than an int: still a clean message.
    EXPECT_TRUE(contains(error_of("[cloth]\nrows = 1000000000000\n").what,
                         "cloth.rows must be between 1 and 4194304"));
}

TEST(SceneLoader, ASelfCollisionThicknessOfManySpacingsIsRefused) {
    // Every particle within the thickness of every other: the pass would be all pairs (a
    // fuzzed 64² drape with a 1 m thickness hung the fuzzer). Two spacings is the most.
    const SceneError error =
        error_of("[cloth]\nspacing = 0.01\n[self_collision]\nthickness = 1.0\n");
    EXPECT_EQ(error.where, "test.toml:4:13");
    EXPECT_TRUE(contains(error.what, "more than 2 particle spacings")) << error.what;
    EXPECT_TRUE(contains(error.what, "at most 0.02 m")) << error.what;
    // The default thickness (0.01 m) is blamed on the table that asked for it.
    EXPECT_EQ(error_of("[cloth]\nspacing = 0.004\n[self_collision]\n").where, "test.toml:3:1");
    // Two spacings exactly is allowed.
    EXPECT_TRUE(load_scene_text("[cloth]\nspacing = 0.01\n[self_collision]\nthickness = 0.02\n",
                                "test.toml")
                    .ok());
}

TEST(SceneLoader, PinsOutsideTheGridAreRefused) {
    const SceneError error = error_of("[cloth]\nrows = 24\ncols = 24\npins = [[0, 0], [30, 2]]\n");
    EXPECT_EQ(error.where, "test.toml:4:17");
    EXPECT_TRUE(contains(error.what, "pin [30, 2] is outside the 24×24 grid")) << error.what;
    EXPECT_TRUE(contains(error_of("[cloth]\npins = [[0]]\n").what, "[row, col]"));
    EXPECT_TRUE(contains(error_of("[cloth]\npins = 3\n").what, "cloth.pins must be"));
}

TEST(SceneLoader, BadChoiceListsTheOptionsAndSuggests) {
    const SceneError error = error_of("[solver]\nintegrator = \"rk5\"\n");
    EXPECT_TRUE(contains(error.what, "\"symplectic-euler\"")) << error.what;
    EXPECT_TRUE(contains(error.what, "got \"rk5\" (did you mean \"rk4\"?)")) << error.what;
}

TEST(SceneLoader, SyntaxErrorNamesItsPosition) {
    const SceneError error = error_of("[cloth]\nrows = = 3\n");
    EXPECT_TRUE(error.where.rfind("test.toml:2:", 0) == 0) << error.where;
}

TEST(SceneLoader, MissingFileIsAnError) {
    SceneLoadResult result = load_scene_file("/nonexistent/scene.toml");
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error->where, "/nonexistent/scene.toml");
    EXPECT_TRUE(contains(result.error->what, "cannot read file"));
}

// A directory opens as a stream that reads as nothing, and nothing is the default scene: it
// must be refused, not run as the default sheet.
TEST(SceneLoader, ADirectoryIsNotASceneFile) {
    const std::string folder = std::string(WEFT_SOURCE_DIR) + "/assets/scenes";
    SceneLoadResult result = load_scene_file(folder);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error->where, folder);
    EXPECT_EQ(result.error->what, "is a directory, not a scene file");
}

TEST(SceneOverrides, ChangeValuesLikeTheFileWould) {
    SceneLoadResult result = load("[solver]\ndt = 0.001\n",
                                  {"solver.dt=0.0005", "cloth.rows=40", "solver.integrator=rk4",
                                   "forces.gravity=[0,-1,0]", "name=\"Override\""});
    ASSERT_TRUE(result.ok()) << result.error->message();
    EXPECT_EQ(result.scene->solver.dt, 0.0005);
    EXPECT_EQ(result.scene->cloth.rows, 40);
    EXPECT_EQ(result.scene->solver.integrator, Integrator::rk4);  // bare word: a string
    EXPECT_EQ(result.scene->forces.gravity, (Vec3d{0.0, -1.0, 0.0}));
    EXPECT_EQ(result.scene->name, "Override");
}

TEST(SceneOverrides, SwitchSpringFamiliesOnAndOff) {
    SceneLoadResult off = load("[springs.bend]\nstiffness = 5\n", {"springs.bend.enabled=false"});
    ASSERT_TRUE(off.ok());
    EXPECT_FALSE(off.scene->bend.enabled);
    SceneLoadResult on = load("", {"springs.shear.stiffness=300"});
    ASSERT_TRUE(on.ok());
    EXPECT_TRUE(on.scene->shear.enabled);
    EXPECT_EQ(on.scene->shear.stiffness, 300.0);
    SceneLoadResult pins = load("", {"cloth.pins=[[0,1],[2,3]]"});
    ASSERT_TRUE(pins.ok());
    EXPECT_EQ(pins.scene->cloth.pin_list.size(), 2u);
}

TEST(SceneOverrides, AreCheckedExactlyLikeTheFileAndBlamedByKey) {
    SceneError error = error_of("", {"solver.dt=-1"});
    EXPECT_EQ(error.where, "--set solver.dt");
    EXPECT_TRUE(contains(error.what, "solver.dt must be > 0")) << error.what;
    error = error_of("", {"cloth.rowz=3"});
    EXPECT_EQ(error.where, "--set cloth.rowz");
    EXPECT_TRUE(contains(error.what, "did you mean 'rows'")) << error.what;
    error = error_of("", {"solver.dt=abc"});
    EXPECT_EQ(error.where, "--set solver.dt");
    EXPECT_TRUE(contains(error.what, "must be a number, got a string")) << error.what;
    error = error_of("", {"cloth.pins=[[99,0]]"});
    EXPECT_EQ(error.where, "--set cloth.pins");
    // A file error stays a file error even when overrides are present.
    error = error_of("[cloth]\nrows = 0\n", {"solver.dt=0.1"});
    EXPECT_EQ(error.where, "test.toml:2:8");
}

TEST(SceneOverrides, MalformedOverridesAreRefused) {
    EXPECT_EQ(error_of("", {"nonsense"}).where, "--set nonsense");
    EXPECT_EQ(error_of("", {"=3"}).where, "--set ");
    EXPECT_EQ(error_of("", {"solver..dt=3"}).where, "--set solver..dt");
    EXPECT_EQ(error_of("", {"solver.dt="}).where, "--set solver.dt");
    EXPECT_TRUE(contains(error_of("[solver]\ndt = 0.1\n", {"solver.dt.x=3"}).what, "not a table"));
    // Where the path does not exist yet, the table it makes fails the type check instead.
    EXPECT_TRUE(
        contains(error_of("", {"solver.dt.x=3"}).what, "solver.dt must be a number, got a table"));
}

}  // namespace
}  // namespace weft
