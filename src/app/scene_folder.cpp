#include "app/scene_folder.h"

#include <filesystem>
#include <system_error>

namespace weft::app {

std::string running_executable_path() {
    std::error_code error;
    const std::filesystem::path path = std::filesystem::read_symlink("/proc/self/exe", error);
    return error ? std::string() : path.string();
}

std::string shipped_scenes_folder(const std::string& executable_path,
                                  const std::string& installed_relative,
                                  const std::string& source_scenes) {
    if (!executable_path.empty()) {
        const std::filesystem::path installed =
            std::filesystem::path(executable_path).parent_path() / installed_relative;
        std::error_code error;
        if (std::filesystem::is_regular_file(installed / "hanging_sheet.toml", error))
            return installed.lexically_normal().string();
    }
    return source_scenes;
}

std::string shipped_scenes_folder() {
    return shipped_scenes_folder(running_executable_path(), WEFT_INSTALLED_SCENES,
                                 WEFT_SOURCE_SCENES);
}

std::string default_scene_path() {
    return (std::filesystem::path(shipped_scenes_folder()) / "hanging_sheet.toml").string();
}

}  // namespace weft::app
