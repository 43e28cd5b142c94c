#include <imgui.h>
#include <cmath>
#include <string>

#include "app/grid_edit.h"
#include "app/number_format.h"
#include "app/panel_sections.h"
#include "app/panel_widgets.h"
#include "app/status_text.h"

namespace weft::app {
namespace {

// Names the refusal of Apply is said under.
constexpr const char* grid_control = "cloth.grid";

// The pins choice: the three presets and, when the draft holds a list of pins (from the
// scene), that list.
void pins_combo(ClothSpec& draft) {
    const char* presets[] = {"none", "top-corners", "top-row"};
    const std::string listed =
        "as listed (" + counted(static_cast<long long>(draft.pin_list.size()), "pin", "pins") + ")";
    const char* shown = draft.pin_preset == PinPreset::list
                            ? listed.c_str()
                            : presets[static_cast<int>(draft.pin_preset)];
    if (!ImGui::BeginCombo("pins", shown)) return;
    for (int p = 0; p < 3; ++p)
        if (ImGui::Selectable(presets[p], static_cast<int>(draft.pin_preset) == p))
            draft.pin_preset = static_cast<PinPreset>(p);
    if (!draft.pin_list.empty() &&
        ImGui::Selectable(listed.c_str(), draft.pin_preset == PinPreset::list))
        draft.pin_preset = PinPreset::list;
    ImGui::EndCombo();
}

}  // namespace

void grid_section(DemoState& state) {
    // The draft, and the running grid it was taken from: when the running grid changes
    // (Apply, another scene, a replay) the draft starts again from it.
    static ClothSpec draft, drafted_from;
    static bool drafted = false;
    const ClothSpec& running = state.simulation().scene().cloth;
    if (!drafted || !same_grid(running, drafted_from)) {
        draft = drafted_from = running;
        drafted = true;
    }
    ImGui::InputInt("rows", &draft.rows);
    ImGui::InputInt("cols", &draft.cols);
    const std::string spacing_format = significant_format(draft.spacing, slider_digits);
    ImGui::InputDouble("spacing (m)", &draft.spacing, 0.0, 0.0, spacing_format.c_str());
    int layout = static_cast<int>(draft.layout), orientation = static_cast<int>(draft.orientation);
    if (ImGui::Combo("layout", &layout, "grid\0offset\0"))
        draft.layout = static_cast<Layout>(layout);
    if (ImGui::Combo("orientation", &orientation, "vertical\0horizontal\0"))
        draft.orientation = static_cast<Orientation>(orientation);
    pins_combo(draft);
    // A size that cannot be a grid is said as it is typed, in place of a count that would
    // read as a negative number of particles, and cannot be applied.
    const char* bad_size = draft.rows < 1   ? "rows: at least 1"
                           : draft.cols < 1 ? "cols: at least 1"
                           : !(draft.spacing > 0.0 && std::isfinite(draft.spacing))
                               ? "spacing: more than 0 m"
                               : nullptr;
    const long long particles = bad_size ? 0 : grid_particle_count(draft);
    if (bad_size)
        ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", bad_size);
    else
        ImGui::Text("%s", counted(particles, "particle", "particles").c_str());
    // Said before Apply, so the number typed is seen to be too many while it is typed.
    if (particles > max_window_grid_particles)
        ImGui::TextColored(ImVec4(1, 0.6f, 0.2f, 1), "more than the window's limit of %s",
                           counted(max_window_grid_particles, "particle", "particles").c_str());
    const bool edited = !same_grid(draft, running);
    ImGui::BeginDisabled(!edited || bad_size != nullptr);
    if (ImGui::Button("apply (rebuilds the cloth)"))
        answer_edit(grid_control, apply_grid(state, draft));
    ImGui::SameLine();
    if (ImGui::Button("revert")) {
        draft = running;
        answer_edit(grid_control, std::nullopt);
    }
    ImGui::EndDisabled();
    refusal_below(grid_control);
}

}  // namespace weft::app
