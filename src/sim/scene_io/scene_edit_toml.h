// Scene edits (scene_edit.h) as TOML: how a recording stores one ("key" and "value") and how
// a --set style "KEY=VALUE" becomes one. Types are checked here, with the loader's reader
// and its messages; values are checked when the edit is applied (apply_scene_edits).
#pragma once

#include <toml++/toml.h>

#include <optional>
#include <string>
#include <string_view>

#include "sim/scene/scene_edit.h"
#include "sim/scene_io/toml_reader.h"

namespace weft {

// The edit that sets `key` (a scene key's path, scene_keys.h; a collider's as "colliders.N.field")
// to `value`. On a key no edit reaches, or a value of the wrong type, records the error in `reader`
// at `value` and returns nothing.
std::optional<SceneEdit> read_scene_edit(TomlReader& reader, const std::string& key,
                                         const toml::node& value);

// A --set style "KEY=VALUE" as an edit; errors name "--set KEY".
std::optional<SceneEdit> scene_edit_from_override(const std::string& override_text,
                                                  SceneError& error);

// The edit's value as TOML that read_scene_edit reads back to the same value, bit for bit.
std::string scene_value_toml(const SceneValue& value);

}  // namespace weft
