// The panel's number controls with a value typed in (Ctrl+click): Dear ImGui, driven headless
// with a synthetic mouse and keyboard, applies the field at every keystroke; the controls
// apply it once, when the field is left. Escape leaves the value in force.
#include <gtest/gtest.h>
#include <imgui.h>

#include <string>
#include <vector>

#include "app/panel_widgets.h"

namespace weft::app {
namespace {

constexpr int enter_key = 13, escape_key = 27;

// A Dear ImGui context with no renderer: its font atlas built, frames begun and ended, the
// control drawn in a window filling the screen.
class HeadlessPanel {
  public:
    HeadlessPanel() {
        context_ = ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;
        io.DisplaySize = ImVec2(480.0f, 320.0f);
        io.DeltaTime = 1.0f / 60.0f;
        io.KeyMap[ImGuiKey_Enter] = enter_key;
        io.KeyMap[ImGuiKey_Escape] = escape_key;
        unsigned char* pixels = nullptr;
        int width = 0, height = 0;
        io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
    }
    ~HeadlessPanel() { ImGui::DestroyContext(context_); }
    HeadlessPanel(const HeadlessPanel&) = delete;
    HeadlessPanel& operator=(const HeadlessPanel&) = delete;

    // One frame with `control` drawn; what it returned. The mouse rests near the control's
    // left end (once its place is known): on a line of three numbers, on the first.
    template <class Control>
    bool frame(Control control) {
        ImGuiIO& io = ImGui::GetIO();
        io.MousePos = elsewhere_ ? ImVec2(io.DisplaySize.x - 5.0f, io.DisplaySize.y - 5.0f) : on_;
        ImGui::NewFrame();
        ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f));
        ImGui::SetNextWindowSize(io.DisplaySize);
        ImGui::Begin("panel");
        const bool answer = control();
        const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
        on_ = ImVec2(min.x + 10.0f, 0.5f * (min.y + max.y));
        ImGui::End();
        ImGui::Render();
        // What was pressed for one frame is let go.
        io.MouseDown[0] = false;
        io.KeyCtrl = false;
        io.KeysDown[enter_key] = io.KeysDown[escape_key] = false;
        return answer;
    }
    void ctrl_click() {
        ImGui::GetIO().KeyCtrl = true;
        ImGui::GetIO().MouseDown[0] = true;
    }
    void type(const std::string& text) {
        for (char c : text) ImGui::GetIO().AddInputCharacter(static_cast<unsigned>(c));
    }
    void press(int key) { ImGui::GetIO().KeysDown[key] = true; }
    // A click on the empty part of the panel, far from the control.
    void click_elsewhere() {
        elsewhere_ = true;
        ImGui::GetIO().MouseDown[0] = true;
    }

  private:
    ImGuiContext* context_ = nullptr;
    ImVec2 on_{-1.0f, -1.0f};
    bool elsewhere_ = false;
};

constexpr int click_elsewhere = -1;

// Types `text` into the control one character a frame after a Ctrl+click, then leaves it
// with `key` (or a click elsewhere); every value the control reported as an edit, in order.
template <class Value, class Control>
std::vector<Value> typed_edits(Value& value, Control control, const std::string& text, int key) {
    HeadlessPanel panel;
    std::vector<Value> edits;
    auto frame = [&] {
        if (panel.frame([&] { return control(value); })) edits.push_back(value);
    };
    frame();  // where the control is
    frame();  // the mouse on it
    panel.ctrl_click();
    frame();
    frame();
    for (char c : text) {
        panel.type(std::string(1, c));
        frame();
    }
    if (key == click_elsewhere)
        panel.click_elsewhere();
    else
        panel.press(key);
    frame();
    frame();
    frame();
    return edits;
}

TEST(TypedValues, ALogSliderAppliesTheTypedValueOnceOnEnter) {
    double stiffness = 800.0;
    const auto edits = typed_edits(
        stiffness, [](double& v) { return slider_log("stiffness (N/m)", v, 1.0, 1e5); }, "25000",
        enter_key);
    ASSERT_EQ(edits.size(), 1u);  // not 2, 25, 250, 2500 on the way
    EXPECT_EQ(edits[0], 25000.0);
    EXPECT_EQ(stiffness, 25000.0);
}

// A value past the slider's range is what the edit's check is for: it comes through whole,
// once, to be refused.
TEST(TypedValues, AValuePastTheRangeComesThroughWholeOnce) {
    double fov = 50.0;
    const auto edits = typed_edits(
        fov, [](double& v) { return slider("field of view (deg)", v, 10.0, 120.0, "%.3g"); },
        "1e308", enter_key);
    ASSERT_EQ(edits.size(), 1u);  // not 1, 1e3 and 1e30 on the way
    EXPECT_EQ(edits[0], 1e308);
}

TEST(TypedValues, AClickElsewhereAppliesAsEnterDoes) {
    double fov = 50.0;
    const auto edits = typed_edits(
        fov, [](double& v) { return slider("field of view (deg)", v, 10.0, 120.0, "%.3g"); }, "75",
        click_elsewhere);
    ASSERT_EQ(edits.size(), 1u);
    EXPECT_EQ(edits[0], 75.0);
}

TEST(TypedValues, EscapeLeavesTheValueInForce) {
    double stiffness = 800.0;
    const auto edits = typed_edits(
        stiffness, [](double& v) { return slider_log("stiffness (N/m)", v, 1.0, 1e5); }, "25000",
        escape_key);
    EXPECT_TRUE(edits.empty());
    EXPECT_EQ(stiffness, 800.0);
}

// Three numbers on a line: the one typed in comes through once, the others as they were.
TEST(TypedValues, OneOfThreeNumbersAppliesOnce) {
    Vec3d gravity = {0.0, -9.81, 0.0};
    const auto edits = typed_edits(
        gravity, [](Vec3d& v) { return drag3("gravity (m/s2)", v, 0.05); }, "-1.5", enter_key);
    ASSERT_EQ(edits.size(), 1u);
    EXPECT_EQ(edits[0][0], -1.5);
    EXPECT_EQ(edits[0][1], -9.81);
    EXPECT_EQ(edits[0][2], 0.0);
}

}  // namespace
}  // namespace weft::app
