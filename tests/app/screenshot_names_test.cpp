// Screenshots never overwrite an earlier one.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "app/screenshot_names.h"

namespace weft::app {
namespace {

TEST(ScreenshotNames, TheNextNameIsTheFirstFreeOne) {
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / "weft-screenshot-names-test";
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    EXPECT_EQ(std::filesystem::path(next_screenshot_path(folder.string())).filename(),
              "weft-screenshot-0001.png");
    std::ofstream(folder / "weft-screenshot-0001.png") << "x";
    std::ofstream(folder / "weft-screenshot-0002.png") << "x";
    EXPECT_EQ(std::filesystem::path(next_screenshot_path(folder.string())).filename(),
              "weft-screenshot-0003.png");
    std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace weft::app
