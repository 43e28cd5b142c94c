// The window's state file (app/window_state_file.h): what a driving script reads back is the
// running state, every digit of simulated time, and a rewrite replaces it whole.
#include "app/window_state_file.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "shipped_demo.h"

namespace weft::app {
namespace {

std::string value_of(const std::string& text, const std::string& key) {
    std::istringstream lines(text);
    std::string name, value;
    while (lines >> name >> value)
        if (name == key) return value;
    return "";
}

TEST(WindowStateFile, SaysTheFramesStepsTimeAndHandOfTheMainRun) {
    DemoState state = demo();
    state.step(7);
    const std::string text = window_state_text(42, state);
    EXPECT_EQ(value_of(text, "frames"), "42");
    EXPECT_EQ(value_of(text, "steps"), "7");
    EXPECT_EQ(std::stod(value_of(text, "time")), state.simulation().time());  // every digit
    EXPECT_EQ(value_of(text, "paused"), "0");
    EXPECT_EQ(value_of(text, "held"), "0");
    state.toggle_pause();
    EXPECT_EQ(value_of(window_state_text(43, state), "paused"), "1");
}

TEST(WindowStateFile, ARewriteReplacesTheFileWhole) {
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() / "weft_window_state_test.txt";
    DemoState state = demo();
    ASSERT_TRUE(write_window_state(path.string(), 1, state));
    state.step(3);
    ASSERT_TRUE(write_window_state(path.string(), 2, state));
    std::ifstream file(path);
    std::stringstream text;
    text << file.rdbuf();
    EXPECT_EQ(text.str(), window_state_text(2, state));
    EXPECT_FALSE(std::filesystem::exists(path.string() + ".tmp"));
    std::filesystem::remove(path);
    EXPECT_FALSE(write_window_state("/nonexistent-folder/state", 1, state));
}

}  // namespace
}  // namespace weft::app
