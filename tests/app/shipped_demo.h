// Test support: a DemoState on one of the shipped scenes (assets/scenes), as the window
// opens it.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "app/demo_state.h"
#include "sim/scene_io/scene_loader.h"

namespace weft::app {

inline const std::string shipped_scenes_dir = std::string(WEFT_SOURCE_DIR) + "/assets/scenes";

inline DemoState demo(const std::string& scene_file = "hanging_sheet.toml") {
    const std::string path = shipped_scenes_dir + "/" + scene_file;
    SceneLoadResult loaded = load_scene_file(path);
    EXPECT_TRUE(loaded.ok()) << (loaded.error ? loaded.error->message() : "");
    return DemoState(path, {}, *loaded.scene);
}

}  // namespace weft::app
