// DemoState: everything the interactive demo keeps between frames, apart from SDL itself.
// The window (demo_window.cpp) feeds it input; the panel (control_panel.cpp) edits it.
#pragma once

#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "app/camera_rig.h"
#include "app/step_clock.h"
#include "raster/framebuffer.h"
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

struct DemoState {
    std::string scene_path;
    std::vector<std::string> overrides;
    Scene scene;  // as loaded: what R restores (with the panel's parameters)
    Simulation simulation;
    view::ClothView cloth_view;
    view::FrameOptions frame_options;
    float ground_height = 0.0f;
    CameraRig rig;
    CameraRig initial_rig;
    StepClock clock;
    bool paused = false;
    bool single_step = false;
    bool show_help = false;
    double drag_radius = 0.08;  // m

    // Recovery from divergence: a recent sound state to roll back to, and what happened.
    std::optional<Simulation> last_good;
    double last_good_time = -1.0;
    int recoveries = 0;
    std::string message;         // shown on screen for a few seconds
    double message_until = 0.0;  // wall clock seconds
    DemoStatistics statistics;

    DemoState(const std::string& path, const std::vector<std::string>& scene_overrides,
              const Scene& loaded);

    // Back to the scene's start, keeping the parameters changed in the panel.
    void reset_simulation();
    // Replaces the scene (the panel's picker); the old one stays if the new one fails to load.
    bool load_scene(const std::string& path, std::string& error);
};

}  // namespace weft::app
