// The interactive demo: an SDL2 window showing weft's own CPU-rendered frames, with the
// keyboard camera, pulling, cutting, pins, the parameter panel and divergence recovery.
// The only part of weft that includes SDL.
#pragma once

#include "app/command_line.h"

namespace weft::app {

// Returns the exit status: 0, 2 for a bad scene or when no window can be opened.
int run_demo_window(const CommandLine& command_line, const char* default_scene_path);

}  // namespace weft::app
