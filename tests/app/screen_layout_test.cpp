// Where the status lines may draw: beside the panel, never under it (issue 18, item 5).
// Truth: the strips left and right of the panel, worked out by hand for each case.
#include <gtest/gtest.h>

#include "app/screen_layout.h"

namespace weft::app {
namespace {

constexpr ScreenRect window{0, 0, 800, 600};

void expect_rect(const ScreenRect& got, const ScreenRect& want) {
    EXPECT_EQ(got.x, want.x);
    EXPECT_EQ(got.y, want.y);
    EXPECT_EQ(got.width, want.width);
    EXPECT_EQ(got.height, want.height);
}

TEST(ScreenLayout, APanelOnTheLeftLeavesTheStripRightOfIt) {
    // The panel as it opens: at (10, 10), 390 wide, 580 tall.
    expect_rect(area_beside_panel(window, {10, 10, 390, 580}, 240), {400, 0, 400, 600});
}

TEST(ScreenLayout, APanelDraggedRightLeavesTheWiderStripLeftOfIt) {
    expect_rect(area_beside_panel(window, {500, 40, 280, 300}, 240), {0, 0, 500, 600});
}

TEST(ScreenLayout, APanelPartlyOffTheWindowTakesOnlyWhatIsInside) {
    expect_rect(area_beside_panel(window, {-200, 0, 300, 600}, 240), {100, 0, 700, 600});
}

TEST(ScreenLayout, TooNarrowAStripFallsBackToTheWholeWindow) {
    // 150 px left, 160 px right: too cramped to read, so the text goes over the panel.
    expect_rect(area_beside_panel(window, {150, 0, 490, 600}, 240), window);
}

}  // namespace
}  // namespace weft::app
