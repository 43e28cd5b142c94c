// DemoState: everything the interactive demo keeps between frames, apart from SDL itself,
// and every operation the window performs on it: stepping with recovery from divergence,
// the hand on the cloth (drag, cut, pin), checked parameter changes, loading and saving
// scenes. SDL-free, so the same code the window runs is tested headless (demo_state_test).
// The window (demo_window.cpp) turns events into these calls; the panel (control_panel.cpp)
// edits through change().
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "app/camera_rig.h"
#include "app/step_clock.h"
#include "sim/scene_loader.h"
#include "sim/simulation.h"
#include "view/cloth_view.h"
#include "view/frame_renderer.h"

namespace weft::app {

struct DemoStatistics {
    double frame_seconds = 0.0;   // wall time of the last frame
    double sim_seconds = 0.0;     // stepping in the last frame
    double raster_seconds = 0.0;  // drawing in the last frame
    int steps = 0;                // steps in the last frame
    bool behind = false;          // the step budget cut the last frame short
    std::vector<float> energy;    // J, total energy, one entry per frame, the last few seconds
};

// What the mouse and the space bar are doing to the cloth.
struct Hand {
    bool dragging = false;
    Vec3 anchor{0.0};  // m, the grabbed point: the drag plane goes through it
    bool cutting = false;
    glm::vec2 last_cursor{0.0f};  // px, where the cut stroke was at the last motion
};

// The view the cursor is in: window pixels, origin top left.
struct ViewSize {
    int width = 1;
    int height = 1;
};

// Recovery halves dt down to this; below it the scene restarts instead (a step this small
// would stall the demo without making a hopeless parameter set stable).
inline constexpr double smallest_recovery_dt = 1e-6;  // s

struct DemoState {
    std::string scene_path;
    std::vector<std::string> overrides;
    Scene scene;  // as loaded
    Simulation simulation;
    view::ClothView cloth_view;
    view::FrameOptions frame_options;
    float ground_height = 0.0f;
    CameraRig rig;
    CameraRig initial_rig;
    StepClock clock;
    Hand hand;
    bool paused = false;
    bool single_step = false;
    bool show_help = false;
    double drag_radius = 0.08;  // m

    // Recovery from divergence: a recent sound state to roll back to, and what happened.
    std::optional<Simulation> last_good;
    double last_good_time = -1.0;
    int recoveries = 0;
    std::string message;         // shown on screen for a few seconds
    double message_until = 0.0;  // wall clock s
    double wall_now = 0.0;       // wall clock s, set by the window every frame
    DemoStatistics statistics;

    DemoState(const std::string& path, const std::vector<std::string>& scene_overrides,
              const Scene& loaded);

    // Takes `steps` steps. On divergence: rolls back to the last sound state (keeping the
    // parameters as they are now), halves dt, says so and stops for this frame; below
    // smallest_recovery_dt it restarts the scene instead. Returns the steps taken.
    int step(int steps);

    // The hand, at a cursor in a view of the given size. grab() takes hold only where the
    // cursor is on the cloth; pull() moves the held point on the plane it was grabbed in.
    bool grab(const glm::vec2& cursor, ViewSize view);
    void pull(const glm::vec2& cursor, ViewSize view);
    void let_go();
    void start_cut(const glm::vec2& cursor);
    std::size_t cut_to(const glm::vec2& cursor, ViewSize view);  // springs cut
    void end_cut();
    bool toggle_pin(const glm::vec2& cursor, ViewSize view);  // false: nothing under it

    // Changes parameters by "KEY=VALUE" overrides of the scene format (as --set takes them),
    // checked exactly like a scene file. Returns the error and changes nothing if any is
    // refused; otherwise applies them live, or rebuilds the cloth if they change its grid.
    std::optional<std::string> change(const std::vector<std::string>& overrides);
    // The same for a whole scene (edits --set cannot name, such as a collider's fields): it
    // is written out and read back through the loader's checks before anything changes.
    std::optional<std::string> change_scene(const Scene& wanted);
    // Moves collider `index` by `offset` (m), as the keyboard does with a sphere.
    void move_collider(std::size_t index, const Vec3d& offset);

    // Back to the scene's start, keeping the parameters changed in the panel.
    void reset_simulation();
    // Replaces the scene (the panel's picker); the running one stays if the new one fails.
    bool load_scene(const std::string& path, std::string& error);
    // The current parameters, with the current camera, as a scene file. Writes a temporary
    // file beside `path`, flushes it to disk and renames it over `path`, so a crash never
    // leaves a half-written scene; refuses to replace an existing file unless `overwrite`.
    bool save_scene(const std::string& path, bool overwrite, std::string& error) const;
    // The scene save_scene writes.
    Scene scene_to_save() const;

    void say(const std::string& text);  // a message on screen (and on stderr)

  private:
    std::optional<std::string> apply(const SceneLoadResult& checked);
    void after_new_simulation();  // view, ground, recovery state for a new cloth
};

}  // namespace weft::app
