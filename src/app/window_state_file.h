// The window's state as a small text file, rewritten after every frame when the environment
// names one (WEFT_WINDOW_STATE=FILE): what a script driving the window waits on instead of
// sleeping, such as the end-to-end test waiting for frames to be drawn or simulated time to
// pass.
#pragma once

#include <string>

#include "app/demo_state.h"

namespace weft::app {

// "frames N", "steps N", "time T" (the main run's simulated s, every digit), "paused 0|1",
// "held 0|1" (the hand holds the cloth), one per line.
std::string window_state_text(long long frames_drawn, const DemoState& state);

// Writes the text to PATH.tmp and renames it over PATH, so a reader sees a whole file, old or
// new. No flush to disk: the file is for a process on the same machine, every frame. Returns
// false if it could not.
bool write_window_state(const std::string& path, long long frames_drawn, const DemoState& state);

}  // namespace weft::app
