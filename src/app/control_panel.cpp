// Table of contents: controls table · statistics · solver · materials · forces · tearing and
// limits · view · scenes · overlays.
#include "app/control_panel.h"

#include <imgui.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "sim/energy.h"
#include "sim/stability_limit.h"

namespace weft::app {

const char* const controls_text[][2] = {
    {"W / S", "move forward / back"},
    {"A / D", "move left / right"},
    {"Q / E", "move down / up"},
    {"arrow keys", "turn left / right / up / down"},
    {"mouse wheel", "zoom"},
    {"Home or C", "reset the camera"},
    {"space + mouse", "pull the cloth (grab where the cursor is)"},
    {"left mouse drag", "pull the cloth"},
    {"right mouse drag", "cut the springs the cursor crosses"},
    {"T", "pin or unpin the particle under the cursor"},
    {"U", "release all pins"},
    {"P", "pause / resume"},
    {"N", "one step (while paused)"},
    {"R", "reset the scene"},
    {"F12", "screenshot of the view (weft-screenshot-NNNN.png, never overwritten)"},
    {"Shift+F12", "screenshot of the whole window, panel included"},
    {"H or F1", "this help"},
    {"Esc", "quit"},
};
const int controls_count = static_cast<int>(std::size(controls_text));

namespace {

bool slider_log(const char* label, double& value, double low, double high, const char* format) {
    float v = static_cast<float>(value);
    if (!ImGui::SliderFloat(label, &v, static_cast<float>(low), static_cast<float>(high), format,
                            ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp))
        return false;
    value = v;
    return true;
}

void statistics(DemoState& state) {
    const DemoStatistics& s = state.statistics;
    const Cloth& cloth = state.simulation.cloth();
    ImGui::Text("%.0f fps   sim %.2f ms   raster %.2f ms", ImGui::GetIO().Framerate,
                s.sim_seconds * 1e3, s.raster_seconds * 1e3);
    ImGui::Text("%d steps/frame   t = %.2f s%s", s.steps, state.simulation.time(),
                state.paused ? "   (paused)" : "");
    ImGui::Text("%zu particles, %zu springs, %d threads", cloth.particle_count(),
                cloth.spring_count(), state.simulation.thread_count());
    if (!s.energy.empty()) {
        ImGui::Text("energy %.4g J", s.energy.back());
        ImGui::PlotLines("##energy", s.energy.data(), static_cast<int>(s.energy.size()), 0, nullptr,
                         FLT_MAX, FLT_MAX, ImVec2(0, 50));
    }
    state.cloth_view.spring_colours(cloth);  // measures the largest strain
    ImGui::Text("largest stretch %.1f %%", 100.0 * state.cloth_view.largest_strain());
    if (state.recoveries > 0)
        ImGui::TextColored(ImVec4(1, 0.6f, 0.2f, 1), "recovered from divergence %d times",
                           state.recoveries);
}

void solver(DemoState& state) {
    Simulation& sim = state.simulation;
    const char* names[] = {"explicit-euler", "symplectic-euler", "verlet", "velocity-verlet", "rk4",
                           "implicit-euler"};
    int current = static_cast<int>(sim.integrator());
    if (ImGui::Combo("integrator", &current, names, static_cast<int>(std::size(names))))
        sim.set_integrator(static_cast<Integrator>(current));
    double dt_ms = sim.dt() * 1e3;
    if (slider_log("dt (ms)", dt_ms, 0.01, 10.0, "%.3f")) sim.set_dt(dt_ms * 1e-3);
    const double limit =
        estimated_step_limit(sim.cloth(), sim.force_field().air_drag, sim.integrator());
    if (limit > 0.0 && std::isfinite(limit)) {
        const bool over = sim.dt() > limit;
        ImGui::TextColored(over ? ImVec4(1, 0.3f, 0.3f, 1) : ImVec4(0.6f, 0.9f, 0.6f, 1),
                           "step limit estimate %.3f ms%s", limit * 1e3,
                           over ? ": may blow up" : "");
    } else if (limit == 0.0) {
        ImGui::TextColored(ImVec4(1, 0.6f, 0.2f, 1),
                           "explicit Euler: no step is safe without damping");
    }
}

void materials(DemoState& state) {
    Simulation& sim = state.simulation;
    for (SpringFamily family :
         {SpringFamily::structural, SpringFamily::shear, SpringFamily::bend}) {
        const Scene& scene = sim.scene();
        const SpringFamilySpec& spec = family == SpringFamily::structural ? scene.structural
                                       : family == SpringFamily::shear    ? scene.shear
                                                                          : scene.bend;
        ImGui::PushID(static_cast<int>(family));
        const SpringGroup* group = sim.cloth().find_group(family);
        const std::size_t count = group ? group->springs.size() : 0;
        if (family == SpringFamily::structural) {
            ImGui::Text("%s springs (%zu)", spring_family_name(family), count);
        } else {
            char label[64];
            std::snprintf(label, sizeof label, "%s springs (%zu)", spring_family_name(family),
                          count);
            bool enabled = spec.enabled;
            if (ImGui::Checkbox(label, &enabled)) sim.set_family_enabled(family, enabled);
        }
        double stiffness = spec.stiffness, damping = spec.damping;
        bool changed = slider_log("stiffness (N/m)", stiffness, 1.0, 1e5, "%.0f");
        changed |= slider_log("damping (N s/m)", damping, 1e-4, 10.0, "%.4f");
        if (changed) sim.set_spring_material(family, stiffness, damping);
        ImGui::PopID();
    }
    double mass_g = sim.scene().cloth.particle_mass * 1e3;
    if (slider_log("particle mass (g)", mass_g, 0.1, 1000.0, "%.2f"))
        sim.set_particle_mass(mass_g * 1e-3);
}

void forces(DemoState& state) {
    Simulation& sim = state.simulation;
    ForcesSpec f = sim.scene().forces;
    bool changed = false;
    float gravity = static_cast<float>(f.gravity[1]);
    if (ImGui::SliderFloat("gravity y (m/s2)", &gravity, -30.0f, 5.0f))
        f.gravity[1] = gravity, changed = true;
    changed |= slider_log("air drag (N s/m)", f.air_drag, 1e-4, 1.0, "%.4f");
    float strength = static_cast<float>(std::hypot(f.wind[0], f.wind[2]));
    float heading = static_cast<float>(std::atan2(f.wind[2], f.wind[0]) * 180.0 / M_PI);
    bool wind_changed = ImGui::SliderFloat("wind (m/s)", &strength, 0.0f, 20.0f);
    wind_changed |= ImGui::SliderFloat("wind heading (deg)", &heading, -180.0f, 180.0f);
    if (wind_changed) {
        f.wind[0] = strength * std::cos(heading * M_PI / 180.0);
        f.wind[2] = strength * std::sin(heading * M_PI / 180.0);
        changed = true;
    }
    if (changed) sim.set_force_field(f.gravity, f.air_drag, f.wind);
}

void limits(DemoState& state) {
    Simulation& sim = state.simulation;
    bool tearing = sim.scene().tear_max_stretch.has_value();
    double tear = sim.scene().tear_max_stretch.value_or(1.6);
    bool changed = ImGui::Checkbox("tearing", &tearing);
    ImGui::SameLine();
    changed |= slider_log("tear at x rest", tear, 1.05, 5.0, "%.2f");
    if (changed) sim.set_tear_limit(tearing ? std::optional<double>(tear) : std::nullopt);
    bool limiting = sim.scene().strain_limit_max_stretch.has_value();
    double limit = sim.scene().strain_limit_max_stretch.value_or(0.1);
    changed = ImGui::Checkbox("strain limit", &limiting);
    ImGui::SameLine();
    changed |= slider_log("max stretch", limit, 0.01, 1.0, "%.2f");
    if (changed) sim.set_strain_limit(limiting ? std::optional<double>(limit) : std::nullopt);
    slider_log("drag radius (m)", state.drag_radius, 0.005, 0.5, "%.3f");
    if (ImGui::Button("release all pins (U)")) sim.release_all_pins();
}

void view_toggles(DemoState& state) {
    view::FrameOptions& o = state.frame_options;
    ImGui::Checkbox("shaded", &o.shaded);
    ImGui::SameLine();
    ImGui::Checkbox("wireframe", &o.wireframe);
    ImGui::SameLine();
    ImGui::Checkbox("ground", &o.ground);
    ImGui::Checkbox("springs by strain", &o.strain_springs);
    ImGui::SameLine();
    ImGui::Checkbox("particles", &o.particles);
}

void scenes(DemoState& state) {
    static std::string error;
    const std::filesystem::path folder = std::filesystem::path(state.scene_path).parent_path();
    std::vector<std::string> files;
    std::error_code ignored;
    for (const auto& entry :
         std::filesystem::directory_iterator(folder.empty() ? "." : folder, ignored))
        if (entry.path().extension() == ".toml") files.push_back(entry.path().string());
    std::sort(files.begin(), files.end());
    if (ImGui::BeginCombo("scene",
                          std::filesystem::path(state.scene_path).filename().string().c_str())) {
        for (const std::string& file : files) {
            if (ImGui::Selectable(std::filesystem::path(file).filename().string().c_str(),
                                  file == state.scene_path)) {
                error.clear();
                state.load_scene(file, error);
            }
        }
        ImGui::EndCombo();
    }
    if (ImGui::Button("reset (R)")) state.reset_simulation();
    if (!error.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", error.c_str());
}

}  // namespace

void draw_control_panel(DemoState& state) {
    ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(390, 0), ImGuiCond_FirstUseEver);
    ImGui::Begin("weft");
    ImGui::TextUnformatted(state.simulation.scene().name.c_str());
    statistics(state);
    if (ImGui::CollapsingHeader("solver", ImGuiTreeNodeFlags_DefaultOpen)) solver(state);
    if (ImGui::CollapsingHeader("materials", ImGuiTreeNodeFlags_DefaultOpen)) materials(state);
    if (ImGui::CollapsingHeader("forces")) forces(state);
    if (ImGui::CollapsingHeader("tearing, limits, pins")) limits(state);
    if (ImGui::CollapsingHeader("view")) view_toggles(state);
    if (ImGui::CollapsingHeader("scenes", ImGuiTreeNodeFlags_DefaultOpen)) scenes(state);
    ImGui::TextDisabled("H: help");
    ImGui::End();
}

void draw_help_overlay(bool& open) {
    if (!open) return;
    const ImVec2 size = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(0.5f * size.x, 0.5f * size.y), ImGuiCond_Always,
                            ImVec2(0.5f, 0.5f));
    ImGui::Begin("controls", &open,
                 ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse);
    if (ImGui::BeginTable("keys", 2)) {
        for (const auto& row : controls_text) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(row[0]);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(row[1]);
        }
        ImGui::EndTable();
    }
    ImGui::End();
}

void draw_status_overlay(const DemoState& state, double now_seconds) {
    const bool show_message = now_seconds < state.message_until && !state.message.empty();
    if (!show_message && !state.statistics.behind && !state.paused) return;
    const ImVec2 size = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(size.x * 0.5f, size.y - 10.0f), ImGuiCond_Always,
                            ImVec2(0.5f, 1.0f));
    ImGui::SetNextWindowBgAlpha(0.6f);
    ImGui::Begin("status", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                     ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoFocusOnAppearing);
    if (state.paused) ImGui::TextUnformatted("paused (P resumes, N steps)");
    if (state.statistics.behind)
        ImGui::TextColored(ImVec4(1, 0.8f, 0.3f, 1),
                           "falling behind real time: simulating slower than the clock");
    if (show_message) ImGui::TextColored(ImVec4(1, 0.5f, 0.3f, 1), "%s", state.message.c_str());
    ImGui::End();
}

}  // namespace weft::app
