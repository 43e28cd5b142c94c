// Side by side's columns share the view beside the panel, not the window (split across the
// whole window, most of the main run's column sat under the panel). Truth: the 800 x 600
// window's layout (a 300 px panel, a 500 px view) worked out by hand.
#include <gtest/gtest.h>

#include "app/screen_layout.h"
#include "app/side_by_side.h"

namespace weft::app {
namespace {

const Columns two_runs_at_800x600 = Columns::split(lay_out_window(800, 600, false, 19).view, 2);

TEST(SideBySide, TwoRunsSplitTheViewBesideThePanelInHalves) {
    EXPECT_EQ(two_runs_at_800x600.width, 250);
    EXPECT_EQ(two_runs_at_800x600.height, 600);
    EXPECT_EQ(two_runs_at_800x600.right_of(0), 550.0f);
    EXPECT_EQ(two_runs_at_800x600.right_of(1), 800.0f);
}

TEST(SideBySide, TheCursorActsOnTheColumnItIsOverInThatColumnsCoordinates) {
    EXPECT_EQ(two_runs_at_800x600.column_at(301.0f), 0);
    EXPECT_EQ(two_runs_at_800x600.column_at(549.0f), 0);
    EXPECT_EQ(two_runs_at_800x600.column_at(551.0f), 1);
    const glm::vec2 in_copy = two_runs_at_800x600.local({675.0f, 300.0f}, 1);
    EXPECT_EQ(in_copy.x, 125.0f);  // the copy's column centre
    EXPECT_EQ(in_copy.y, 300.0f);
}

TEST(SideBySide, ACursorOverThePanelActsOnTheFirstColumn) {
    EXPECT_EQ(two_runs_at_800x600.column_at(100.0f), 0);
    EXPECT_EQ(two_runs_at_800x600.local({100.0f, 50.0f}, 0).x, -200.0f);
}

TEST(SideBySide, AFoldedPanelGivesTheColumnsTheWindowBelowItsStrip) {
    const Columns columns = Columns::split(lay_out_window(800, 600, true, 19).view, 2);
    EXPECT_EQ(columns.width, 400);
    EXPECT_EQ(columns.height, 581);
    EXPECT_EQ(columns.local({600.0f, 319.0f}, 1).y, 300.0f);
}

}  // namespace
}  // namespace weft::app
