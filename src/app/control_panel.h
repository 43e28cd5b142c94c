// The parameter panel (Dear ImGui): every scene parameter live, the scene picker, view
// toggles and the statistics; and the help overlay. Draws into the current ImGui frame.
#pragma once

#include "app/demo_state.h"

namespace weft::app {

void draw_control_panel(DemoState& state);
void draw_help_overlay(bool& open);
void draw_status_overlay(const DemoState& state, double now_seconds);

// Every key and mouse action, for the help overlay and the README.
extern const char* const controls_text[][2];
extern const int controls_count;

}  // namespace weft::app
