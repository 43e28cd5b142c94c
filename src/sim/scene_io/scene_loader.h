// Scene loading: a TOML scene file plus `--set KEY=VALUE` overrides become a checked Scene.
//
// Every key has a default (scene.h); a file names only what it changes. Anything wrong —
// an unknown key, a wrong type, an out-of-range value, a grid too large for memory, a pin
// outside the grid — is reported as one SceneError naming where ("FILE:LINE:COL" for the
// file, "--set KEY" for an override) and what, and no Scene is produced.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sim/scene/scene.h"

namespace weft {

struct SceneError {
    std::string where;  // "FILE:LINE:COL", "FILE" (no position, e.g. unreadable), or "--set KEY"
    std::string what;   // human-readable description, e.g. "unknown key 'stifness' (did you mean
                        // 'stiffness'?)"
    std::string message() const { return "error: " + where + ": " + what; }
};

struct SceneLoadResult {
    std::optional<Scene> scene;         // set on success
    std::optional<SceneError> error;    // set on failure
    std::vector<std::string> warnings;  // e.g. keys accepted but not yet modelled
    bool ok() const { return scene.has_value(); }
};

// Loads a scene file and applies overrides ("KEY=VALUE", KEY a dotted path such as
// "solver.dt", VALUE a TOML value such as 0.0005, "rk4", [0,-9.81,0], false).
SceneLoadResult load_scene_file(const std::string& path,
                                const std::vector<std::string>& overrides = {});

// Same, from text in memory; source_name stands in for the file name in errors.
SceneLoadResult load_scene_text(std::string_view toml_text, std::string_view source_name,
                                const std::vector<std::string>& overrides = {});

}  // namespace weft
