#include "app/side_by_side.h"

#include <algorithm>
#include <cmath>

#include "view/hand_marker.h"

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

void render_columns(raster::Framebuffer& framebuffer, std::vector<raster::Framebuffer>& scratch,
                    const raster::Camera& camera, std::span<const RunView> runs, int column_width,
                    const view::FrameOptions& options, float ground_height, WorkerPool* pool) {
    if (runs.size() == 1) {
        view::render_frame(framebuffer, camera, runs[0].simulation->cloth(), *runs[0].cloth_view,
                           options, ground_height, runs[0].simulation->colliders(), pool);
        view::draw_hand_marker(framebuffer, camera, runs[0].simulation->grab(),
                               runs[0].simulation->cloth());
        return;
    }
    framebuffer.clear(options.background);
    scratch.resize(runs.size(), raster::Framebuffer(1, 1));
    const int height = framebuffer.height();
    for (std::size_t run = 0; run < runs.size(); ++run) {
        raster::Framebuffer& column = scratch[run];
        if (column.width() != column_width || column.height() != height)
            column.resize(column_width, height);
        const Simulation& simulation = *runs[run].simulation;
        view::render_frame(column, camera, simulation.cloth(), *runs[run].cloth_view, options,
                           ground_height, simulation.colliders(), pool);
        view::draw_hand_marker(column, camera, simulation.grab(), simulation.cloth());
        const int left = static_cast<int>(run) * column_width;
        const int copied = std::min(column_width, framebuffer.width() - left);
        for (int y = 0; y < height && copied > 0; ++y)
            std::copy_n(
                column.colours().begin() + static_cast<long>(column.index(0, y)), copied,
                framebuffer.colours().begin() + static_cast<long>(framebuffer.index(left, y)));
    }
}

void render_runs(raster::Framebuffer& framebuffer, std::vector<raster::Framebuffer>& scratch,
                 DemoState& state, const Columns& columns, WorkerPool* pool) {
    std::vector<RunView> runs;
    for (DemoRun& run : state.runs) runs.push_back({&run.simulation, &run.cloth_view});
    runs.resize(std::min(runs.size(), static_cast<std::size_t>(columns.count)));
    render_columns(framebuffer, scratch, state.rig.camera(), runs, columns.width,
                   state.frame_options, state.ground_height, pool);
}

}  // namespace weft::app
