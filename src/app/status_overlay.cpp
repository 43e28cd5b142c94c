#include "app/status_overlay.h"

#include <imgui.h>
#include <algorithm>

#include "app/status_text.h"

namespace weft::app {
namespace {

const ImVec4 recording_red(1.0f, 0.25f, 0.25f, 1.0f);
const ImVec4 warning_amber(1.0f, 0.8f, 0.3f, 1.0f);

ImVec4 tone_colour(Tone tone) {
    switch (tone) {
        case Tone::success:
            return ImVec4(0.45f, 0.9f, 0.45f, 1.0f);
        case Tone::problem:
            return ImVec4(1.0f, 0.5f, 0.3f, 1.0f);
        case Tone::info:
            break;
    }
    return ImGui::GetStyleColorVec4(ImGuiCol_Text);
}

}  // namespace

void draw_status_overlay(const DemoState& state, double now_seconds, const ScreenRect& area) {
    const bool recording = state.recording.has_value();
    const bool show_message = now_seconds < state.message_until && !state.message.empty();
    const bool capturing = state.frame_capture.has_value();
    if (!show_message && !state.statistics.behind && !state.paused && !recording && !capturing)
        return;
    // The window is as wide as the area allows, less a margin, and the text wraps inside it: a
    // divergence message names particles and numbers and is longer than most windows are wide.
    constexpr float margin = 10.0f;
    const float width = std::max(1.0f, area.width - 2.0f * margin);
    ImGui::SetNextWindowPos(ImVec2(area.x + 0.5f * area.width, area.y + area.height - margin),
                            ImGuiCond_Always, ImVec2(0.5f, 1.0f));
    ImGui::SetNextWindowSizeConstraints(ImVec2(0.0f, 0.0f), ImVec2(width, area.height));
    ImGui::SetNextWindowBgAlpha(0.6f);
    ImGui::Begin("status", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                     ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoFocusOnAppearing);
    ImGui::PushTextWrapPos(width - ImGui::GetStyle().WindowPadding.x);
    if (recording) {
        ImGui::TextColored(recording_red, "REC");
        ImGui::SameLine();
        ImGui::TextUnformatted("recording the session (F5 stops and saves it)");
    }
    if (capturing) {
        ImGui::TextColored(recording_red, "REC");
        ImGui::SameLine();
        ImGui::Text("capturing frames: %llu so far (F9 stops)",
                    state.frame_capture->frames_written());
    }
    if (state.paused) ImGui::TextUnformatted("paused (P resumes, N steps)");
    if (state.statistics.behind)
        ImGui::TextColored(warning_amber,
                           "falling behind real time: simulating slower than the clock");
    if (show_message)
        ImGui::TextColored(tone_colour(state.message_tone), "%s",
                           ascii_text(state.message).c_str());
    ImGui::PopTextWrapPos();
    ImGui::End();
}

void draw_hand_hint(const DemoState& state, const ScreenRect& area) {
    if (!state.hand_hint || state.replaying) return;
    constexpr float margin = 10.0f;
    ImGui::SetNextWindowPos(ImVec2(area.x + 0.5f * area.width, area.y + margin), ImGuiCond_Always,
                            ImVec2(0.5f, 0.0f));
    ImGui::SetNextWindowSizeConstraints(
        ImVec2(0.0f, 0.0f), ImVec2(std::max(1.0f, area.width - 2.0f * margin), area.height));
    ImGui::SetNextWindowBgAlpha(0.6f);
    ImGui::Begin("hand hint", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                     ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoFocusOnAppearing);
    ImGui::PushTextWrapPos(std::max(1.0f, area.width - 2.0f * margin) -
                           ImGui::GetStyle().WindowPadding.x);
    ImGui::TextUnformatted("space or left-drag: pull, right-drag: cut, T: pin, H: help");
    ImGui::PopTextWrapPos();
    ImGui::End();
}

}  // namespace weft::app
