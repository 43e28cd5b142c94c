#include <imgui.h>
#include <cmath>

#include "app/panel_sections.h"
#include "app/panel_widgets.h"

namespace weft::app {

void forces_section(DemoState& state) {
    const ForcesSpec& f = state.simulation().scene().forces;
    Vec3d gravity = f.gravity;
    if (drag3("gravity (m/s2)", gravity, 0.05)) edit(state, {SceneKey::gravity, gravity});
    refusal_below("forces.gravity");
    double air_drag = f.air_drag;
    if (slider_log("air drag (N s/m)", air_drag, 1e-4, 1.0))
        edit(state, {SceneKey::air_drag, air_drag});
    refusal_below("forces.air_drag");
    // The wind as the eye sees it: how strong and from where along the ground, and how much
    // of it blows up (or down). A horizontal part untouched this frame is sent back as it is,
    // not through the sliders' floats.
    double strength = std::hypot(f.wind[0], f.wind[2]);
    double heading = std::atan2(f.wind[2], f.wind[0]) * 180.0 / M_PI;
    double upward = f.wind[1];
    bool horizontal_changed = slider("wind (m/s)", strength, 0.0, 20.0, "%.3f");
    horizontal_changed |= slider("wind heading (deg)", heading, -180.0, 180.0, "%.3f");
    const bool upward_changed = slider("wind up (m/s)", upward, -10.0, 10.0, "%.3g");
    if (horizontal_changed || upward_changed) {
        Vec3d wind = f.wind;
        if (horizontal_changed) {
            wind[0] = strength * std::cos(heading * M_PI / 180.0);
            wind[2] = strength * std::sin(heading * M_PI / 180.0);
        }
        wind[1] = upward;
        edit(state, {SceneKey::wind, wind});
    }
    refusal_below("forces.wind");
    double gust = f.gust;
    if (slider("gusts (share of the wind)", gust, 0.0, 1.0, "%.2f"))
        edit(state, {SceneKey::gust, gust});
    refusal_below("forces.gust");
}

}  // namespace weft::app
