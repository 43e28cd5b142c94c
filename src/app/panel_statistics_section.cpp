#include <imgui.h>
#include <cfloat>
#include <cstdio>

#include "app/panel_sections.h"
#include "app/status_text.h"

namespace weft::app {
namespace {

// One plot under its label (the latest value), the panel's full width (the label column
// would cut a long label short). The label sits above the curve, never over it; before the
// first sample there is only the label.
void plot(const char* id, const PlotHistory& history, const char* label) {
    ImGui::TextUnformatted(label);
    if (history.empty()) return;
    ImGui::PlotLines(id, history.samples().data(), static_cast<int>(history.samples().size()), 0,
                     nullptr, FLT_MAX, FLT_MAX, ImVec2(ImGui::GetContentRegionAvail().x, 28));
}

}  // namespace

void statistics_section(DemoState& state) {
    const DemoStatistics& s = state.statistics;
    const Cloth& cloth = state.simulation().cloth();
    ImGui::Text("%.0f fps   sim %.2f ms   raster %.2f ms", ImGui::GetIO().Framerate,
                s.sim_seconds * 1e3, s.raster_seconds * 1e3);
    ImGui::Text("%s a frame   t = %.2f s%s", counted(s.steps, "step", "steps").c_str(),
                state.simulation().time(), state.paused ? "   (paused)" : "");
    ImGui::Text(
        "%s, %s, %s",
        counted(static_cast<long long>(cloth.particle_count()), "particle", "particles").c_str(),
        counted(static_cast<long long>(cloth.spring_count()), "spring", "springs").c_str(),
        counted(state.simulation().thread_count(), "thread", "threads").c_str());
    // Implicit Euler's cost and accuracy per step hang on its conjugate-gradient solve.
    if (auto solve = linear_solve_text(state.simulation())) ImGui::TextUnformatted(solve->c_str());
    // The plots gain a sample for each frame that stepped, so they hold still while paused.
    const FramePlots& plots = s.plots;
    char label[192];
    if (!plots.energy.empty()) {  // measured only on frames that step
        std::snprintf(label, sizeof label, "energy %.4g J", plots.energy.latest());
        plot("##energy", plots.energy, label);
    }
    // The stretch is measured every frame, so a cut while paused shows at once.
    // Where that spring is goes on the label's second line: the panel's rows stay put.
    // Two lines always (the second blank when there is no place to name).
    std::snprintf(label, sizeof label, "%s\n%s", stretch_text(s.stretch_ratio).c_str(),
                  s.stretch_place.c_str());
    plot("##stretch", plots.stretch_percent, label);
    if (!plots.frame_milliseconds.empty()) {
        std::snprintf(label, sizeof label, "%.2f ms a frame stepping + drawing",
                      plots.frame_milliseconds.latest());
        plot("##frame_ms", plots.frame_milliseconds, label);
    }
    if (state.main_run().recovery.recoveries > 0)
        ImGui::TextColored(ImVec4(1, 0.6f, 0.2f, 1), "recovered from divergence %s",
                           counted(state.main_run().recovery.recoveries, "time", "times").c_str());
}

}  // namespace weft::app
