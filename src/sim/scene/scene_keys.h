// The scene keys that a live edit, a recording or --set can change, each described once: its
// name in a scene file, the kind of value it takes, its unit, the rule its value must pass,
// a line of documentation, and how it is read from and written into a Scene. Typed edits
// (scene_edit.h), their TOML form (scene_edit_toml.h) and the reference, docs/scene-format.md
// (written by tools/make_scene_format.cpp and checked against this table), all come from it.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "sim/scene/scene.h"
#include "sim/scene/scene_rules.h"

namespace weft {

// Each key a live edit may change, in the order of the table (scene_key_table).
enum class SceneKey : std::uint8_t {
    cloth_rows,
    cloth_cols,
    cloth_spacing,
    cloth_particle_mass,
    cloth_layout,
    cloth_orientation,
    cloth_pins,
    cloth_origin,
    cloth_density,
    structural_enabled,
    structural_stiffness,
    structural_damping,
    shear_enabled,
    shear_stiffness,
    shear_damping,
    bend_enabled,
    bend_stiffness,
    bend_damping,
    tear_max_stretch,
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
inline constexpr std::size_t scene_key_count = 38;

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

// What a key's value is, which says how it is read, checked and written.
enum class ValueKind : std::uint8_t {
    count,    // a whole number of particles (cloth.rows, cloth.cols)
    number,   // a finite number within the key's rule
    flag,     // true or false
    vector,   // [x, y, z], finite
    choice,   // one of the key's names
    pins,     // a pin preset or a list of [row, col]
    feature,  // a number within the rule, or false: the optional table switched off
};

struct SceneKeyInfo {
    SceneKey key;
    std::string_view name;  // dotted path in a scene file; a collider's without its index
    ValueKind kind;
    std::string_view unit;                      // SI, "" for none
    NumberRule rule;                            // number and feature
    std::span<const std::string_view> choices;  // choice: its spellings, by the enum's value
    double feature_default;                     // feature: the value when the table is bare
    std::string_view doc;                       // one line, for the reference
    // The key's value in `scene` (collider `c`'s, for a collider key), and writing one that
    // has passed the checks.
    SceneValue (*get)(const Scene& scene, std::uint32_t c);
    void (*set)(Scene& scene, const SceneValue& value, std::uint32_t c);
    // choice: the value of the spelling at `index` in `choices`.
    SceneValue (*choice_value)(int index);

    // The table the key sits in ("springs.shear", "colliders") and its name there.
    std::string_view section() const { return name.substr(0, name.rfind('.')); }
    std::string_view leaf() const { return name.substr(name.rfind('.') + 1); }
};

// Every key, in SceneKey's order.
std::span<const SceneKeyInfo> scene_key_table();
const SceneKeyInfo& scene_key_info(SceneKey key);
inline std::string_view scene_key_name(SceneKey key) {
    return scene_key_info(key).name;
}

// docs/scene-format.md: every key of a scene file with its unit, default and range.
std::string scene_format_markdown();

}  // namespace weft
