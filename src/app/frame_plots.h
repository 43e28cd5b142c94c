// The HUD's plots: total energy, largest stretch and milliseconds of work per frame, one
// sample for each frame that stepped. A paused frame adds none, so every plot holds still
// while paused instead of scrolling a flat line through time that did not pass (the energy
// plot used to scroll while paused). ImGui-free, so it is tested; the panel draws them.
#pragma once

#include <cstddef>
#include <vector>

namespace weft::app {

// The last `capacity` samples of one quantity, oldest first (the order ImGui::PlotLines
// draws them in).
class PlotHistory {
  public:
    explicit PlotHistory(std::size_t capacity) : capacity_(capacity) {}

    void add(float sample);
    const std::vector<float>& samples() const { return samples_; }
    bool empty() const { return samples_.empty(); }
    float latest() const { return samples_.back(); }  // only when !empty()
    std::size_t capacity() const { return capacity_; }

  private:
    std::size_t capacity_;
    std::vector<float> samples_;
};

// Five seconds at 60 frames a second.
inline constexpr std::size_t plot_samples_kept = 300;

struct FramePlots {
    PlotHistory energy{plot_samples_kept};              // J, total energy of the main run
    PlotHistory stretch_percent{plot_samples_kept};     // %, largest spring stretch past rest
    PlotHistory frame_milliseconds{plot_samples_kept};  // ms, stepping and drawing a frame

    // One frame's samples, if it took steps (steps > 0); none for a paused frame.
    void add_frame(int steps, double energy_joules, double stretch_ratio, double work_seconds);
};

}  // namespace weft::app
