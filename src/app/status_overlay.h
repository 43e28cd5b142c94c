// The lines over the 3D view that say how the run is going: recording, paused, falling
// behind real time, and the last message (a save, a divergence and its recovery), each in a
// colour that says whether it is news, success or a problem. Draws into the current ImGui
// frame, inside the part of the window the panel leaves free.
#pragma once

#include "app/demo_state.h"
#include "app/screen_layout.h"

namespace weft::app {

void draw_status_overlay(const DemoState& state, double now_seconds, const ScreenRect& area);

// The one-line hint at the top of the view, "space or left-drag: pull, right-drag: cut,
// T: pin, H: help", until the hand is first used (DemoState::hand_hint).
void draw_hand_hint(const DemoState& state, const ScreenRect& area);

}  // namespace weft::app
