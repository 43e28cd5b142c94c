// How the window is shared: the parameter panel docked along its left edge, the 3D view in
// the rest. SDL- and ImGui-free, so the rule is tested.
#pragma once

namespace weft::app {

// A rectangle on screen in pixels, origin top left.
struct ScreenRect {
    float x = 0.0f, y = 0.0f;
    float width = 0.0f, height = 0.0f;
    float right() const { return x + width; }
};

// The window's two parts. The view is the camera's viewport, where side by side's columns,
// their labels and the status lines go: nothing of the cloth is ever drawn under the panel.
struct WindowLayout {
    ScreenRect panel;  // the parameter panel, from the top of the window to its bottom
    ScreenRect view;   // the 3D view: the rest of the window
};

// The layout of a window `width` x `height` px. Open, the panel is the window's full height
// and 30 % of its width, at least 300 px (a label column wide enough for the longest label,
// "field of view (deg)", beside sliders wide enough for their numbers) and at most 400 (more
// is empty space), but never more than half the window: the cloth keeps at least half.
// Folded, the panel is its title bar, a strip `title_height` px tall at the top of its
// column, and the view is the whole window below that strip. Widths are whole pixels, so
// the view's framebuffer lands on the window's pixels one to one.
WindowLayout lay_out_window(float width, float height, bool panel_folded, float title_height);

}  // namespace weft::app
