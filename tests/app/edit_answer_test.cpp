// Where and how long the panel says an edit was refused: under the control that made it, until
// the next edit; in words without the command line's lead. Truth: the loader's message for a
// negative stiffness, copied from `weft --set`.
#include <gtest/gtest.h>

#include "app/edit_answer.h"

namespace weft::app {
namespace {

const std::string negative_stiffness =
    "error: --set springs.structural.stiffness: springs.structural.stiffness must be >= 0, "
    "got -5";

TEST(EditAnswer, ARefusalIsSaidUnderTheControlThatMadeTheEditOnly) {
    LastEdit last;
    last.answer("springs.structural.stiffness", negative_stiffness);
    EXPECT_EQ(last.refusal_under("springs.structural.stiffness"),
              "refused: springs.structural.stiffness must be >= 0, got -5");
    EXPECT_EQ(last.refusal_under("springs.shear.stiffness"), "");
}

TEST(EditAnswer, ARefusalStaysUntilTheNextEdit) {
    LastEdit last;
    last.answer("springs.structural.stiffness", negative_stiffness);
    EXPECT_NE(last.refusal_under("springs.structural.stiffness"), "");  // frame after frame
    EXPECT_NE(last.refusal_under("springs.structural.stiffness"), "");
    last.answer("forces.air_drag", std::nullopt);
    EXPECT_EQ(last.refusal_under("springs.structural.stiffness"), "");
    EXPECT_EQ(last.refusal_under("forces.air_drag"), "");
}

TEST(EditAnswer, ATakenEditOfTheSameControlClearsItsRefusal) {
    LastEdit last;
    last.answer("cloth.particle_mass", "error: --set cloth.particle_mass: must be > 0, got 0");
    last.answer("cloth.particle_mass", std::nullopt);
    EXPECT_EQ(last.refusal_under("cloth.particle_mass"), "");
}

// The panel scrolls a refusal into sight the first frame it is drawn and never again, so a
// user who scrolls away from it is not pulled back every frame.
TEST(EditAnswer, ANewRefusalIsBroughtIntoSightOnceAndATakenEditNever) {
    LastEdit last;
    EXPECT_FALSE(last.newly_refused());  // nothing edited yet
    last.answer("springs.structural.stiffness", negative_stiffness);
    EXPECT_TRUE(last.newly_refused());
    EXPECT_FALSE(last.newly_refused());  // the next frames: shown already
    EXPECT_NE(last.refusal_under("springs.structural.stiffness"), "");  // and still said
    last.answer("springs.structural.stiffness", negative_stiffness);    // refused again
    EXPECT_TRUE(last.newly_refused());
    last.answer("forces.air_drag", std::nullopt);
    EXPECT_FALSE(last.newly_refused());
    last.answer("cloth.particle_mass", "error: --set cloth.particle_mass: must be > 0, got 0");
    last.answer("cloth.particle_mass", std::nullopt);  // taken before a frame drew the refusal
    EXPECT_FALSE(last.newly_refused());
}

TEST(EditAnswer, AMessageWithoutTheCommandLinesLeadIsKeptWhole) {
    EXPECT_EQ(refusal_text("grab radius must be in (0, 10] m, got 20"),
              "refused: grab radius must be in (0, 10] m, got 20");
    EXPECT_EQ(refusal_text("error: panel: colliders[0].restitution must be in [0, 1], got 1.5"),
              "refused: panel: colliders[0].restitution must be in [0, 1], got 1.5");
}

TEST(EditAnswer, ARefusalIsInSignsThePanelsFontDraws) {
    EXPECT_EQ(refusal_text("error: --set cloth.rows: cloth.rows \u00d7 cloth.cols = 10000000000 "
                           "particles, more than the limit of 4194304"),
              "refused: cloth.rows x cloth.cols = 10000000000 particles, more than the limit of "
              "4194304");
}

}  // namespace
}  // namespace weft::app
