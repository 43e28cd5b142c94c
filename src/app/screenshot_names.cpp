#include "app/screenshot_names.h"

#include <cstdio>
#include <filesystem>

namespace weft::app {

std::string next_free_path(const std::string& directory, const std::string& prefix,
                           const std::string& extension) {
    for (int number = 1;; ++number) {
        char suffix[32];
        std::snprintf(suffix, sizeof suffix, "-%04d.", number);
        const std::filesystem::path path =
            std::filesystem::path(directory) / (prefix + suffix + extension);
        if (!std::filesystem::exists(path)) return path.string();
    }
}

std::string next_free_folder(const std::string& directory, const std::string& prefix) {
    for (int number = 1;; ++number) {
        char suffix[32];
        std::snprintf(suffix, sizeof suffix, "-%04d", number);
        const std::filesystem::path path = std::filesystem::path(directory) / (prefix + suffix);
        if (!std::filesystem::exists(path)) return path.string();
    }
}

std::string next_screenshot_path(const std::string& directory) {
    return next_free_path(directory, "weft-screenshot", "png");
}

}  // namespace weft::app
