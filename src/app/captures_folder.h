// Where the window saves what it makes: screenshots (F12), the cloth as OBJ (O), session
// recordings (F5) and frame captures (F9). One folder, and never the folder weft was started
// from, which may be a source checkout.
#pragma once

#include <string>

namespace weft::app {

// $WEFT_CAPTURES when it is set and not empty, else ~/weft-captures ($HOME), else
// /tmp/weft-captures. The arguments are those variables' values, or null when unset.
std::string captures_folder_for(const char* weft_captures, const char* home);

// The same from this process's environment.
std::string captures_folder();

// Makes the folder (and its parents) unless it exists; false, with the reason, if it cannot.
bool make_captures_folder(const std::string& folder, std::string& error);

}  // namespace weft::app
