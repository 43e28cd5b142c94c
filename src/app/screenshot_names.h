// Screenshot file names that never overwrite an earlier one.
#pragma once

#include <string>

namespace weft::app {

// The first of DIRECTORY/weft-screenshot-0001.png, -0002.png, ... that does not exist yet.
std::string next_screenshot_path(const std::string& directory);

}  // namespace weft::app
