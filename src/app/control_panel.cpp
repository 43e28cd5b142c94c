// Table of contents: controls table · run buttons · solver · materials · tearing and limits
// · side by side · record and replay · view · scenes · save · the panel's layout · help
// overlay. The statistics, forces, colliders and grid sections are in panel_*_section.cpp.
#include "app/control_panel.h"

#include <imgui.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "app/atomic_file.h"
#include "app/captures_folder.h"
#include "app/panel_sections.h"
#include "app/panel_widgets.h"
#include "app/profile_text.h"
#include "app/screenshot_names.h"
#include "app/session_record.h"
#include "app/status_text.h"
#include "sim/guards/stability_limit.h"
#include "sim/scene/scene_rules.h"

namespace weft::app {

const char* const controls_text[][2] = {
    {"W / S", "move forward / back"},
    {"A / D", "move left / right"},
    {"Shift + W/A/S/D/Q/E", "move the first sphere (scenes with one)"},
    {"Q / E", "move down / up"},
    {"arrow keys", "orbit around the point looked at"},
    {"mouse wheel", "zoom toward / away from the point looked at"},
    {"Home / C", "frame the cloth (its largest piece) / the scene's camera"},
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
    {"F9", "start / stop capturing frames, 30 a simulated second (weft-frames-NNNN/)"},
    {"O", "the cloth as a mesh (weft-cloth-NNNN.obj: for Blender, or a scene's cloth.mesh)"},
    {"F5", "start recording the session (restarts the scene) / stop and save it"},
    {"", "all of these go to ~/weft-captures, or $WEFT_CAPTURES when set"},
    {"H or F1", "this help"},
    {"Esc", "quit"},
};
const int controls_count = static_cast<int>(std::size(controls_text));

// The longest label beside a control; the label column is as wide as it.
constexpr const char* widest_label = "field of view (deg)";

namespace {

// The buttons beside the keys P, N and R, calling what the keys call.
void run_buttons(DemoState& state) {
    // "###pause": one button whose label says what a click does now.
    if (ImGui::SmallButton(state.paused ? "resume (P)###pause" : "pause (P)###pause"))
        state.toggle_pause();
    ImGui::SameLine();
    ImGui::BeginDisabled(!state.paused);  // one step is a paused run's
    if (ImGui::SmallButton("step (N)")) state.step_once();
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::SmallButton("reset (R)")) state.reset_simulation();
}

// The integrators' names for a combo box: integrator_names (scene.h) as C strings.
struct IntegratorNames {
    const char* names[integrator_names.size()];
    IntegratorNames() {
        for (std::size_t i = 0; i < integrator_names.size(); ++i)
            names[i] = integrator_names[i].data();
    }
};

bool integrator_combo(int& current, const char* label = "integrator") {
    static const IntegratorNames combo;
    return ImGui::Combo(label, &current, combo.names, static_cast<int>(integrator_names.size()));
}

void solver(DemoState& state) {
    const Simulation& sim = state.simulation();
    int current = static_cast<int>(sim.integrator());
    if (integrator_combo(current))
        edit(state, {SceneKey::integrator, static_cast<Integrator>(current)});
    refusal_below("solver.integrator");
    double dt_ms = sim.dt() * 1e3;
    if (slider_log("dt (ms)", dt_ms, 0.01, 10.0)) edit(state, {SceneKey::dt, dt_ms * 1e-3});
    refusal_below("solver.dt");
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
    for (SpringFamily family :
         {SpringFamily::structural, SpringFamily::shear, SpringFamily::bend}) {
        const Scene& scene = state.simulation().scene();
        const SpringFamilySpec& spec = family == SpringFamily::structural ? scene.structural
                                       : family == SpringFamily::shear    ? scene.shear
                                                                          : scene.bend;
        const std::string key = std::string("springs.") + spring_family_name(family);
        const auto index = static_cast<std::size_t>(family);  // spring_family_names' order
        ImGui::PushID(static_cast<int>(family));
        const SpringGroup* group = state.simulation().cloth().find_group(family);
        const std::size_t count = group ? group->springs.size() : 0;
        if (family == SpringFamily::structural) {
            ImGui::Text("%s springs (%zu)", spring_family_name(family), count);
        } else {
            char label[64];
            std::snprintf(label, sizeof label, "%s springs (%zu)", spring_family_name(family),
                          count);
            bool enabled = spec.enabled;
            if (ImGui::Checkbox(label, &enabled))
                edit(state, {spring_key(index, SpringField::enabled), enabled});
            refusal_below(key + ".enabled");
        }
        double stiffness = spec.stiffness, damping = spec.damping;
        if (slider_log("stiffness (N/m)", stiffness, 1.0, 1e5))
            edit(state, {spring_key(index, SpringField::stiffness), stiffness});
        refusal_below(key + ".stiffness");
        if (slider_log("damping (N s/m)", damping, 1e-4, 10.0))
            edit(state, {spring_key(index, SpringField::damping), damping});
        refusal_below(key + ".damping");
        ImGui::PopID();
    }
    const ClothSpec& cloth = state.simulation().scene().cloth;
    if (!cloth.mesh.empty() && !cloth.mesh_particle_mass) {
        // A mesh's masses are lumped from its triangles' areas: its material has a density.
        double density = cloth.density;  // kg/m²
        if (slider_log("density (kg/m2)", density, 0.01, 100.0))
            edit(state, {SceneKey::cloth_density, density});
        refusal_below("cloth.density");
        return;
    }
    double mass_g = cloth.particle_mass * 1e3;
    if (slider_log("particle mass (g)", mass_g, 0.1, 1000.0))
        edit(state, {SceneKey::cloth_particle_mass, mass_g * 1e-3});
    refusal_below("cloth.particle_mass");
}

// An optional feature table such as [tearing]: a checkbox for its presence, and under it a
// slider for its value (beside the checkbox it ran past a narrow panel's edge). Switching it
// on is an edit like any other; switching it off removes the table, which is always valid.
void optional_feature(DemoState& state, const char* label, SceneKey key,
                      std::optional<double> Scene::*member, double shown, double low, double high,
                      const char* suffix) {
    const std::string path(scene_key_name(key));
    ImGui::PushID(path.c_str());
    const std::optional<double>& value = state.simulation().scene().*member;
    bool on = value.has_value();
    double v = value.value_or(shown);
    if (ImGui::Checkbox(label, &on))
        edit(state, on ? SceneEdit{key, v} : SceneEdit{key, FeatureOff{}});
    if (slider_log(path.substr(path.find('.') + 1).c_str(), v, low, high, suffix) && on)
        edit(state, {key, v});
    refusal_below(path);
    ImGui::PopID();
}

// Where the main run's steps went over about the last second, as --profile prints a run's.
void profile_section(const DemoState& state) {
    const StepProfile& recent = state.statistics.recent_profile;
    if (recent.steps == 0) {
        ImGui::TextDisabled("no steps in the last second");
        return;
    }
    ImGui::TextUnformatted(profile_panel_text(recent).c_str());
}

void save(DemoState& state) {
    static char path[512] = "";
    static std::string status;
    static bool confirm_replace = false;
    if (path[0] == '\0') {
        const std::filesystem::path loaded(state.scene_path);
        const std::string suggestion =
            (loaded.parent_path() / (loaded.stem().string() + "-saved.toml")).string();
        std::snprintf(path, sizeof path, "%s", suggestion.c_str());
    }
    if (ImGui::InputText("file", path, sizeof path)) confirm_replace = false;
    std::string error;
    if (!confirm_replace && ImGui::Button("save parameters and camera")) {
        if (state.save_scene(path, false, error)) {
            status = std::string("saved ") + path;
        } else if (std::filesystem::exists(path)) {
            confirm_replace = true;  // ask before replacing anything, the loaded scene above all
            status.clear();
        } else {
            status = error;
        }
    }
    if (confirm_replace) {
        std::error_code ignored;
        const bool loaded_from = std::filesystem::equivalent(path, state.scene_path, ignored);
        ImGui::TextColored(ImVec4(1, 0.8f, 0.3f, 1), "%s exists%s. Replace it?", path,
                           loaded_from ? " (the scene this was loaded from)" : "");
        if (ImGui::Button("replace")) {
            status = state.save_scene(path, true, error) ? std::string("saved ") + path : error;
            confirm_replace = false;
        }
        ImGui::SameLine();
        if (ImGui::Button("cancel")) confirm_replace = false;
    }
    if (!status.empty()) ImGui::TextWrapped("%s", status.c_str());
}

// Copies of the scene beside the main run, each with its own integrator and dt.
void comparison(DemoState& state) {
    static int new_integrator = static_cast<int>(Integrator::rk4);
    integrator_combo(new_integrator, "##new");
    ImGui::SameLine();
    if (ImGui::Button("add a copy beside"))
        state.add_copy(static_cast<Integrator>(new_integrator), state.simulation().dt());
    for (std::size_t c = 0; c + 1 < state.runs.size(); ++c) {
        ImGui::PushID(static_cast<int>(c) + 100);
        const Simulation& copy = state.runs[c + 1].simulation;
        ImGui::Text("copy %zu", c + 1);
        int current = static_cast<int>(copy.integrator());
        const std::string control = "copy." + std::to_string(c);
        if (integrator_combo(current))
            answer_edit(
                control,
                state.edit_copy(c, {{SceneKey::integrator, static_cast<Integrator>(current)}}));
        double dt_ms = copy.dt() * 1e3;
        if (slider_log("dt (ms)", dt_ms, 0.01, 10.0))
            answer_edit(control, state.edit_copy(c, {{SceneKey::dt, dt_ms * 1e-3}}));
        refusal_below(control);
        if (ImGui::Button("remove")) state.remove_copy(c);
        ImGui::PopID();
    }
}

// Recording the session (F5) and replaying a recording.
void session(DemoState& state) {
    static char replay_path[512] = "weft-session-0001.toml";
    static std::string status;
    if (state.replaying) {
        ImGui::Text("replaying: step %llu of %llu",
                    static_cast<unsigned long long>(state.steps_run),
                    static_cast<unsigned long long>(state.replaying->steps));
        if (ImGui::Button("stop the replay")) state.stop_replay();
        return;
    }
    if (state.recording) {
        ImGui::TextColored(
            ImVec4(1, 0.4f, 0.4f, 1), "recording: %s, %s",
            counted(static_cast<long long>(state.recording->events.size()), "event", "events")
                .c_str(),
            counted(static_cast<long long>(state.steps_run), "step", "steps").c_str());
        if (ImGui::Button("stop and save (F5)")) {
            // Where the F5 key saves it: the captures folder, never the working folder.
            const SessionRecord record = state.stop_recording();
            std::string error;
            if (!make_captures_folder(state.captures, error)) {
                status = error;
            } else {
                const std::string path = next_free_path(state.captures, "weft-session", "toml");
                status = write_file_atomically(path, session_to_toml(record), false, error)
                             ? "saved " + path
                             : error;
            }
        }
    } else if (ImGui::Button("record (F5; restarts the scene)")) {
        state.start_recording();
        status.clear();
    }
    ImGui::InputText("session", replay_path, sizeof replay_path);
    ImGui::SameLine();
    if (ImGui::Button("replay")) {
        std::string error;
        if (auto record = read_session_file(replay_path, error)) {
            state.start_replay(*record);
            status.clear();
        } else {
            status = error;
        }
    }
    if (!status.empty()) ImGui::TextWrapped("%s", status.c_str());
}

void limits(DemoState& state) {
    optional_feature(state, "tearing", SceneKey::tear_max_stretch, &Scene::tear_max_stretch, 1.6,
                     1.05, 5.0, " x rest");
    optional_feature(state, "strain limit", SceneKey::strain_limit_max_strain,
                     &Scene::strain_limit_max_strain, 0.1, 0.01, 0.5, "");
    optional_feature(state, "self-collision", SceneKey::self_collision_thickness,
                     &Scene::self_collision_thickness, 0.01, 0.002, 0.1, " m");
    double radius = state.grab_radius;
    if (slider_log("grab radius (m)", radius, 0.005, 0.5)) {
        const bool taken = radius > 0.0 && radius <= 10.0;
        if (taken) state.grab_radius = radius;
        answer_edit("grab_radius",
                    taken ? std::nullopt
                          : std::optional<std::string>("grab radius must be in (0, 10] m, got " +
                                                       format_number(radius)));
    }
    refusal_below("grab_radius");
    if (ImGui::Button("release all pins (U)")) state.release_all_pins();
}

void view_toggles(DemoState& state) {
    view::FrameOptions& o = state.frame_options;
    ImGui::Checkbox("shaded", &o.shaded);
    ImGui::SameLine();
    ImGui::Checkbox("wireframe", &o.wireframe);
    ImGui::SameLine();
    ImGui::Checkbox("ground", &o.ground);
    ImGui::SameLine();
    ImGui::Checkbox("shadows", &o.shadows);
    ImGui::Checkbox("springs by strain", &o.strain_springs);
    ImGui::SameLine();
    ImGui::Checkbox("particles", &o.particles);
    double fov = state.rig.fov_degrees;
    if (slider("field of view (deg)", fov, 10.0, 120.0, "%.3g"))
        answer_edit("camera.fov_degrees", state.change_field_of_view(fov));
    refusal_below("camera.fov_degrees");
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
    if (!error.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", error.c_str());
}

}  // namespace

bool draw_control_panel(DemoState& state, const ScreenRect& area) {
    // Docked where the layout puts it, its height the window's: what does not fit scrolls
    // inside the panel instead of running off the window. The title bar's arrow folds it to a
    // strip, and the view takes the window.
    ImGui::SetNextWindowPos(ImVec2(area.x, area.y), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(area.width, area.height), ImGuiCond_Always);
    // No background: a blended rectangle the size of the panel, every frame, in SDL's software
    // renderer; the window is cleared to the same colour under it (demo_window.cpp).
    const bool open =
        ImGui::Begin("weft", nullptr,
                     ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                         ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBackground);
    if (!open) {
        ImGui::End();
        return false;
    }
    // Every label in a column of its own right of its control, as wide as the widest label,
    // so no unit is cut off; text wraps at the panel's edge.
    const ImGuiStyle& style = ImGui::GetStyle();
    ImGui::PushItemWidth(-(ImGui::CalcTextSize(widest_label).x + style.ItemInnerSpacing.x));
    ImGui::PushTextWrapPos(0.0f);
    // A slider's value is written over its grab: a thin, translucent grab leaves the digits
    // readable ("4|0", not a block hiding the middle digit).
    ImGui::PushStyleVar(ImGuiStyleVar_GrabMinSize, 3.0f);
    ImVec4 grab = style.Colors[ImGuiCol_SliderGrab];
    grab.w = 0.3f;
    ImGui::PushStyleColor(ImGuiCol_SliderGrab, grab);
    // The scene's name, and under it pause, step and reset, each labelled with its key: at
    // the top, where no section's height can push them out of sight.
    // The scene picker and the help key come right after them, above the fold of any window.
    ImGui::TextUnformatted(state.simulation().scene().name.c_str());
    ImGui::SameLine();
    ImGui::TextDisabled("  H: help");
    run_buttons(state);
    scenes(state);
    statistics_section(state);
    // Only the solver is open at first: the materials' sliders would push everything else
    // below the fold.
    if (ImGui::CollapsingHeader("solver", ImGuiTreeNodeFlags_DefaultOpen)) solver(state);
    if (ImGui::CollapsingHeader("materials")) materials(state);
    // A mesh's shape is its OBJ file's: there is no grid to rebuild.
    if (state.simulation().scene().cloth.mesh.empty() &&
        ImGui::CollapsingHeader("grid (rebuilt on apply)"))
        grid_section(state);
    if (ImGui::CollapsingHeader("forces")) forces_section(state);
    if (ImGui::CollapsingHeader("tearing, limits, pins")) limits(state);
    if (ImGui::CollapsingHeader("colliders")) colliders_section(state);
    if (ImGui::CollapsingHeader("side by side")) comparison(state);
    if (ImGui::CollapsingHeader("record and replay")) session(state);
    if (ImGui::CollapsingHeader("view")) view_toggles(state);
    if (ImGui::CollapsingHeader("save scene")) save(state);
    // Last: opened, it pushes nothing else down.
    if (ImGui::CollapsingHeader("step profile")) profile_section(state);
    ImGui::PopStyleColor();
    ImGui::PopStyleVar();
    ImGui::PopTextWrapPos();
    ImGui::PopItemWidth();
    ImGui::End();
    return true;
}

void draw_help_overlay(bool& open) {
    if (!open) return;
    // A card over everything, the panel included: opaque (the cloth and the panel's text
    // showed through it), in focus so it is drawn last, as wide as its text needs up to nine
    // tenths of the window, its descriptions wrapped beside a key column as wide as its
    // longest key ("Shift + W/A/S/D/Q/E" ran into its description).
    const ImVec2 size = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(0.5f * size.x, 0.5f * size.y), ImGuiCond_Always,
                            ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(std::min(0.9f * size.x, 46.0f * ImGui::GetFontSize()), 0.0f),
                             ImGuiCond_Always);
    ImGui::SetNextWindowSizeConstraints(ImVec2(0.0f, 0.0f), ImVec2(size.x, 0.9f * size.y));
    ImGui::SetNextWindowBgAlpha(1.0f);
    ImGui::SetNextWindowFocus();
    ImGui::Begin(
        "controls (H or F1 closes this)", &open,
        ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoSavedSettings);
    if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_PadOuterX)) {
        ImGui::TableSetupColumn("key", ImGuiTableColumnFlags_WidthFixed);
        ImGui::TableSetupColumn("does", ImGuiTableColumnFlags_WidthStretch);
        for (const auto& row : controls_text) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(row[0]);
            ImGui::TableNextColumn();
            ImGui::TextWrapped("%s", row[1]);
        }
        ImGui::EndTable();
    }
    ImGui::End();
}

}  // namespace weft::app
