#include "app/screenshot_names.h"

#include <cstdio>
#include <filesystem>

namespace weft::app {

std::string next_screenshot_path(const std::string& directory) {
    for (int number = 1;; ++number) {
        char name[64];
        std::snprintf(name, sizeof name, "weft-screenshot-%04d.png", number);
        const std::filesystem::path path = std::filesystem::path(directory) / name;
        if (!std::filesystem::exists(path)) return path.string();
    }
}

}  // namespace weft::app
