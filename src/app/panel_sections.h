// The parameter panel's sections that live in files of their own, each named after what it
// holds (panel_*_section.cpp); control_panel.cpp lays them out with the rest. Each draws
// into the current ImGui window and edits through panel_widgets.h.
#pragma once

#include "app/demo_state.h"

namespace weft::app {

// Frame rate, costs, counts, and the plots of energy, largest stretch and work per frame.
void statistics_section(DemoState& state);
// Gravity as a vector, air drag, and the wind: strength, heading and vertical part.
void forces_section(DemoState& state);
// Each collider: where it is, its size, its response, restitution and friction.
void colliders_section(DemoState& state);
// The grid (rows, cols, spacing, layout, orientation, pins), held as a draft and rebuilt on
// Apply.
void grid_section(DemoState& state);

}  // namespace weft::app
