// Runs side by side: the view split into one column per run (the main run first, then its
// copies), each drawn through the same camera, and the cursor acting on the run of the
// column it is in. SDL-free, so the split and the drawing are tested without a window.
#pragma once

#include <span>
#include <vector>

#include <glm/vec2.hpp>

#include "app/demo_state.h"
#include "app/screen_layout.h"
#include "raster/framebuffer.h"

namespace weft::app {

// The view's columns, in the window: they share the view beside the panel, not the window,
// so no run is drawn under the panel.
struct Columns {
    int count = 1;      // runs shown
    int width = 1;      // px, of each column; an uneven split leaves the last pixels background
    int height = 1;     // px
    float left = 0.0f;  // px, the view's left edge in the window: where the first column starts
    float top = 0.0f;   // px, the view's top edge in the window

    // `view` in whole pixels (WindowLayout::view), split into `runs` columns.
    static Columns split(const ScreenRect& view, int runs);
    int column_at(float window_x) const;  // the column under x, clamped to the columns
    float right_of(int column) const;     // the window x of the column's right edge
    // A window point in the coordinates of `column`'s own view.
    glm::vec2 local(const glm::vec2& window_point, int column) const;
    ViewSize view() const { return {width, height}; }
};

// One run of a side-by-side frame: what is drawn and the view kept for it between frames.
struct RunView {
    const Simulation* simulation;
    view::ClothView* cloth_view;
};

// Draws `runs` side by side through one camera, each into a column `column_width` px wide
// and the framebuffer's height, the first at the left, through `scratch` framebuffers kept
// between frames; a single run is drawn straight into `framebuffer`. The window and the
// headless screenshot (--compare) both draw through this.
void render_columns(raster::Framebuffer& framebuffer, std::vector<raster::Framebuffer>& scratch,
                    const raster::Camera& camera, std::span<const RunView> runs, int column_width,
                    const view::FrameOptions& options, float ground_height,
                    WorkerPool* pool = nullptr);

// Draws every run of `state` into its column of `framebuffer` (resized to the view), through
// `scratch` framebuffers kept between frames. With one run it draws straight into it.
// `pool` draws each frame in bands (none: one thread).
void render_runs(raster::Framebuffer& framebuffer, std::vector<raster::Framebuffer>& scratch,
                 DemoState& state, const Columns& columns, WorkerPool* pool = nullptr);

}  // namespace weft::app
