#include "app/panel_widgets.h"

#include <imgui.h>
#include <imgui_internal.h>
#include <algorithm>
#include <cstdio>

#include "app/edit_answer.h"
#include "app/number_format.h"

namespace weft::app {
namespace {

// The last edit and, if it was refused, why: said under the control that made it.
LastEdit last_edit;

// Ctrl+click (or a double-click on a drag) turns a control into a text field, and Dear ImGui
// applies what the field holds at every keystroke: typing 1e308 would apply 1, 1e3 and 1e30
// on the way. So while a field is typed in, what it holds waits here, and it is applied once,
// as the field is left with Enter or a click elsewhere (Escape leaves the value in force).
// One field can be typed in at a time.
struct TypedValue {
    ImGuiID control = 0;  // 0: none
    int frame = 0;        // the last frame it was typed in
    double value[3] = {};
};
TypedValue typed;

// After the ImGui call for `control` that edits `count` numbers from `before` to `value`
// (`changed` as the call returned): while it is typed in, puts `before` back in `value` and
// returns false; in the frame it is left, puts the typed numbers in `value` and returns
// whether they differ from `before`; otherwise returns `changed`.
bool apply_when_left(ImGuiID control, bool changed, double* value, const double* before,
                     int count) {
    const ImGuiContext& g = *ImGui::GetCurrentContext();
    const bool typing =
        g.TempInputId != 0 && g.ActiveId == g.TempInputId && g.LastItemData.ID == g.ActiveId;
    const int frame = ImGui::GetFrameCount();
    if (typing) {
        if (typed.control != control || typed.frame != frame - 1) {
            typed.control = control;
            std::copy(before, before + count, typed.value);
        }
        typed.frame = frame;
        if (changed) std::copy(value, value + count, typed.value);
        std::copy(before, before + count, value);
        return false;
    }
    if (typed.control != control || typed.frame != frame - 1) return changed;
    typed.control = 0;
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) {
        std::copy(before, before + count, value);
        return false;
    }
    // The frame that leaves the field may also change it (a last keystroke with the Enter).
    if (!changed) std::copy(typed.value, typed.value + count, value);
    return !std::equal(value, value + count, before);
}

}  // namespace

void edit(DemoState& state, const SceneEdit& change) {
    last_edit.answer(scene_edit_name(change), state.edit({change}));
}

void answer_edit(std::string_view control, const std::optional<std::string>& error) {
    last_edit.answer(control, error);
}

void refusal_below(std::string_view control) {
    const std::string& refusal = last_edit.refusal_under(control);
    if (refusal.empty()) return;
    ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", refusal.c_str());
    // A new refusal cut off by the panel's foot is scrolled whole into sight, once.
    if (last_edit.newly_refused() &&
        ImGui::GetItemRectMax().y > ImGui::GetWindowDrawList()->GetClipRectMax().y)
        ImGui::SetScrollHereY(1.0f);
}

bool slider_log(const char* label, double& value, double low, double high,
                std::string_view suffix) {
    // Dear ImGui rounds a dragged value to the format and reads the smallest value a
    // logarithmic slider reaches from its decimals: the format resolves `low` as well.
    const std::string format =
        significant_format(value, slider_digits, decimals_to_reach(low), suffix);
    const ImGuiID control = ImGui::GetID(label);
    const double before = value;
    float v = static_cast<float>(value);
    const bool changed =
        ImGui::SliderFloat(label, &v, static_cast<float>(low), static_cast<float>(high),
                           format.c_str(), ImGuiSliderFlags_Logarithmic);
    if (changed) value = v;
    return apply_when_left(control, changed, &value, &before, 1);
}

bool slider(const char* label, double& value, double low, double high, const char* format) {
    const ImGuiID control = ImGui::GetID(label);
    const double before = value;
    const bool changed =
        ImGui::SliderScalar(label, ImGuiDataType_Double, &value, &low, &high, format);
    return apply_when_left(control, changed, &value, &before, 1);
}

bool drag3(const char* label, Vec3d& v, double speed) {
    const ImGuiID control = ImGui::GetID(label);
    const Vec3d before = v;
    // One format for the three numbers: "%g" gives each its own significant digits, so a
    // small one beside a large one never reads as a rounded zero.
    const bool changed = ImGui::DragScalarN(label, ImGuiDataType_Double, v.data(), 3,
                                            static_cast<float>(speed), nullptr, nullptr, "%.3g");
    return apply_when_left(control, changed, v.data(), before.data(), 3);
}

}  // namespace weft::app
