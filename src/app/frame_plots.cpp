#include "app/frame_plots.h"

#include <cmath>

namespace weft::app {

void PlotHistory::add(float sample) {
    if (capacity_ == 0) return;
    // Erasing the front of a few hundred floats once a frame costs nothing measurable; a
    // ring buffer would hand ImGui an offset to unwrap instead.
    if (samples_.size() >= capacity_) samples_.erase(samples_.begin());
    samples_.push_back(sample);
}

void FramePlots::add_frame(int steps, double energy_joules, double stretch_ratio,
                           double work_seconds) {
    if (steps <= 0) return;
    energy.add(static_cast<float>(energy_joules));
    // A cloth without springs has no stretch (the ratio is not finite): plotted as 0 %.
    stretch_percent.add(
        std::isfinite(stretch_ratio) ? static_cast<float>(100.0 * (stretch_ratio - 1.0)) : 0.0f);
    frame_milliseconds.add(static_cast<float>(work_seconds * 1e3));
}

}  // namespace weft::app
