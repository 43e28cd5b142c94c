#include "app/side_by_side.h"

#include <algorithm>
#include <cmath>

namespace weft::app {

Columns Columns::split(const ScreenRect& view, int runs) {
    Columns columns;
    columns.count = std::max(1, runs);
    columns.width = std::max(1, static_cast<int>(view.width) / columns.count);
    columns.height = std::max(1, static_cast<int>(view.height));
    columns.left = view.x;
    columns.top = view.y;
    return columns;
}

int Columns::column_at(float window_x) const {
    const int column = static_cast<int>(std::floor((window_x - left) / static_cast<float>(width)));
    return std::clamp(column, 0, count - 1);
}

float Columns::right_of(int column) const {
    return left + static_cast<float>((column + 1) * width);
}

glm::vec2 Columns::local(const glm::vec2& window_point, int column) const {
    return {window_point.x - left - static_cast<float>(column * width), window_point.y - top};
}

namespace {

view::ClothView& run_view(DemoState& state, int run) {
    return run == 0 ? state.cloth_view
                    : state.companions[static_cast<std::size_t>(run - 1)].cloth_view;
}

}  // namespace

void render_runs(raster::Framebuffer& framebuffer, std::vector<raster::Framebuffer>& scratch,
                 DemoState& state, const Columns& columns, WorkerPool* pool) {
    const raster::Camera camera = state.rig.camera();
    if (columns.count == 1) {
        view::render_frame(framebuffer, camera, state.simulation.cloth(), state.cloth_view,
                           state.frame_options, state.ground_height, state.simulation.colliders(),
                           pool);
        return;
    }
    framebuffer.clear(state.frame_options.background);
    scratch.resize(static_cast<std::size_t>(columns.count), raster::Framebuffer(1, 1));
    for (int run = 0; run < columns.count; ++run) {
        raster::Framebuffer& column = scratch[static_cast<std::size_t>(run)];
        if (column.width() != columns.width || column.height() != columns.height)
            column.resize(columns.width, columns.height);
        const Simulation& simulation = state.run(run);
        view::render_frame(column, camera, simulation.cloth(), run_view(state, run),
                           state.frame_options, state.ground_height, simulation.colliders(), pool);
        const int left = run * columns.width;
        const int copied = std::min(columns.width, framebuffer.width() - left);
        for (int y = 0; y < std::min(columns.height, framebuffer.height()) && copied > 0; ++y)
            std::copy_n(
                column.colours().begin() + static_cast<long>(column.index(0, y)), copied,
                framebuffer.colours().begin() + static_cast<long>(framebuffer.index(left, y)));
    }
}

}  // namespace weft::app
