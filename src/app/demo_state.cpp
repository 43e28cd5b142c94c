// Table of contents: construction · stepping with recovery · runs side by side · the hand ·
// parameter changes · scenes (reset, load, save) · recording and replay. Pausing and what
// each frame measures are in demo_frame.cpp.
#include "app/demo_state.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "app/atomic_file.h"
#include "app/hand_tools.h"
#include "app/number_format.h"
#include "sim/core/state_hash.h"
#include "sim/scene_io/scene_edit_toml.h"
#include "sim/scene_io/scene_loader.h"
#include "sim/scene_io/scene_writer.h"

namespace weft::app {
namespace {

glm::vec3 to_vec3(const Vec3d& v) {
    return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}

Vec3d to_vec3d(const glm::vec3& v) {
    return {static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(v.z)};
}

DemoRun new_run(const Simulation& started, double restart_dt) {
    return DemoRun{started, view::ClothView(started.cloth()), {}, restart_dt, 0.0};
}

CameraRig scene_rig(const Scene& scene) {
    return CameraRig::looking_at(to_vec3(scene.camera.position), to_vec3(scene.camera.target),
                                 static_cast<float>(scene.camera.fov_degrees));
}

}  // namespace

// ---- construction -------------------------------------------------------------------------

DemoState::DemoState(const std::string& path, const std::vector<std::string>& scene_overrides,
                     const Scene& loaded)
    : scene_path(path),
      overrides(scene_overrides),
      scene(loaded),
      runs{new_run(Simulation(loaded), loaded.solver.dt)},
      ground_height(view::ground_height_below(simulation().cloth(), simulation().colliders())),
      rig(scene_rig(loaded)),
      initial_rig(rig) {}

void DemoState::after_new_state() {
    for (DemoRun& run : runs) {
        run.cloth_view = view::ClothView(run.simulation.cloth());
        run.recovery.forget();
    }
    ground_height = view::ground_height_below(simulation().cloth(), simulation().colliders());
    hand = Hand{};
    clock.reset();
}

void DemoState::replace_simulation(const Scene& new_scene) {
    for (std::size_t r = 0; r < runs.size(); ++r) {
        Scene own = new_scene;
        if (r > 0) own.solver = runs[r].simulation.scene().solver;  // a copy keeps its solver
        runs[r].simulation = Simulation(own);
    }
    after_new_state();
}

void DemoState::say(const std::string& text, Tone tone) {
    message = text;
    message_tone = tone;
    message_until = wall_now + 4.0;
    std::fprintf(stderr, "%s\n", text.c_str());
}

// ---- stepping with recovery -----------------------------------------------------------------

void DemoState::pause_hopeless(Recovery& hopeless, const std::string& run) {
    paused = true;
    single_step = false;
    say("paused: " + run + " restarted " + std::to_string(hopeless.restarts_in_a_row) +
            " times in a row, diverging at every step down to " +
            significant_text(smallest_recovery_dt * 1e3, 1) +
            " ms. Lower a stiffness, raise the particle mass or the damping, or choose "
            "implicit Euler; then P to run again",
        Tone::problem);
    hopeless.restarts_in_a_row = 0;  // P gives these parameters as many tries again
}

int DemoState::step(int steps) {
    auto apply_due_events = [&] {
        while (replaying && replay_next < replaying->events.size() &&
               replaying->events[replay_next].step <= steps_run)
            apply_to_all_runs(replaying->events[replay_next++].event);
    };
    for (DemoRun& run : runs) run.seconds = 0.0;
    apply_due_events();
    for (int s = 0; s < steps; ++s) {
        if (replay_finished()) return s;  // a replay ends where its recording ended
        ++steps_run;
        std::string why;
        const bool sound = main_run().recovery.step(simulation(), main_run().restart_dt, why);
        for (std::size_t r = 1; r < runs.size(); ++r)
            if (!follow_main_run(r)) return s + 1;
        apply_due_events();
        // The main run speaks last, so its message is the one on screen.
        if (sound && !why.empty()) say(why, Tone::info);  // dt grew back
        if (!sound) {
            hand.pulling = false;
            main_run().cloth_view = view::ClothView(simulation().cloth());
            say(why, Tone::problem);
            if (main_run().recovery.hopeless()) pause_hopeless(main_run().recovery, "the scene");
            return s;
        }
    }
    return steps;
}

bool DemoState::follow_main_run(std::size_t run) {
    DemoRun& copy = runs[run];
    const std::string name = "copy " + std::to_string(run);
    const auto started = std::chrono::steady_clock::now();
    std::string why;
    // Each copy follows to the same simulated time with its own dt, at most one step more
    // than keeps pace: a copy that rolled back or restarted catches up over the following
    // steps instead of stalling this one.
    int budget = static_cast<int>(std::ceil(simulation().dt() / copy.simulation.dt())) + 1;
    bool window_runs = true;
    while (budget-- > 0 &&
           copy.simulation.time() + 0.5 * copy.simulation.dt() <= simulation().time()) {
        const bool sound = copy.recovery.step(copy.simulation, copy.restart_dt, why);
        if (!why.empty()) {
            say(name + ": " + why, sound ? Tone::info : Tone::problem);
            why.clear();
        }
        if (!sound) {
            copy.cloth_view = view::ClothView(copy.simulation.cloth());
            if (copy.recovery.hopeless()) {
                pause_hopeless(copy.recovery, name);
                window_runs = false;
            }
            break;
        }
    }
    copy.seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return window_runs;
}

namespace {

// --set style "KEY=VALUE" overrides as typed edits; the first that does not read is refused
// as "error: --set KEY: ...".
std::optional<std::string> read_overrides(const std::vector<std::string>& overrides,
                                          std::vector<SceneEdit>& edits) {
    for (const std::string& text : overrides) {
        SceneError error;
        std::optional<SceneEdit> edit = scene_edit_from_override(text, error);
        if (!edit) return error.message();
        edits.push_back(std::move(*edit));
    }
    return std::nullopt;
}

// Where a refusal of a batch of --set style overrides says it came from, as the loader
// words a --set one: "--set KEY", naming every key of the batch (the rules that join keys
// blame the batch).
std::string override_keys(const std::vector<std::string>& overrides) {
    std::string keys;
    for (const std::string& text : overrides)
        keys += (keys.empty() ? "" : ", ") + text.substr(0, text.find('='));
    return "--set " + keys;
}

}  // namespace

// ---- runs side by side --------------------------------------------------------------------------

const Simulation& DemoState::run(int index) const {
    return index <= 0 || index >= run_count() ? simulation()
                                              : runs[static_cast<std::size_t>(index)].simulation;
}

void DemoState::add_copy(Integrator integrator, double dt) {
    runs.push_back(new_run(simulation(), dt));
    runs.back().simulation.set_integrator(integrator);
    runs.back().simulation.set_dt(dt);
}

void DemoState::remove_copy(std::size_t index) {
    if (index + 1 < runs.size()) runs.erase(runs.begin() + static_cast<long>(index + 1));
}

std::optional<std::string> DemoState::edit_copy(std::size_t index,
                                                const std::vector<SceneEdit>& edits) {
    if (index + 1 >= runs.size()) return "no copy " + std::to_string(index + 1);
    for (const SceneEdit& edit : edits)
        if (!is_solver_key(edit.key))
            return "a copy differs from the main run only in its integrator and dt";
    DemoRun& copy = runs[index + 1];
    Simulation& companion = copy.simulation;
    Scene checked = companion.scene();
    if (auto problem = apply_scene_edits(checked, edits)) return "error: " + *problem;
    if (auto problem = window_dt_problem(checked.solver.dt)) return "error: " + *problem;
    // dt differs from the running one only where the user set it, and only then is it the
    // copy's new chosen dt (not whatever recovery had halved it to).
    if (checked.solver.dt != companion.dt()) copy.restart_dt = checked.solver.dt;
    companion.set_parameters(checked);
    return std::nullopt;
}

std::optional<std::string> DemoState::change_copy(std::size_t index,
                                                  const std::vector<std::string>& texts) {
    std::vector<SceneEdit> edits;
    if (auto error = read_overrides(texts, edits)) return error;
    return edit_copy(index, edits);
}

// ---- the hand -----------------------------------------------------------------------------------

void DemoState::perform(const ClothEvent& event) {
    if (replaying) return;  // the replay drives the cloth; the hand waits
    if (recording) recording->events.push_back({steps_run, event});
    apply_to_all_runs(event);
}

void DemoState::apply_to_all_runs(const ClothEvent& event) {
    using Kind = ClothEvent::Kind;
    const double dt_before = simulation().dt();
    bool rebuilt = false;
    for (std::size_t r = 0; r < runs.size(); ++r) {
        const SolverSpec own = runs[r].simulation.scene().solver;  // a copy keeps its solver
        rebuilt |=
            apply_event(runs[r].simulation, event, r > 0 ? &own : nullptr) == EventResult::rebuilt;
    }
    // The panel writes the running parameters with its edits, so dt differs from the running
    // one only where the user set it: that is the new chosen dt. Here, not in change(), so a
    // replay of the event chooses the same dt.
    const bool parameters = event.kind == Kind::edit || event.kind == Kind::parameters;
    if (parameters && simulation().dt() != dt_before) {
        main_run().restart_dt = simulation().dt();
        main_run().recovery.restart_growth();
    }
    if (event.kind == Kind::reset) {
        // R starts over at the chosen dt: whatever recovery halved it to was for the motion
        // that diverged, which is gone.
        // set_dt only where dt differs: it drops the history a multistep method carries.
        for (DemoRun& run : runs) {
            if (run.simulation.dt() != run.restart_dt) run.simulation.set_dt(run.restart_dt);
            run.recovery.recoveries = 0;
        }
    }
    if (rebuilt || event.kind == Kind::reset) {
        after_new_state();
    } else if (event.kind == Kind::cut || event.kind == Kind::pin || event.kind == Kind::unpin ||
               event.kind == Kind::release_pins) {
        // A rollback must not undo the user's cuts and pins: the state just after them is the
        // most recent sound one.
        auto remember = [](Recovery& r, const Simulation& s) {
            r.last_good = s;
            r.last_good_time = s.time();
        };
        for (DemoRun& run : runs) remember(run.recovery, run.simulation);
    } else if (parameters) {
        // New parameters get as many restarts as the first ones did.
        for (DemoRun& run : runs) run.recovery.restarts_in_a_row = 0;
        ground_height = view::ground_height_below(simulation().cloth(), simulation().colliders());
    }
    if (event.kind == ClothEvent::Kind::let_go) hand.pulling = false;
}

bool DemoState::grab(const glm::vec2& cursor, ViewSize view, int run_index) {
    if (replaying) return false;
    auto hit =
        cloth_under_cursor(run(run_index).cloth(), rig.camera(), view.width, view.height, cursor);
    if (!hit) return false;  // only grabs when the cursor is on the cloth
    ClothEvent event;
    event.kind = ClothEvent::Kind::grab;
    event.hit = *hit;
    event.radius = grab_radius;
    perform(event);
    hand_hint = false;
    hand.pulling = simulation().grab().active();
    hand.anchor = hit->point;
    return hand.pulling;
}

void DemoState::pull(const glm::vec2& cursor, ViewSize view) {
    if (!hand.pulling || !simulation().grab().active()) return;
    auto target = point_on_grab_plane(rig.camera(), view.width, view.height, cursor, hand.anchor);
    if (!target || *target == simulation().grab().target) return;  // nothing new to record
    ClothEvent event;
    event.kind = ClothEvent::Kind::pull;
    event.target = *target;
    perform(event);
}

void DemoState::let_go() {
    if (hand.pulling) perform(plain_event(ClothEvent::Kind::let_go));
    hand.pulling = false;
}

void DemoState::start_cut(const glm::vec2& cursor, ViewSize view, int run_index) {
    hand.cutting = true;
    hand_hint = false;
    hand.last_cursor = cursor;
    hand.last_on_screen =
        particles_on_screen(run(run_index).cloth(), rig.camera(), view.width, view.height);
}

std::size_t DemoState::cut_to(const glm::vec2& cursor, ViewSize view, int run_index) {
    if (!hand.cutting || replaying) return 0;
    ClothEvent event;
    event.kind = ClothEvent::Kind::cut;
    const Cloth& cloth = run(run_index).cloth();
    ScreenPoints on_screen = particles_on_screen(cloth, rig.camera(), view.width, view.height);
    // A reset or another scene since the last motion: nothing to compare with.
    if (hand.last_on_screen.size() != on_screen.size()) hand.last_on_screen = on_screen;
    event.springs =
        springs_along_stroke(cloth, hand.last_on_screen, on_screen, hand.last_cursor, cursor);
    hand.last_cursor = cursor;
    hand.last_on_screen = std::move(on_screen);
    if (event.springs.empty()) return 0;
    const std::size_t before = simulation().cloth().spring_count();
    perform(event);
    return before - simulation().cloth().spring_count();
}

void DemoState::end_cut() {
    hand.cutting = false;
    hand.last_on_screen.clear();
}

bool DemoState::toggle_pin(const glm::vec2& cursor, ViewSize view, int run_index) {
    if (replaying) return false;
    const Simulation& target = run(run_index);
    auto hit = cloth_under_cursor(target.cloth(), rig.camera(), view.width, view.height, cursor);
    if (!hit) return false;
    ClothEvent event;
    event.kind =
        target.cloth().is_pinned(hit->particle) ? ClothEvent::Kind::unpin : ClothEvent::Kind::pin;
    event.particle = hit->particle;
    perform(event);
    hand_hint = false;
    return true;
}

void DemoState::release_all_pins() {
    perform(plain_event(ClothEvent::Kind::release_pins));
}

// ---- parameter changes ------------------------------------------------------------------------

std::optional<std::string> DemoState::edit(const std::vector<SceneEdit>& edits) {
    return edit(edits, "");
}

std::optional<std::string> window_dt_problem(double dt) {
    if (dt <= StepClock::max_dt) return std::nullopt;
    return "solver.dt: at most " + significant_text(StepClock::max_dt * 1e3, 3) +
           " ms in the window, which steps in real time (ten steps a second at least); got " +
           significant_text(dt * 1e3, 3) + " ms";
}

std::optional<std::string> DemoState::edit(const std::vector<SceneEdit>& edits,
                                           const std::string& where) {
    if (replaying) return std::string("a session is replaying: stop it to change parameters");
    Scene checked = simulation().scene();
    if (auto problem = apply_scene_edits(checked, edits))
        return "error: " + (where.empty() ? "" : where + ": ") + *problem;
    if (auto problem = window_dt_problem(checked.solver.dt))
        return "error: " + (where.empty() ? "" : where + ": ") + *problem;
    if (edits.empty()) return std::nullopt;
    ClothEvent event;
    event.kind = ClothEvent::Kind::edit;
    event.edits = edits;
    perform(event);
    return std::nullopt;
}

std::optional<std::string> DemoState::change(const std::vector<std::string>& texts) {
    std::vector<SceneEdit> edits;
    if (auto error = read_overrides(texts, edits)) return error;
    return edit(edits, override_keys(texts));
}

std::optional<std::string> DemoState::change_scene(const Scene& wanted) {
    std::optional<std::vector<SceneEdit>> edits = scene_edits_between(simulation().scene(), wanted);
    if (!edits) return std::string("error: only loading another scene changes that");
    return edit(*edits);
}

std::optional<std::string> DemoState::change_field_of_view(double degrees) {
    Scene checked = scene_to_save();
    const SceneEdit fov{SceneKey::camera_fov_degrees, degrees};
    if (auto problem = apply_scene_edits(checked, {&fov, 1})) return "error: " + *problem;
    rig.fov_degrees = static_cast<float>(checked.camera.fov_degrees);
    return std::nullopt;
}

void DemoState::move_collider(std::size_t index, const Vec3d& offset) {
    Scene wanted = simulation().scene();
    if (index >= wanted.colliders.size()) return;
    ColliderSpec& collider = wanted.colliders[index];
    for (int k = 0; k < 3; ++k) {
        collider.center[k] += offset[k];
        collider.point[k] += offset[k];
    }
    change_scene(wanted);  // refused (so nothing moves) only if a coordinate overflowed
}

// ---- scenes -----------------------------------------------------------------------------------

void DemoState::reset_simulation() {
    if (replaying) return;
    perform(plain_event(ClothEvent::Kind::reset));
    if (!recording) steps_run = 0;
}

bool DemoState::load_scene(const std::string& path, std::string& error) {
    SceneLoadResult loaded = load_scene_file(path, overrides);
    for (const std::string& warning : loaded.warnings)
        std::fprintf(stderr, "warning: %s\n", warning.c_str());
    if (!loaded.ok()) {
        error = loaded.error->message();
        return false;  // the running simulation is untouched
    }
    if (auto problem = window_dt_problem(loaded.scene->solver.dt)) {
        error = path + ": " + *problem;
        return false;
    }
    scene_path = path;
    scene = *loaded.scene;
    recording.reset();
    replaying.reset();
    replace_simulation(scene);
    main_run().restart_dt = scene.solver.dt;
    steps_run = 0;
    rig = initial_rig = scene_rig(scene);
    return true;
}

// ---- recording and replay ---------------------------------------------------------------------

void DemoState::start_recording() {
    replaying.reset();
    apply_to_all_runs(plain_event(ClothEvent::Kind::reset));  // at the chosen dt
    steps_run = 0;
    recording = SessionRecord{};
    recording->scene_toml = scene_to_toml(simulation().scene());
}

SessionRecord DemoState::stop_recording() {
    SessionRecord record = recording.value_or(SessionRecord{});
    record.steps = steps_run;
    record.final_state_hash = hash_state(simulation().cloth());
    recording.reset();
    return record;
}

void DemoState::start_replay(const SessionRecord& record) {
    SceneLoadResult loaded = load_scene_text(record.scene_toml, "recorded scene");
    if (!loaded.ok()) {
        say("cannot replay: " + loaded.error->message(), Tone::problem);
        return;
    }
    recording.reset();
    scene = *loaded.scene;
    replace_simulation(scene);
    main_run().restart_dt = scene.solver.dt;
    steps_run = 0;
    replaying = record;
    replay_next = 0;
}

void DemoState::stop_replay() {
    replaying.reset();
    replay_next = 0;
}

bool DemoState::replay_matches() const {
    return replay_finished() && replay_next == replaying->events.size() &&
           hash_state(simulation().cloth()) == replaying->final_state_hash;
}

Scene DemoState::scene_to_save() const {
    Scene saved = simulation().scene();
    saved.camera.position = to_vec3d(rig.position);
    saved.camera.target = to_vec3d(rig.target());
    saved.camera.fov_degrees = static_cast<double>(rig.fov_degrees);
    return saved;
}

bool DemoState::save_scene(const std::string& path, bool overwrite, std::string& error) const {
    Scene saved = scene_to_save();
    if (!saved.cloth.mesh.empty()) {
        // The mesh as the loader reads it, relative to the scene file's folder: the saved
        // scene and its mesh can then move together, as the shipped ones do.
        namespace fs = std::filesystem;
        std::error_code failed;
        const fs::path folder = fs::absolute(fs::path(path), failed).parent_path();
        const fs::path relative = fs::path(saved.cloth.mesh).lexically_relative(folder);
        if (!failed && !relative.empty()) saved.cloth.mesh = relative.generic_string();
    }
    return write_file_atomically(path, scene_to_toml(saved), overwrite, error);
}

}  // namespace weft::app
