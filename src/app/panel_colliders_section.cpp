#include <imgui.h>
#include <string>
#include <vector>

#include "app/panel_sections.h"
#include "app/panel_widgets.h"

namespace weft::app {

void colliders_section(DemoState& state) {
    // The floor under the drawn ground (sim/collision/floor.h), unless the scene's own ground plane
    // is.
    bool floor = state.simulation().scene().floor_enabled;
    if (ImGui::Checkbox("floor (the ground stops the cloth)", &floor))
        edit(state, {SceneKey::floor_enabled, floor});
    refusal_below("floor.enabled");
    const std::vector<ColliderSpec>& specs = state.simulation().scene().colliders;
    if (specs.empty()) {
        ImGui::TextDisabled("no other collider in this scene");
        return;
    }
    for (std::size_t c = 0; c < specs.size(); ++c) {
        ImGui::PushID(static_cast<int>(c));
        // The whole scene with this collider edited, checked like a scene file: --set cannot
        // name one entry of the [[colliders]] array.
        Scene wanted = state.simulation().scene();
        ColliderSpec& spec = wanted.colliders[c];
        const bool sphere = spec.type == ColliderType::sphere;
        if (sphere)
            ImGui::Text("sphere %zu%s", c, c == 0 ? "  (Shift+W/A/S/D/Q/E moves it)" : "");
        else
            ImGui::Text("plane %zu, normal (%.3g, %.3g, %.3g)", c, spec.normal[0], spec.normal[1],
                        spec.normal[2]);
        // Where it is (a sphere's centre, a point of the plane) and a sphere's size; dragged
        // 5 mm a pixel or typed with Ctrl+click.
        bool changed = sphere ? drag3("centre (m)", spec.center, 0.005)
                              : drag3("point (m)", spec.point, 0.005);
        if (sphere) changed |= slider_log("radius (m)", spec.radius, 0.02, 2.0);
        int response = static_cast<int>(spec.response);
        changed |= ImGui::Combo("response", &response, "impulse\0repulsion\0");
        spec.response = static_cast<ContactResponse>(response);
        changed |= slider("restitution", spec.restitution, 0.0, 1.0, "%.2f");
        changed |= slider("friction", spec.friction, 0.0, 2.0, "%.2f");
        const std::string control = "colliders." + std::to_string(c);
        if (changed) answer_edit(control, state.change_scene(wanted));
        refusal_below(control);
        ImGui::PopID();
    }
}

}  // namespace weft::app
