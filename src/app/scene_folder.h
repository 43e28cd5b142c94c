// Where the shipped scenes (assets/scenes) are: beside an installed program, or in the source
// tree a build-tree program was built from. SDL-free, shared by weft and weft-bench, tested.
#pragma once

#include <string>

namespace weft::app {

// The running program's own path (Linux: /proc/self/exe); empty if it cannot be read.
std::string running_executable_path();

// The scenes folder for the program at `executable_path`: `installed_relative` (the install's
// data folder as seen from its bin folder, "../share/weft/scenes") taken from the program's
// folder when it holds hanging_sheet.toml — an installed weft, wherever its prefix was moved
// — else `source_scenes` (the source tree's assets/scenes, for a program in the build tree).
std::string shipped_scenes_folder(const std::string& executable_path,
                                  const std::string& installed_relative,
                                  const std::string& source_scenes);

// shipped_scenes_folder for this program, with the folders CMake configured
// (WEFT_INSTALLED_SCENES, WEFT_SOURCE_SCENES).
std::string shipped_scenes_folder();

// The scene weft opens when given none: hanging_sheet.toml in shipped_scenes_folder().
std::string default_scene_path();

}  // namespace weft::app
