// Where the window's overlays may draw: the part of the window the panel leaves free.
// SDL- and ImGui-free, so the rule is tested.
#pragma once

namespace weft::app {

// A rectangle on screen in pixels, origin top left.
struct ScreenRect {
    float x = 0.0f, y = 0.0f;
    float width = 0.0f, height = 0.0f;
    float right() const { return x + width; }
};

// The full-height strip of `window` beside `panel` (left or right of it, whichever is wider),
// for text that must stay readable and off the panel. The whole window when that strip would
// be narrower than `narrowest` pixels: covering the panel is better than text too cramped to
// read.
ScreenRect area_beside_panel(const ScreenRect& window, const ScreenRect& panel, float narrowest);

}  // namespace weft::app
