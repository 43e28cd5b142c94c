// File names that never overwrite an earlier one: screenshots, session recordings.
#pragma once

#include <string>

namespace weft::app {

// The first of DIRECTORY/PREFIX-0001.EXTENSION, -0002, ... that does not exist yet.
std::string next_free_path(const std::string& directory, const std::string& prefix,
                           const std::string& extension);

// The first of DIRECTORY/PREFIX-0001, -0002, ... that does not exist yet: a new folder's name.
std::string next_free_folder(const std::string& directory, const std::string& prefix);

// next_free_path(directory, "weft-screenshot", "png").
std::string next_screenshot_path(const std::string& directory);

}  // namespace weft::app
