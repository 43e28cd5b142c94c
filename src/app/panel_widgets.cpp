#include "app/panel_widgets.h"

#include <imgui.h>
#include <cstdio>

#include "app/edit_answer.h"
#include "app/number_format.h"

namespace weft::app {
namespace {

// The last edit and, if it was refused, why: said under the control that made it.
LastEdit last_edit;

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
    float v = static_cast<float>(value);
    if (!ImGui::SliderFloat(label, &v, static_cast<float>(low), static_cast<float>(high),
                            format.c_str(), ImGuiSliderFlags_Logarithmic))
        return false;
    value = v;
    return true;
}

bool slider(const char* label, double& value, double low, double high, const char* format) {
    return ImGui::SliderScalar(label, ImGuiDataType_Double, &value, &low, &high, format);
}

bool drag3(const char* label, Vec3d& v, double speed) {
    // One format for the three numbers: "%g" gives each its own significant digits, so a
    // small one beside a large one never reads as a rounded zero.
    return ImGui::DragScalarN(label, ImGuiDataType_Double, v.data(), 3, static_cast<float>(speed),
                              nullptr, nullptr, "%.3g");
}

}  // namespace weft::app
