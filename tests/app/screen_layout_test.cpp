// How the window is shared between the panel and the view: the view lies beside the panel,
// never under it, at common window sizes and at the limits of the rule. Truth: the rule's
// arithmetic worked out by hand for each case.
#include <gtest/gtest.h>

#include "app/screen_layout.h"

namespace weft::app {
namespace {

constexpr float title_height = 19.0f;

void expect_rect(const ScreenRect& got, const ScreenRect& want) {
    EXPECT_EQ(got.x, want.x);
    EXPECT_EQ(got.y, want.y);
    EXPECT_EQ(got.width, want.width);
    EXPECT_EQ(got.height, want.height);
}

void expect_layout(float width, float height, bool folded, const ScreenRect& panel,
                   const ScreenRect& view) {
    const WindowLayout layout = lay_out_window(width, height, folded, title_height);
    expect_rect(layout.panel, panel);
    expect_rect(layout.view, view);
}

TEST(ScreenLayout, At800x600ThePanelTakesItsNarrowestWidthAndTheViewTheRest) {
    // 30 % of 800 is 240, below the narrowest panel: 300 px.
    expect_layout(800, 600, false, {0, 0, 300, 600}, {300, 0, 500, 600});
}

TEST(ScreenLayout, At1280x720ThePanelTakesThirtyPercentInWholePixels) {
    // 30 % of 1280 is 384.
    expect_layout(1280, 720, false, {0, 0, 384, 720}, {384, 0, 896, 720});
}

TEST(ScreenLayout, AWideWindowGivesThePanelNoMoreThanItsWidest) {
    expect_layout(2560, 1440, false, {0, 0, 400, 1440}, {400, 0, 2160, 1440});
}

TEST(ScreenLayout, ANarrowWindowKeepsHalfForTheView) {
    // 300 px would leave the cloth 201 of 501: the panel gives way to half.
    expect_layout(501, 400, false, {0, 0, 250, 400}, {250, 0, 251, 400});
}

TEST(ScreenLayout, TheViewNeverOverlapsTheOpenPanel) {
    for (float width : {320.0f, 640.0f, 800.0f, 1024.0f, 1280.0f, 1333.0f, 1920.0f}) {
        const WindowLayout layout = lay_out_window(width, 600, false, title_height);
        EXPECT_EQ(layout.view.x, layout.panel.right()) << width;
        EXPECT_EQ(layout.view.right(), width) << width;
        EXPECT_GE(layout.view.width, 0.5f * width) << width;
        EXPECT_EQ(layout.panel.width, static_cast<float>(static_cast<int>(layout.panel.width)));
    }
}

TEST(ScreenLayout, AFoldedPanelIsAStripAcrossTheTopAndTheViewTakesTheWindowBelowIt) {
    expect_layout(800, 600, true, {0, 0, 300, 19}, {0, 19, 800, 581});
}

}  // namespace
}  // namespace weft::app
