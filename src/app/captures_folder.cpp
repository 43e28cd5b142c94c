#include "app/captures_folder.h"

#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace weft::app {

std::string captures_folder_for(const char* weft_captures, const char* home) {
    if (weft_captures && *weft_captures) return weft_captures;
    if (home && *home) return (std::filesystem::path(home) / "weft-captures").string();
    return "/tmp/weft-captures";
}

std::string captures_folder() {
    return captures_folder_for(std::getenv("WEFT_CAPTURES"), std::getenv("HOME"));
}

bool make_captures_folder(const std::string& folder, std::string& error) {
    std::error_code failure;
    std::filesystem::create_directories(folder, failure);
    if (!failure && std::filesystem::is_directory(folder, failure)) return true;
    error = folder + ": cannot make the captures folder" +
            (failure ? ": " + failure.message() : std::string(": not a folder"));
    return false;
}

}  // namespace weft::app
