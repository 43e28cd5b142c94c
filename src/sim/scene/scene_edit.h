// SceneEdit: one live change of a scene as a typed value — which parameter, and its new
// value — instead of a whole scene written as TOML and parsed back. The panel makes these,
// the demo applies them to every run shown, and a recording stores them (about 100 bytes a
// slider tick where a whole scene took 1 KB or more).
//
// An edit is checked by the scene rules the loader checks a file with (scene_rules.h), so a
// refused edit changes nothing and says why in the loader's words. Edits that belong
// together (a grid's rows, cols and pins) go in one batch: the checks that join keys (rows ×
// cols, pins inside the grid, thickness against spacing) look at the batch's result.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "sim/scene/scene.h"
#include "sim/scene/scene_keys.h"

namespace weft {

struct SceneEdit {
    SceneKey key = SceneKey::dt;
    SceneValue value = 0.0;
    std::uint32_t collider = 0;  // which [[colliders]] entry, for the collider keys

    bool operator==(const SceneEdit&) const = default;
};

// A spring family's key: `family` indexes spring_family_names (scene.h).
enum class SpringField { enabled, stiffness, damping };
SceneKey spring_key(std::size_t family, SpringField field);

bool is_collider_key(SceneKey key);
bool is_solver_key(SceneKey key);  // solver.integrator, solver.dt
// The key as a scene file path; a collider's with its index: "colliders.2.radius".
std::string scene_edit_name(const SceneEdit& edit);

// Applies `edits` in order to `scene`, all or nothing: on a refusal returns the problem, in
// the scene rules' words, with `scene` unchanged.
std::optional<std::string> apply_scene_edits(Scene& scene, std::span<const SceneEdit> edits);

// The edits that turn `from` into `to`: nothing if they are the same scene; nullopt if they
// differ where no edit reaches (the name, the mesh, a collider added, removed or of another
// type), so only a new scene gets there.
std::optional<std::vector<SceneEdit>> scene_edits_between(const Scene& from, const Scene& to);

}  // namespace weft
