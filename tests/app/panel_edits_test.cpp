// What the panel edits beyond the sliders of old: gravity as a vector, the wind's vertical
// part, the camera's field of view, where each collider is and its size, and the grid rebuilt
// on Apply; each through the calls the panel makes, checked like a scene file.
//
// Truths: a taken edit shows in the running simulation (or camera) exactly as typed; a
// refused one leaves the scene equal field by field and the state hash equal, and says why
// in words the panel's font can draw; a grid is rebuilt with rows × cols particles.
#include <gtest/gtest.h>

#include <cmath>

#include "app/demo_state.h"
#include "app/edit_answer.h"
#include "app/grid_edit.h"
#include "shipped_demo.h"
#include "sim/core/state_hash.h"

namespace weft::app {
namespace {

// Expects `edit` to be refused by the loader and to change nothing; returns the refusal as
// the panel says it.
template <class Edit>
std::string refused(DemoState& state, Edit edit) {
    const Scene before = state.simulation().scene();
    const std::uint64_t hash = hash_state(state.simulation().cloth());
    const float fov = state.rig.fov_degrees;
    const std::optional<std::string> error = edit(state);
    EXPECT_TRUE(error.has_value());
    EXPECT_TRUE(state.simulation().scene() == before);
    EXPECT_EQ(hash_state(state.simulation().cloth()), hash);
    EXPECT_EQ(state.rig.fov_degrees, fov);
    return error ? refusal_text(*error) : std::string();
}

// The window steps in real time: a dt it could not step in a frame (1e9 ms froze the run with
// "0 steps a frame") is refused with the bound, in the main run and in a copy; the longest
// allowed is taken.
TEST(PanelEdits, ADtTheWindowCannotStepIsRefused) {
    DemoState state = demo();
    state.add_copy(Integrator::rk4, state.simulation().dt());
    for (const double dt : {1e6, 0.5, std::nextafter(StepClock::max_dt, 1.0)}) {
        const std::string why = refused(state, [&](DemoState& s) {
            return s.edit({{SceneKey::dt, dt}});
        });
        EXPECT_NE(why.find("solver.dt: at most 100 ms in the window"), std::string::npos) << why;
        EXPECT_TRUE(state.edit_copy(0, {{SceneKey::dt, dt}}).has_value());
    }
    EXPECT_FALSE(state.edit({{SceneKey::dt, StepClock::max_dt}}));
    EXPECT_EQ(state.simulation().dt(), StepClock::max_dt);
    EXPECT_FALSE(state.edit_copy(0, {{SceneKey::dt, StepClock::max_dt}}));
}

TEST(PanelEdits, GravityIsAVectorCheckedAndAppliedLive) {
    DemoState state = demo();
    state.step(50);
    const double time = state.simulation().time();
    ASSERT_FALSE(state.change({"forces.gravity=[1.5,-3,0.25]"}));
    EXPECT_EQ(state.simulation().force_field().gravity, Vec3(1.5, -3.0, 0.25));
    EXPECT_EQ(state.simulation().time(), time);  // the same cloth, still running
    for (const char* bad : {"forces.gravity=[0,-9.81]", "forces.gravity=[0,nan,0]"})
        refused(state, [&](DemoState& s) { return s.change({bad}); });
}

TEST(PanelEdits, TheWindHasAVerticalPart) {
    DemoState state = demo();
    ASSERT_FALSE(state.change({"forces.wind=[1,2.5,0]"}));
    EXPECT_EQ(state.simulation().force_field().wind, Vec3(1.0, 2.5, 0.0));
}

TEST(PanelEdits, TheFieldOfViewIsCheckedLikeASceneFile) {
    DemoState state = demo();
    ASSERT_FALSE(state.change_field_of_view(30.0));
    EXPECT_EQ(state.rig.fov_degrees, 30.0f);
    EXPECT_EQ(state.scene_to_save().camera.fov_degrees, 30.0);  // saved as seen
    for (double bad : {0.0, 180.0, -10.0, std::nan("")}) {
        const std::string why =
            refused(state, [&](DemoState& s) { return s.change_field_of_view(bad); });
        EXPECT_NE(why.find("camera.fov_degrees"), std::string::npos) << why;
    }
}

TEST(PanelEdits, AColliderMovesAndResizesAndABadPlaceIsRefused) {
    DemoState state = demo("tablecloth.toml");
    state.step(20);
    Scene wanted = state.simulation().scene();
    ASSERT_EQ(wanted.colliders.size(), 2u);
    wanted.colliders[0].center = {0.1, 0.15, -0.05};
    wanted.colliders[0].radius = 0.4;
    wanted.colliders[1].point = {0.0, -0.5, 0.0};
    ASSERT_FALSE(state.change_scene(wanted));
    const Collider& sphere = state.simulation().colliders()[0];
    EXPECT_EQ(sphere.center, Vec3(0.1, 0.15, -0.05));
    EXPECT_EQ(sphere.radius, 0.4);
    EXPECT_EQ(state.simulation().colliders()[1].point, Vec3(0.0, -0.5, 0.0));
    Scene bad = state.simulation().scene();
    bad.colliders[0].radius = -0.1;
    refused(state, [&](DemoState& s) { return s.change_scene(bad); });
}

TEST(PanelEdits, ApplyRebuildsTheGridAsDrafted) {
    DemoState state = demo();
    ClothSpec draft = state.simulation().scene().cloth;
    draft.rows = 9;
    draft.cols = 13;
    draft.spacing = 0.04;
    draft.layout = Layout::offset;
    draft.orientation = Orientation::horizontal;
    draft.pin_preset = PinPreset::list;
    draft.pin_list = {{0, 0}, {8, 12}};
    ASSERT_FALSE(state.edit(grid_edits(draft)));
    const Scene& scene = state.simulation().scene();
    EXPECT_TRUE(scene.cloth == draft);
    const Cloth& cloth = state.simulation().cloth();
    ASSERT_EQ(cloth.particle_count(), 9u * 13u);
    EXPECT_TRUE(cloth.is_pinned(0));
    EXPECT_TRUE(cloth.is_pinned(9 * 13 - 1));
    EXPECT_FALSE(cloth.is_pinned(12));  // the top row's other end: not in the list
    EXPECT_EQ(state.step(10), 10);
    for (PinPreset preset : {PinPreset::none, PinPreset::top_row, PinPreset::top_corners}) {
        draft.pin_preset = preset;
        ASSERT_FALSE(state.edit(grid_edits(draft)));
        EXPECT_EQ(state.simulation().scene().cloth.pin_preset, preset);
    }
}

TEST(PanelEdits, ApplyingTheRunningGridChangesNothingBitForBit) {
    DemoState applied = demo(), untouched = demo();
    applied.step(100);
    untouched.step(100);
    ASSERT_FALSE(applied.edit(grid_edits(applied.simulation().scene().cloth)));
    applied.step(100);
    untouched.step(100);
    EXPECT_EQ(hash_state(applied.simulation().cloth()), hash_state(untouched.simulation().cloth()));
}

TEST(PanelEdits, AHugeGridIsRefusedAtOnceWithTheLimit) {
    DemoState state = demo();
    ClothSpec draft = state.simulation().scene().cloth;
    draft.rows = 100000;
    draft.cols = 100000;
    const std::size_t particles_before = state.simulation().cloth().particle_count();
    const std::string why = refused(state, [&](DemoState& s) { return s.edit(grid_edits(draft)); });
    // Refused by the count, before anything is built: the running sheet is the one it was.
    EXPECT_EQ(state.simulation().cloth().particle_count(), particles_before);
    EXPECT_NE(why.find("more than the limit of " + std::to_string(max_particles)),
              std::string::npos)
        << why;
    EXPECT_EQ(why.find("\u00d7"), std::string::npos) << why;  // the font draws "x", not "×"
    EXPECT_EQ(grid_particle_count(draft), 10'000'000'000LL);
}

TEST(PanelEdits, AGridTheWindowCannotStepIsRefusedAndTheSheetKept) {
    DemoState state = demo();
    state.step(20);
    ClothSpec draft = state.simulation().scene().cloth;
    draft.rows = 2048;
    draft.cols = 2048;
    ASSERT_LE(grid_particle_count(draft), max_particles);  // a scene file may have it
    const std::size_t particles_before = state.simulation().cloth().particle_count();
    const std::string why = refused(state, [&](DemoState& s) { return apply_grid(s, draft); });
    EXPECT_EQ(state.simulation().cloth().particle_count(), particles_before);
    EXPECT_NE(
        why.find("more than the window's limit of " + std::to_string(max_window_grid_particles)),
        std::string::npos)
        << why;
    EXPECT_EQ(why.find("\u00d7"), std::string::npos) << why;  // the font draws "x", not "×"
    draft.rows = static_cast<int>(max_window_grid_particles) + 1;
    draft.cols = 1;
    refused(state, [&](DemoState& s) { return apply_grid(s, draft); });
    // Signs the loader refuses are named as such, not multiplied into a count.
    draft.rows = -1000;
    draft.cols = -1000;
    EXPECT_EQ(
        refused(state, [&](DemoState& s) { return apply_grid(s, draft); }).find("window's limit"),
        std::string::npos);
    // Up to the limit the grid is built.
    draft.rows = static_cast<int>(max_window_grid_particles);
    draft.cols = 1;
    ASSERT_FALSE(apply_grid(state, draft));
    EXPECT_EQ(state.simulation().cloth().particle_count(),
              static_cast<std::size_t>(max_window_grid_particles));
}

TEST(PanelEdits, ABadGridIsRefusedAndSaysWhy) {
    DemoState state = demo();
    ClothSpec draft = state.simulation().scene().cloth;
    draft.pin_preset = PinPreset::list;
    draft.pin_list = {{0, 23}};
    draft.cols = 10;  // the pin falls outside
    EXPECT_NE(
        refused(state, [&](DemoState& s) { return s.edit(grid_edits(draft)); }).find("outside"),
        std::string::npos);
    draft = state.simulation().scene().cloth;
    draft.rows = 0;
    refused(state, [&](DemoState& s) { return s.edit(grid_edits(draft)); });
    draft = state.simulation().scene().cloth;
    draft.spacing = -0.05;
    refused(state, [&](DemoState& s) { return s.edit(grid_edits(draft)); });
}

}  // namespace
}  // namespace weft::app
