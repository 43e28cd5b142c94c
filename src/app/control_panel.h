// The parameter panel (Dear ImGui): every scene parameter live, the scene picker, view
// toggles and the statistics; and the help overlay. Draws into the current ImGui frame.
// (The status lines over the view are status_overlay.h's.)
#pragma once

#include "app/demo_state.h"
#include "app/screen_layout.h"

namespace weft::app {

// Draws the panel into `area` (WindowLayout::panel). Returns false when the panel is folded
// to its title bar, so the view can take the window.
bool draw_control_panel(DemoState& state, const ScreenRect& area);
void draw_help_overlay(bool& open);

// Every key and mouse action, for the help overlay and the README.
extern const char* const controls_text[][2];
extern const int controls_count;

}  // namespace weft::app
