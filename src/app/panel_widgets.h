// What every section of the parameter panel edits with: checked edits with their refusal said
// under the control that made them, numbers written for the loader, and sliders whose digits
// follow the value's magnitude. The sections (control_panel.cpp, panel_*_section.cpp) draw
// into the current ImGui window.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "app/demo_state.h"

namespace weft::app {

// Every edit goes through DemoState::edit as a typed edit, checked by the rules a scene file
// is: a refused value (one typed past a slider's range with Ctrl+click, say) shows its error
// and changes nothing. The edit's key (scene_edit_name) names the control for its refusal.
void edit(DemoState& state, const SceneEdit& change);
// The answer to an edit made some other way (DemoState::change_scene, a companion's change):
// `error` is said under `control` until the next edit.
void answer_edit(std::string_view control, const std::optional<std::string>& error);
// Under the control named `control`, the refusal of its edit if that was the last edit:
// whole, wrapped to the panel, where the eye already is.
void refusal_below(std::string_view control);

// Significant digits a slider shows its value with.
inline constexpr int slider_digits = 3;

// A logarithmic slider over [low, high], its value shown with slider_digits significant
// digits and `suffix` after it; Ctrl+click types any value, which change() checks.
bool slider_log(const char* label, double& value, double low, double high,
                std::string_view suffix = "");
// A linear slider over [low, high] with a fixed format; Ctrl+click types any value.
bool slider(const char* label, double& value, double low, double high, const char* format);
// Three numbers on one line (a position, gravity), dragged at `speed` per pixel or typed
// with Ctrl+click; each shown with 3 significant digits.
bool drag3(const char* label, Vec3d& v, double speed);

}  // namespace weft::app
