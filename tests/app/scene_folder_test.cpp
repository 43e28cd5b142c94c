// Where weft looks for its scenes: beside an installed program first, else the source tree.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "app/scene_folder.h"

namespace weft::app {
namespace {

namespace fs = std::filesystem;

TEST(SceneFolder, AnInstalledProgramReadsTheScenesBesideIt) {
    const fs::path prefix = fs::temp_directory_path() / "weft-shipped-scenes-test";
    fs::remove_all(prefix);
    fs::create_directories(prefix / "bin");
    fs::create_directories(prefix / "share/weft/scenes");
    const std::string program = (prefix / "bin/weft").string();
    // No default scene there yet: the source tree's folder.
    EXPECT_EQ(shipped_scenes_folder(program, "../share/weft/scenes", "/src/assets/scenes"),
              "/src/assets/scenes");
    std::ofstream(prefix / "share/weft/scenes/hanging_sheet.toml") << "name = \"x\"\n";
    EXPECT_EQ(shipped_scenes_folder(program, "../share/weft/scenes", "/src/assets/scenes"),
              (prefix / "share/weft/scenes").string());
    fs::remove_all(prefix);
}

TEST(SceneFolder, ThisBuildsDefaultSceneExists) {
    EXPECT_FALSE(running_executable_path().empty());
    EXPECT_TRUE(fs::is_regular_file(default_scene_path())) << default_scene_path();
}

}  // namespace
}  // namespace weft::app
