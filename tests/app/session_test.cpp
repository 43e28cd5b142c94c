// Recording and replaying a session, and runs side by side, through the DemoState calls the
// window makes.
//
// Truths: a replay of a recorded session ends in the recorded state, bit for bit (state
// hash); a copy with the same integrator and dt fed the same events stays bit for bit equal
// to the main run; a recording reads back field for field.
#include <gtest/gtest.h>

#include <cmath>

#include "app/demo_state.h"
#include "app/session_record.h"
#include "shipped_demo.h"
#include "sim/build/topology_edits.h"
#include "sim/core/state_hash.h"
#include "sim/scene_io/scene_loader.h"

namespace weft::app {
namespace {

constexpr ViewSize view{800, 600};

// A busy session: frames of uneven length (as a real clock gives), a drag across the sheet,
// a cut, pins, parameter changes (one of them past the stability limit, so the run diverges
// and recovers), a change of method, a reset.
void play_a_busy_session(DemoState& state) {
    const int frame_steps[] = {16, 17, 9, 31, 16, 1, 24};
    int frame = 0;
    auto frames = [&](int count) {
        for (int f = 0; f < count; ++f) state.step(frame_steps[frame++ % 7]);
    };
    frames(60);  // it swings down
    state.reset_simulation();
    frames(120);  // and again, to rest
    ASSERT_TRUE(state.grab({400.0f, 300.0f}, view));
    for (int move = 0; move < 40; ++move) {
        state.pull(
            {400.0f + 6.0f * static_cast<float>(move), 300.0f - 2.0f * static_cast<float>(move)},
            view);
        frames(1);
    }
    state.let_go();
    frames(20);
    std::size_t cut = 0;
    for (float y = 150.0f; y < 500.0f; y += 50.0f) {
        state.start_cut({0.0f, y}, view);
        for (int move = 1; move <= 10; ++move)
            cut += state.cut_to({80.0f * static_cast<float>(move), y + 10.0f}, view);
        state.end_cut();
    }
    EXPECT_GT(cut, 5u);
    frames(20);
    state.toggle_pin({420.0f, 360.0f}, view);
    ASSERT_FALSE(state.change({"springs.shear.stiffness=150", "forces.wind=[2,0,-1]"}));
    frames(30);
    ASSERT_FALSE(state.change({"solver.dt=0.006"}));  // past the limit: diverges, recovers
    frames(30);
    ASSERT_FALSE(state.change({"solver.integrator=velocity-verlet"}));
    frames(30);
    state.release_all_pins();
    frames(10);
}

TEST(Session, AReplayEndsInTheRecordedStateBitForBit) {
    DemoState recorder = demo();
    recorder.start_recording();
    play_a_busy_session(recorder);
    EXPECT_GE(recorder.main_run().recovery.recoveries, 1);  // the session included a recovery
    const SessionRecord recorded = recorder.stop_recording();
    ASSERT_GT(recorded.events.size(), 40u);

    // Through the file format, into a demo that has been doing something else.
    std::string error;
    const std::optional<SessionRecord> read =
        session_from_toml(session_to_toml(recorded), "session.toml", error);
    ASSERT_TRUE(read) << error;
    DemoState player = demo("all_springs.toml");
    player.step(100);
    player.start_replay(*read);
    int frames = 0;
    while (!player.replay_finished() && frames++ < 100000) player.step(50);
    EXPECT_TRUE(player.replay_matches());
    EXPECT_EQ(hash_state(player.simulation().cloth()), recorded.final_state_hash);
    EXPECT_EQ(player.steps_run, recorded.steps);

    // The hand and the panel wait while a replay runs, and come back after it.
    const std::uint64_t replayed = hash_state(player.simulation().cloth());
    player.reset_simulation();
    player.start_cut({0.0f, 0.0f}, view);
    player.cut_to({800.0f, 600.0f}, view);
    EXPECT_TRUE(player.change({"springs.structural.stiffness=100"}).has_value());
    EXPECT_EQ(hash_state(player.simulation().cloth()), replayed);
    player.stop_replay();
    EXPECT_FALSE(player.change({"springs.structural.stiffness=100"}).has_value());
}

TEST(Session, TheEventsMatterSoAMatchIsNotAnAccident) {
    DemoState recorder = demo();
    recorder.start_recording();
    play_a_busy_session(recorder);
    SessionRecord recorded = recorder.stop_recording();
    // The same session without its cut: the replay must notice.
    std::erase_if(recorded.events,
                  [](const TimedEvent& e) { return e.event.kind == ClothEvent::Kind::cut; });
    DemoState player = demo();
    player.start_replay(recorded);
    while (!player.replay_finished()) player.step(64);
    EXPECT_FALSE(player.replay_matches());
}

TEST(Session, ARecordingReadsBackFieldForField) {
    SessionRecord record;
    record.scene_toml = "name = \"tiny\"\n[cloth]\nrows = 3\ncols = 3\n";
    record.steps = 1234567;
    record.final_state_hash = 0xfedcba9876543210u;
    ClothEvent grab;
    grab.kind = ClothEvent::Kind::grab;
    grab.hit = {5, 2, 1.0 / 3.0, {0.1, -0.2, 1e-300}};
    grab.radius = 0.08;
    ClothEvent pull;
    pull.kind = ClothEvent::Kind::pull;
    pull.target = {1e6, -0.30000000000000004, 2.5};
    ClothEvent cut;
    cut.kind = ClothEvent::Kind::cut;
    cut.springs = {edge_key(0, 1), edge_key(1, 4), edge_key(7, 8)};
    ClothEvent pin;
    pin.kind = ClothEvent::Kind::pin;
    pin.particle = 8;
    ClothEvent parameters;  // a format-1 recording's whole scene
    parameters.kind = ClothEvent::Kind::parameters;
    Scene whole;
    whole.name = "quote \" backslash \\";
    whole.solver.dt = 0.0005;
    parameters.scene = std::make_shared<const Scene>(whole);
    // Every type an edit's value can have, each to the last bit.
    ClothEvent edit;
    edit.kind = ClothEvent::Kind::edit;
    edit.edits = {
        {SceneKey::shear_stiffness, 0.1 + 0.2},
        {SceneKey::cloth_rows, std::int64_t{4194304}},
        {SceneKey::bend_enabled, true},
        {SceneKey::wind, Vec3d{1e-300, -0.30000000000000004, 7.0}},
        {SceneKey::integrator, Integrator::velocity_verlet},
        {SceneKey::cloth_layout, Layout::offset},
        {SceneKey::cloth_orientation, Orientation::horizontal},
        {SceneKey::collider_response, ContactResponse::repulsion, 3},
        {SceneKey::cloth_pins, GridPins{PinPreset::list, {{0, 0}, {2, 7}}}},
        {SceneKey::cloth_pins, GridPins{PinPreset::top_row, {}}},
        {SceneKey::tear_max_stretch, FeatureOff{}},
        {SceneKey::self_collision_thickness, 0.004},
    };
    for (const ClothEvent& event : {grab, pull, plain_event(ClothEvent::Kind::let_go), cut, pin,
                                    plain_event(ClothEvent::Kind::release_pins), parameters, edit,
                                    plain_event(ClothEvent::Kind::reset)})
        record.events.push_back({record.events.size() * 10, event});
    std::string error;
    auto read = session_from_toml(session_to_toml(record), "s.toml", error);
    ASSERT_TRUE(read) << error << "\n" << session_to_toml(record);
    EXPECT_EQ(read->scene_toml, record.scene_toml);
    EXPECT_EQ(read->steps, record.steps);
    EXPECT_EQ(read->final_state_hash, record.final_state_hash);
    ASSERT_EQ(read->events.size(), record.events.size());
    for (std::size_t e = 0; e < record.events.size(); ++e) {
        const ClothEvent& a = record.events[e].event;
        const ClothEvent& b = read->events[e].event;
        EXPECT_EQ(read->events[e].step, record.events[e].step);
        EXPECT_EQ(a.kind, b.kind);
        EXPECT_EQ(a.hit.particle, b.hit.particle);
        EXPECT_EQ(a.hit.triangle, b.hit.triangle);
        EXPECT_EQ(a.hit.distance, b.hit.distance);
        EXPECT_EQ(a.hit.point, b.hit.point);
        EXPECT_EQ(a.radius, b.radius);
        EXPECT_EQ(a.target, b.target);
        EXPECT_EQ(a.springs, b.springs);
        EXPECT_EQ(a.particle, b.particle);
        EXPECT_EQ(a.edits, b.edits);
        ASSERT_EQ(a.scene == nullptr, b.scene == nullptr);
        if (a.scene) {
            EXPECT_TRUE(*a.scene == *b.scene);
        }
    }
}

TEST(Session, AMalformedRecordingIsRefusedWithAPosition) {
    const std::string good_head =
        "format = 1\nsteps = 100\nfinal_state_hash = \"0x0000000000000001\"\nscene = \"\"\n";
    const std::pair<std::string, std::string> cases[] = {
        {"format = 1\nsteps = \n", "s.toml:2:"},
        {"format = 3\nsteps = 1\nfinal_state_hash = \"0x0000000000000001\"\nscene = \"\"\n",
         "s.toml:1:"},
        {"format = 1\nsteps = -1\n", "s.toml:2:"},
        {"format = 1\nsteps = 1\nfinal_state_hash = \"12\"\nscene = \"\"\n", "s.toml:3:"},
        {good_head + "\n[[events]]\nstep = 5\nkind = \"teleport\"\n", "s.toml:8:"},
        {good_head + "\n[[events]]\nstep = 5\nkind = \"pin\"\nparticle = -3\n", "s.toml:9:"},
        {good_head + "\n[[events]]\nstep = 50\nkind = \"reset\"\n[[events]]\nstep = 40\n"
                     "kind = \"reset\"\n",
         "order of step"},
        {good_head + "\n[[events]]\nstep = 500\nkind = \"reset\"\n", "after the last step"},
        {good_head + "\n[[events]]\nstep = 5\nkind = \"pull\"\ntarget = [1, nan, 2]\n",
         "s.toml:9:"},
        {good_head + "\n[[events]]\nstep = 5\nkind = \"cut\"\nsprings = [[1, 2, 3]]\n",
         "s.toml:9:"},
        {good_head + "\n[[events]]\nstep = 5\nkind = \"parameters\"\nscene = \"[solver]\\ndt = "
                     "-1\\n\"\n",
         "dt"},
        // Typed edits (format 2): a key no edit reaches, a value of the wrong type, none.
        {good_head + "\n[[events]]\nstep = 5\nkind = \"edit\"\nedits = [{key = "
                     "\"springs.shear.stifness\", value = 1.0}]\n",
         "s.toml:9:"},
        {good_head + "\n[[events]]\nstep = 5\nkind = \"edit\"\nedits = [{key = "
                     "\"springs.shear.stifness\", value = 1.0}]\n",
         "did you mean 'springs.shear.stiffness'"},
        {good_head + "\n[[events]]\nstep = 5\nkind = \"edit\"\nedits = [{key = \"solver.dt\", "
                     "value = \"fast\"}]\n",
         "solver.dt must be a number"},
        {good_head + "\n[[events]]\nstep = 5\nkind = \"edit\"\nedits = [{key = \"solver.dt\", "
                     "value = \"fast\"}]\n",
         "s.toml:9:"},
        {good_head + "\n[[events]]\nstep = 5\nkind = \"edit\"\nedits = [{key = "
                     "\"colliders.x.radius\", value = 1.0}]\n",
         "s.toml:9:"},
        {good_head + "\n[[events]]\nstep = 5\nkind = \"edit\"\nedits = []\n", "s.toml:9:"},
        {"format = 1\nsteps = 1\nfinal_state_hash = \"0x0000000000000001\"\nscene = \"[cloth]\\n"
         "rows = 0\\n\"\n",
         "rows"},
    };
    for (const auto& [text, expected] : cases) {
        std::string error;
        EXPECT_FALSE(session_from_toml(text, "s.toml", error)) << text;
        EXPECT_NE(error.find(expected), std::string::npos) << error << "\n--- for ---\n" << text;
    }
}

TEST(SideBySide, ACopyWithTheSameMethodStaysIdenticalThroughTheSameHand) {
    DemoState state = demo();
    state.step(2000);
    state.add_copy(state.simulation().integrator(), state.simulation().dt());
    state.add_copy(Integrator::rk4, 0.5 * state.simulation().dt());
    ASSERT_TRUE(state.grab({400.0f, 300.0f}, view, 1));  // picked on the copy: goes to all
    for (int move = 0; move < 30; ++move) {
        state.pull(
            {400.0f - 5.0f * static_cast<float>(move), 300.0f + 3.0f * static_cast<float>(move)},
            view);
        state.step(16);
        EXPECT_TRUE(state.runs[2].simulation.grab().active());
    }
    state.let_go();
    state.start_cut({350.0f, 250.0f}, view, 2);
    state.cut_to({450.0f, 350.0f}, view, 2);
    state.toggle_pin({400.0f, 300.0f}, view);
    ASSERT_FALSE(state.change({"springs.structural.stiffness=600"}));
    state.step(200);
    const Simulation& twin = state.runs[1].simulation;
    const Simulation& rk4 = state.runs[2].simulation;
    EXPECT_EQ(hash_state(twin.cloth()), hash_state(state.simulation().cloth()));
    EXPECT_EQ(twin.cloth().spring_count(), state.simulation().cloth().spring_count());
    // The rk4 copy kept its own method and dt, took the same material, and keeps time.
    EXPECT_EQ(rk4.integrator(), Integrator::rk4);
    EXPECT_EQ(rk4.dt(), 0.5 * state.simulation().dt());
    EXPECT_EQ(rk4.scene().structural.stiffness, 600.0);
    EXPECT_NEAR(rk4.time(), state.simulation().time(), 0.5 * rk4.dt());
    EXPECT_NE(hash_state(rk4.cloth()), hash_state(state.simulation().cloth()));
}

TEST(SideBySide, ACopyThatRollsBackCatchesUpWithoutStallingAFrame) {
    DemoState state = demo();
    // Explicit Euler at 4 ms on this sheet diverges; its copy rolls back and halves its dt.
    state.add_copy(Integrator::explicit_euler, 0.004);
    const Simulation& copy = state.runs[1].simulation;
    for (int frame = 0; frame < 300; ++frame) {
        const double before = copy.time();
        const double copy_dt = copy.dt();
        state.step(16);
        const double most = 16 * (std::ceil(state.simulation().dt() / copy_dt) + 1) * copy_dt;
        ASSERT_LE(copy.time() - before, most + 1e-12) << "frame " << frame;
        ASSERT_LE(copy.time(), state.simulation().time() + 0.5 * copy.dt() + 1e-12);
    }
    EXPECT_GE(state.runs[1].recovery.recoveries, 1);
    EXPECT_NEAR(copy.time(), state.simulation().time(), copy.dt());  // caught up in the end
}

TEST(SideBySide, ACopyChangesOnlyItsOwnSolver) {
    DemoState state = demo();
    state.add_copy(Integrator::verlet, 0.001);
    EXPECT_FALSE(state.change_copy(0, {"solver.integrator=rk4", "solver.dt=0.002"}));
    EXPECT_EQ(state.runs[1].simulation.integrator(), Integrator::rk4);
    EXPECT_EQ(state.runs[1].simulation.dt(), 0.002);
    EXPECT_EQ(state.simulation().integrator(), Integrator::symplectic_euler);
    const Scene before = state.runs[1].simulation.scene();
    EXPECT_TRUE(state.change_copy(0, {"springs.structural.stiffness=5"}));
    EXPECT_TRUE(state.change_copy(0, {"solver.dt=0"}));
    EXPECT_TRUE(state.runs[1].simulation.scene() == before);
    EXPECT_TRUE(state.change_copy(3, {"solver.dt=0.001"}));
}

}  // namespace
}  // namespace weft::app

namespace weft::app {
namespace {

// A session of parameter changes only, as a user playing with the panel makes: 200 ticks of
// a stiffness slider, a wind, a change of method, a new grid (a rebuilt cloth).
std::vector<Scene> play_slider_ticks(DemoState& state) {
    std::vector<Scene> after_each;  // the running scene after each change
    auto change = [&](const std::vector<SceneEdit>& edits) {
        ASSERT_FALSE(state.edit(edits));
        after_each.push_back(state.simulation().scene());
        state.step(3);
    };
    for (int tick = 0; tick < 200; ++tick)
        change({{SceneKey::shear_stiffness, 100.0 + 1.5 * tick}});
    change({{SceneKey::wind, Vec3d{2.0, 0.0, -1.0}}, {SceneKey::air_drag, 0.002}});
    change({{SceneKey::integrator, Integrator::velocity_verlet}});
    change({{SceneKey::cloth_rows, std::int64_t{14}},
            {SceneKey::cloth_pins, GridPins{PinPreset::top_row, {}}}});
    state.step(40);
    return after_each;
}

// The same session as format 1 stored it: each change as kind = "parameters" with the whole
// scene it made (`scenes`, one per edit event).
SessionRecord as_format_one(const SessionRecord& typed, const std::vector<Scene>& scenes) {
    SessionRecord whole = typed;
    for (std::size_t e = 0; e < whole.events.size(); ++e) {
        whole.events[e].event.kind = ClothEvent::Kind::parameters;
        whole.events[e].event.edits.clear();
        whole.events[e].event.scene = std::make_shared<const Scene>(scenes[e]);
    }
    return whole;
}

TEST(Session, TypedEditsMakeARecordingOfSliderTicksOverTenTimesSmaller) {
    DemoState recorder = demo();
    recorder.start_recording();
    const std::vector<Scene> scenes = play_slider_ticks(recorder);
    const SessionRecord typed = recorder.stop_recording();
    ASSERT_EQ(typed.events.size(), scenes.size());
    const SessionRecord whole = as_format_one(typed, scenes);
    const std::size_t typed_bytes = session_to_toml(typed).size();
    const std::size_t whole_bytes = session_to_toml(whole).size();
    EXPECT_LT(10 * typed_bytes, whole_bytes) << typed_bytes << " against " << whole_bytes;
    std::printf("203 parameter changes: %zu bytes typed, %zu bytes as whole scenes (%.1fx)\n",
                typed_bytes, whole_bytes,
                static_cast<double>(whole_bytes) / static_cast<double>(typed_bytes));
}

TEST(Session, AFormatOneRecordingOfWholeScenesStillReplaysBitForBit) {
    DemoState recorder = demo();
    recorder.start_recording();
    const std::vector<Scene> scenes = play_slider_ticks(recorder);
    const SessionRecord typed = recorder.stop_recording();
    const SessionRecord whole = as_format_one(typed, scenes);
    std::string text = session_to_toml(whole);
    const std::size_t format = text.find("format = 2");
    ASSERT_NE(format, std::string::npos);
    text.replace(format, 10, "format = 1");
    std::string error;
    const std::optional<SessionRecord> read = session_from_toml(text, "old.toml", error);
    ASSERT_TRUE(read) << error;
    DemoState player = demo();
    player.start_replay(*read);
    while (!player.replay_finished()) player.step(64);
    EXPECT_TRUE(player.replay_matches());
    EXPECT_EQ(hash_state(player.simulation().cloth()), typed.final_state_hash);
    EXPECT_EQ(player.simulation().cloth().rows, 14);
}

}  // namespace
}  // namespace weft::app
