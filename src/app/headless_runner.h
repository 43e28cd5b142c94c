// Runs a scene without a window: the --headless mode, and the stand-in for the demo until
// the window exists. Returns the process exit status (0 done, 2 bad input, 3 diverged).
#pragma once

#include "app/command_line.h"

namespace weft {

inline constexpr int exit_ok = 0;
inline constexpr int exit_bad_input = 2;
inline constexpr int exit_diverged = 3;

// weft --headless SCENE --steps N [--dump FILE]: exactly N steps of the scene's dt.
int run_headless(const CommandLine& command_line);

// weft [SCENE]: until the SDL window exists, simulates a few seconds of the scene and prints
// how it settles.
int run_text_preview(const CommandLine& command_line, const char* default_scene_path);

}  // namespace weft
