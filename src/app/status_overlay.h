// The lines over the 3D view that say how the run is going: recording, paused, falling
// behind real time, and the last message (a save, a divergence and its recovery), each in a
// colour that says whether it is news, success or a problem. Draws into the current ImGui
// frame, inside the part of the window the panel leaves free.
#pragma once

#include "app/demo_state.h"
#include "app/screen_layout.h"

namespace weft::app {

void draw_status_overlay(const DemoState& state, double now_seconds, const ScreenRect& area);

}  // namespace weft::app
