// The window's captures (captures_folder.h, frame_capture.h): one folder chosen from the
// environment, never the working directory; F9's frames one per 1/30 s of simulated time,
// none while paused, numbered on across a restart.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "app/captures_folder.h"
#include "app/frame_capture.h"
#include "app/screenshot_names.h"

namespace weft::app {
namespace {

namespace fs = std::filesystem;

fs::path scratch_folder(const char* name) {
    const fs::path folder = fs::temp_directory_path() / (std::string("weft-test-") + name);
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

int png_count(const fs::path& folder) {
    int count = 0;
    for (const auto& entry : fs::directory_iterator(folder))
        count += entry.path().extension() == ".png";
    return count;
}

TEST(CapturesFolder, TheVariableThenHomeThenTmp) {
    EXPECT_EQ(captures_folder_for("/data/shots", "/home/ada"), "/data/shots");
    EXPECT_EQ(captures_folder_for("", "/home/ada"), "/home/ada/weft-captures");
    EXPECT_EQ(captures_folder_for(nullptr, "/home/ada"), "/home/ada/weft-captures");
    EXPECT_EQ(captures_folder_for(nullptr, nullptr), "/tmp/weft-captures");
    EXPECT_EQ(captures_folder_for(nullptr, ""), "/tmp/weft-captures");
}

TEST(CapturesFolder, IsMadeOrRefusedWithTheReason) {
    const fs::path folder = scratch_folder("captures");
    std::string error;
    EXPECT_TRUE(make_captures_folder((folder / "a" / "b").string(), error)) << error;
    EXPECT_TRUE(fs::is_directory(folder / "a" / "b"));
    std::ofstream(folder / "file") << "x";
    EXPECT_FALSE(make_captures_folder((folder / "file").string(), error));
    EXPECT_NE(error.find("cannot make the captures folder"), std::string::npos) << error;
    EXPECT_EQ(next_free_folder(folder.string(), "a"), (folder / "a-0001").string());
    fs::create_directories(folder / "a-0001");
    EXPECT_EQ(next_free_folder(folder.string(), "a"), (folder / "a-0002").string());
}

TEST(FrameCapture, OnePerThirtiethOfASimulatedSecondNoneWhilePausedNumberedOnAfterARestart) {
    const fs::path folder = scratch_folder("frames");
    raster::Framebuffer image(8, 6);
    image.clear({10, 20, 30, 255});
    const double dt = 1.0 / 600.0;  // s
    FrameCapture capture(folder.string(), 2.0);
    std::string error;
    double time = 2.0;  // s
    // One simulated second in window frames of 1/60 s: frames 0 to 30.
    for (int frame = 0; frame <= 60; ++frame) {
        ASSERT_TRUE(capture.write_due(image, time, dt, error)) << error;
        time += 10 * dt;
    }
    EXPECT_EQ(capture.frames_written(), 31u);
    // Paused: the time stands still, nothing is written.
    for (int frame = 0; frame < 10; ++frame) ASSERT_TRUE(capture.write_due(image, time, dt, error));
    EXPECT_EQ(capture.frames_written(), 31u);
    // Restarted at t = 0: the next frame at once, numbered on.
    ASSERT_TRUE(capture.write_due(image, 0.0, dt, error));
    EXPECT_EQ(capture.frames_written(), 32u);
    EXPECT_EQ(png_count(folder), 32);
    EXPECT_TRUE(fs::exists(folder / "frame-00000.png"));
    EXPECT_TRUE(fs::exists(folder / "frame-00031.png"));
    // A frame that cannot be written says so.
    FrameCapture nowhere((folder / "missing").string(), 0.0);
    EXPECT_FALSE(nowhere.write_due(image, 0.0, dt, error));
    EXPECT_FALSE(error.empty());
}

}  // namespace
}  // namespace weft::app
