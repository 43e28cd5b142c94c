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

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "sim/scene.h"

namespace weft {

// Each key a live edit may change, named in scene_key_names by its dotted scene-file path.
enum class SceneKey : std::uint8_t {
    cloth_rows,  // int
    cloth_cols,  // int
    cloth_spacing,
    cloth_particle_mass,
    cloth_layout,
    cloth_orientation,
    cloth_pins,  // GridPins
    cloth_origin,
    cloth_density,  // a mesh's
    structural_enabled,
    structural_stiffness,
    structural_damping,
    shear_enabled,
    shear_stiffness,
    shear_damping,
    bend_enabled,
    bend_stiffness,
    bend_damping,
    tear_max_stretch,  // a number, or FeatureOff to switch tearing off
    strain_limit_max_strain,
    self_collision_thickness,
    gravity,
    air_drag,
    wind,
    gust,
    integrator,
    dt,
    collider_center,  // of the collider at SceneEdit::collider
    collider_radius,
    collider_point,
    collider_normal,
    collider_response,
    collider_restitution,
    collider_friction,
    floor_enabled,
    camera_position,
    camera_target,
    camera_fov_degrees,
};

inline constexpr std::array<std::string_view, 38> scene_key_names = {
    "cloth.rows",
    "cloth.cols",
    "cloth.spacing",
    "cloth.particle_mass",
    "cloth.layout",
    "cloth.orientation",
    "cloth.pins",
    "cloth.origin",
    "cloth.density",
    "springs.structural.enabled",
    "springs.structural.stiffness",
    "springs.structural.damping",
    "springs.shear.enabled",
    "springs.shear.stiffness",
    "springs.shear.damping",
    "springs.bend.enabled",
    "springs.bend.stiffness",
    "springs.bend.damping",
    "tearing.max_stretch",
    "strain_limit.max_strain",
    "self_collision.thickness",
    "forces.gravity",
    "forces.air_drag",
    "forces.wind",
    "forces.gust",
    "solver.integrator",
    "solver.dt",
    "colliders.center",
    "colliders.radius",
    "colliders.point",
    "colliders.normal",
    "colliders.response",
    "colliders.restitution",
    "colliders.friction",
    "floor.enabled",
    "camera.position",
    "camera.target",
    "camera.fov_degrees",
};

// A grid's pins: a preset, or a list of [row, col].
struct GridPins {
    PinPreset preset = PinPreset::top_corners;
    std::vector<GridIndex> list;  // when preset == list

    bool operator==(const GridPins&) const = default;
};

// An optional feature ([tearing], [strain_limit], [self_collision]) switched off.
struct FeatureOff {
    bool operator==(const FeatureOff&) const = default;
};

using SceneValue = std::variant<double, std::int64_t, bool, Vec3d, Integrator, Layout, Orientation,
                                ContactResponse, GridPins, FeatureOff>;

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
