// DemoState: everything the interactive demo keeps between frames, apart from SDL itself,
// and every operation the window performs on it: stepping with recovery from divergence,
// the hand on the cloth (drag, cut, pin), checked parameter changes, runs side by side,
// recording and replaying a session, loading and saving scenes. SDL-free, so the same code
// the window runs is tested headless (demo_state_test, session_test). The window turns
// events into these calls; the panel (control_panel.cpp) edits through change().
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "app/camera_rig.h"
#include "app/cloth_event.h"
#include "app/frame_capture.h"
#include "app/frame_plots.h"
#include "app/hand_tools.h"
#include "app/session_record.h"
#include "app/step_clock.h"
#include "sim/core/recovery.h"
#include "sim/core/simulation.h"
#include "sim/scene_io/scene_loader.h"
#include "view/cloth_view.h"
#include "view/frame_renderer.h"

namespace weft::app {

struct DemoStatistics {
    double frame_seconds = 0.0;   // wall time of the last frame
    double sim_seconds = 0.0;     // stepping in the last frame
    double raster_seconds = 0.0;  // drawing in the last frame
    int steps = 0;                // steps in the last frame
    bool behind = false;          // the step budget cut the last frame short
    // largest spring length / rest length at the last frame's end (NaN without springs)
    double stretch_ratio = 0.0;
    std::string stretch_place;  // where that spring is (stretch_place_text)
    FramePlots plots;  // energy, largest stretch and work per frame, over frames that stepped
    // The main run's step profile (Recovery::profile) over about the last second of wall
    // time, for the panel: renewed once a second from a copy taken the second before.
    StepProfile recent_profile;
    StepProfile profile_mark;
    double profile_mark_wall = 0.0;  // s, wall_now when profile_mark was taken
};

// How a message on screen reads at a glance, by its colour: news that something worked must
// not look like an error.
enum class Tone { info, success, problem };

// What the mouse and the space bar are doing to the cloth.
struct Hand {
    bool pulling = false;
    Vec3 anchor{0.0};  // m, the grabbed point: the grab plane goes through it
    bool cutting = false;
    glm::vec2 last_cursor{0.0f};  // px, where the cut stroke was at the last motion
    // The particles in the window at the last motion, for a stroke's run: a cut judges how
    // cursor and cloth moved since then, not only where the cloth is now.
    ScreenPoints last_on_screen;
};

// The view the cursor is in: pixels, origin top left.
struct ViewSize {
    int width = 1;
    int height = 1;
};

// A run the window shows: the main one, or a copy beside it with the same cloth and hand and
// its own integrator and dt.
struct DemoRun {
    Simulation simulation;
    view::ClothView cloth_view;
    Recovery recovery;
    // s, its dt as chosen (the scene's, or the last one set in the panel): what recovery grows
    // dt back to, R restores, and a hopeless run restarts with
    double restart_dt = 0.0;
    double seconds = 0.0;  // stepping in the last frame, s
};

// Why `dt` (s) cannot be the window's step, or nothing: the window steps in real time and
// takes steps of at most StepClock::max_dt.
std::optional<std::string> window_dt_problem(double dt);

struct DemoState {
    std::string scene_path;
    std::vector<std::string> overrides;
    Scene scene;  // as loaded (or as the replayed session started)
    // The runs side by side: the main run first, then its copies. Never empty.
    std::vector<DemoRun> runs;
    DemoRun& main_run() { return runs.front(); }
    const DemoRun& main_run() const { return runs.front(); }
    Simulation& simulation() { return main_run().simulation; }
    const Simulation& simulation() const { return main_run().simulation; }
    view::FrameOptions frame_options;
    float ground_height = 0.0f;
    CameraRig rig;
    CameraRig initial_rig;
    StepClock clock;
    Hand hand;
    bool paused = false;
    bool single_step = false;  // paused, one step is owed to the next frame
    bool show_help = false;
    // The one-line hint on the view (how to pull, cut, pin), shown until the hand is first
    // used: a grab, a cut or a pin.
    bool hand_hint = true;
    double grab_radius = 0.08;  // m

    // Steps run since the scene (re)started, diverged ones included: the clock events are
    // recorded and replayed by.
    std::uint64_t steps_run = 0;
    std::optional<SessionRecord> recording;     // while recording
    std::optional<FrameCapture> frame_capture;  // while capturing frames (F9)
    std::string captures;  // the folder screenshots, OBJ files, sessions and frames go to
    std::optional<SessionRecord> replaying;  // while replaying; events are consumed in order
    std::size_t replay_next = 0;             // the next event of `replaying` to apply

    std::string message;  // shown on screen for a few seconds
    Tone message_tone = Tone::info;
    double message_until = 0.0;  // wall clock s
    double wall_now = 0.0;       // wall clock s, set by the window every frame
    DemoStatistics statistics;

    DemoState(const std::string& path, const std::vector<std::string>& scene_overrides,
              const Scene& loaded);

    // Takes `steps` steps of the main run, each companion following to the same simulated
    // time, applying the replayed events that fall due. Stops early when the main run
    // diverges and recovers (see Recovery); says when a run's dt grows back. Returns the
    // steps the main run took.
    int step(int steps);

    // The runs side by side: 0 is the main run, 1.. the copies; an index out of range is the
    // main run.
    int run_count() const { return static_cast<int>(runs.size()); }
    const Simulation& run(int index) const;
    // A copy starting from the main run's current state with another integrator and dt.
    void add_copy(Integrator integrator, double dt);
    // Copy `index` (0: the first copy, run 1) goes.
    void remove_copy(std::size_t index);
    // Edits copy `index`'s own solver (solver.integrator, solver.dt), checked; the copy is not
    // recorded (a replay has no copies unless asked for).
    std::optional<std::string> edit_copy(std::size_t index, const std::vector<SceneEdit>& edits);
    // The same from --set style overrides ("solver.integrator=rk4", "solver.dt=0.0005").
    std::optional<std::string> change_copy(std::size_t index,
                                           const std::vector<std::string>& texts);

    // The hand, at a cursor in a view of the given size showing run `run_index`. grab()
    // takes hold only where the cursor is on that run's cloth; the event then goes to every
    // run. Ignored while a session replays.
    bool grab(const glm::vec2& cursor, ViewSize view, int run_index = 0);
    void pull(const glm::vec2& cursor, ViewSize view);
    void let_go();
    void start_cut(const glm::vec2& cursor, ViewSize view, int run_index = 0);
    std::size_t cut_to(const glm::vec2& cursor, ViewSize view, int run_index = 0);
    void end_cut();
    bool toggle_pin(const glm::vec2& cursor, ViewSize view, int run_index = 0);
    void release_all_pins();

    // Changes parameters by typed edits (scene_edit.h), checked by the scene rules a file is
    // checked by. Returns the error and changes nothing if any is refused; otherwise applies
    // them to every run, live, or rebuilding the cloth if they change it, and records them.
    std::optional<std::string> edit(const std::vector<SceneEdit>& edits);
    // The same from --set style "KEY=VALUE" overrides; refusals read "error: --set KEY: ...".
    std::optional<std::string> change(const std::vector<std::string>& texts);
    // The same for a changed copy of the running scene: the edits that make it.
    std::optional<std::string> change_scene(const Scene& wanted);
    // The camera's vertical field of view (degrees), checked like camera.fov_degrees in a
    // scene file; the camera is the view's, not the simulation's, so nothing is recorded.
    std::optional<std::string> change_field_of_view(double degrees);
    // Moves collider `index` by `offset` (m), as the keyboard does with a sphere.
    void move_collider(std::size_t index, const Vec3d& offset);

    // Back to the scene's start, keeping the parameters changed in the panel, at the chosen
    // dt (restart_dt, for the main run and each copy) with the recovery counters cleared.
    void reset_simulation();
    // Replaces the scene (the panel's picker); the running one stays if the new one fails.
    bool load_scene(const std::string& path, std::string& error);
    // The current parameters, with the current camera, as a scene file. Writes a temporary
    // file beside `path`, flushes it to disk and renames it over `path`, so a crash never
    // leaves a half-written scene; refuses to replace an existing file unless `overwrite`.
    bool save_scene(const std::string& path, bool overwrite, std::string& error) const;
    // The scene save_scene writes.
    Scene scene_to_save() const;

    // Recording restarts the scene (with the current parameters), so the recording starts
    // from a state a replay can rebuild; stop_recording() returns the session.
    void start_recording();
    SessionRecord stop_recording();
    // Replays a session from its start: the scene it recorded, then its events at their
    // steps. replay_finished() once every step has run; replay_matches() then tells whether
    // the state is bit for bit the one recorded.
    void start_replay(const SessionRecord& record);
    bool replay_finished() const { return replaying && steps_run >= replaying->steps; }
    bool replay_matches() const;
    void stop_replay();  // back to the hand, from wherever the replay got to

    void say(const std::string& text, Tone tone);  // a message on screen (and on stderr)

    // Pausing, for the P and N keys and the panel's buttons alike. step_once() owes the
    // next frame one step if paused; running, it does nothing.
    void toggle_pause();
    void step_once();
    // The steps this frame takes: the clock's plan for `elapsed` wall seconds, or while
    // paused none, or the one step_once() owed (the clock then owes nothing, so resuming
    // does not rush to catch up). `other_seconds`: what the last frame spent besides
    // stepping (StepClock::advance).
    StepClock::Plan plan_frame(double elapsed, double seconds_per_step, double other_seconds = 0.0);

    // Once a frame, after it is stepped and drawn (statistics.sim_seconds and
    // raster_seconds set): measures the main run's largest stretch and, for a frame that
    // took steps, adds a sample to each plot; a frame that took none adds none, so the plots
    // hold still while paused instead of scrolling a flat line through time that did not
    // pass.
    void measure_frame(int steps);

  private:
    // Pauses the run whose `hopeless` recovery restarted restarts_before_pause times in a
    // row, saying so (of `run`: "the scene", "copy 2") and what to change.
    void pause_hopeless(Recovery& hopeless, const std::string& run);
    // Steps copy `run` (1..) on to the main run's time; false if it paused the window.
    bool follow_main_run(std::size_t run);
    // edit(), its refusal said as coming from `where` ("--set KEY"; "" names nothing).
    std::optional<std::string> edit(const std::vector<SceneEdit>& edits, const std::string& where);
    void perform(const ClothEvent& event);  // record it, then apply it to every run
    void apply_to_all_runs(const ClothEvent& event);
    void replace_simulation(const Scene& new_scene);  // a new cloth for every run
    void after_new_state();  // views, ground, recovery, hand for a new or reset cloth
};

}  // namespace weft::app
