// The parameter panel (Dear ImGui): every scene parameter live, the scene picker, view
// toggles and the statistics; and the help overlay. Draws into the current ImGui frame.
// (The status lines over the view are status_overlay.h's.)
#pragma once

#include "app/demo_state.h"

namespace weft::app {

void draw_control_panel(DemoState& state);
void draw_help_overlay(bool& open);

// Every key and mouse action, for the help overlay and the README.
extern const char* const controls_text[][2];
extern const int controls_count;

}  // namespace weft::app
