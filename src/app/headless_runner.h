// Runs a scene without a window: the --headless mode. Returns the process exit status
// (0 done, 2 bad input, 3 diverged).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/command_line.h"
#include "sim/scene/scene.h"

namespace weft {

inline constexpr int exit_ok = 0;
inline constexpr int exit_bad_input = 2;
inline constexpr int exit_diverged = 3;
inline constexpr int exit_replay_differs = 4;  // a headless replay did not end where recorded

// Loads and checks a scene; prints warnings and the error (and returns nothing) when bad.
std::optional<Scene> load_checked_scene(const std::string& path,
                                        const std::vector<std::string>& overrides);

// weft --headless SCENE --steps N [--dump FILE]: exactly N steps of the scene's dt.
int run_headless(const CommandLine& command_line);

// weft --headless --replay SESSION [--dump FILE] [--screenshot IMAGE]: the recorded session
// through the demo's own stepping (its recoveries included); 0 if it ends in the recorded
// state bit for bit, exit_replay_differs if not.
int run_headless_replay(const CommandLine& command_line);

}  // namespace weft
