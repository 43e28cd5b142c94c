#include "sim/scene/scene_edit.h"

#include "sim/scene/scene_rules.h"

namespace weft {
namespace {

bool is_grid_key(SceneKey key) {  // what only a grid has
    return key <= SceneKey::cloth_pins && key != SceneKey::cloth_particle_mass;
}

// The value `key` has in `scene` (its collider `collider`'s, for a collider key).
SceneValue value_of(const Scene& scene, SceneKey key, std::uint32_t collider) {
    return scene_key_info(key).get(scene, collider);
}

// What a key's value must be, for the message when an edit gives another type.
const char* type_wanted(const SceneValue& value) {
    return std::visit(
        [](const auto& v) -> const char* {
            using T = std::decay_t<decltype(v)>;
            if constexpr (std::is_same_v<T, double>) return "a number";
            if constexpr (std::is_same_v<T, std::int64_t>) return "an integer";
            if constexpr (std::is_same_v<T, bool>) return "true or false";
            if constexpr (std::is_same_v<T, Vec3d>) return "an array of 3 numbers";
            if constexpr (std::is_same_v<T, GridPins>) return "a pin preset or a list of pins";
            return "one of its names";
        },
        value);
}

// Whether `edit` may be applied to `scene`, by the loader's rules for its key alone; the
// rules that join keys are checked on the batch's result (joint_problem).
std::optional<std::string> edit_problem(const Scene& scene, const SceneEdit& edit) {
    const std::string name = scene_edit_name(edit);
    const bool mesh = !scene.cloth.mesh.empty();
    if (is_grid_key(edit.key) && mesh) return not_for_mesh(name);
    if (edit.key == SceneKey::cloth_density && !mesh) return only_for_mesh(name);
    // A mesh is weighed one way, by density or by particle_mass, as its file chose.
    const bool weighed_alike = scene.cloth.mesh_particle_mass;
    if (mesh && ((edit.key == SceneKey::cloth_density && weighed_alike) ||
                 (edit.key == SceneKey::cloth_particle_mass && !weighed_alike)))
        return both_mesh_masses();
    if (is_collider_key(edit.key) && edit.collider >= scene.colliders.size())
        return "there is no collider " + std::to_string(edit.collider) + " (the scene has " +
               std::to_string(scene.colliders.size()) + ")";
    const SceneValue current = value_of(scene, edit.key, edit.collider);
    const bool feature = scene_key_info(edit.key).kind == ValueKind::feature;
    const bool same_type = current.index() == edit.value.index() ||
                           (feature && (std::holds_alternative<double>(edit.value) ||
                                        std::holds_alternative<FeatureOff>(edit.value)));
    if (!same_type) return name + " must be " + type_wanted(current);
    if (feature && std::holds_alternative<FeatureOff>(edit.value)) return std::nullopt;
    if (const auto* number = std::get_if<double>(&edit.value))
        return number_problem(name, *number, scene_key_info(edit.key).rule);
    if (const auto* count = std::get_if<std::int64_t>(&edit.value))
        return grid_count_problem(name, *count);
    if (const auto* vector = std::get_if<Vec3d>(&edit.value)) {
        if (auto problem = vector_problem(name, *vector)) return problem;
        if (edit.key == SceneKey::collider_normal) return normal_problem(*vector);
        return std::nullopt;
    }
    if (const auto* enabled = std::get_if<bool>(&edit.value))
        return edit.key == SceneKey::structural_enabled ? structural_enabled_problem(*enabled)
                                                        : std::nullopt;
    if (const auto* pins = std::get_if<GridPins>(&edit.value))
        if (pins->preset == PinPreset::vertices || pins->preset == PinPreset::group)
            return name + " of a grid is a preset or a list of [row, col]";
    return std::nullopt;
}

// Writes `edit` into `scene`; edit_problem has passed it.
void assign(Scene& scene, const SceneEdit& edit) {
    scene_key_info(edit.key).set(scene, edit.value, edit.collider);
}

// The loader's checks that join keys, on the scene the batch made.
std::optional<std::string> joint_problem(const Scene& scene) {
    const ClothSpec& cloth = scene.cloth;
    const bool mesh = !cloth.mesh.empty();
    if (!mesh) {
        if (auto problem = grid_size_problem(cloth.rows, cloth.cols)) return problem;
        if (cloth.pin_preset == PinPreset::list)
            for (const GridIndex& pin : cloth.pin_list)
                if (auto problem = pin_problem(pin.row, pin.col, cloth.rows, cloth.cols))
                    return "cloth.pins: " + *problem;
    }
    if (scene.self_collision_thickness)
        return thickness_problem(*scene.self_collision_thickness,
                                 mesh ? cloth.mesh_data.mean_edge_length : cloth.spacing, mesh);
    return std::nullopt;
}

}  // namespace

SceneKey spring_key(std::size_t family, SpringField field) {
    return static_cast<SceneKey>(static_cast<std::size_t>(SceneKey::structural_enabled) +
                                 3 * family + static_cast<std::size_t>(field));
}

bool is_collider_key(SceneKey key) {
    return key >= SceneKey::collider_center && key <= SceneKey::collider_friction;
}

bool is_solver_key(SceneKey key) {
    return key == SceneKey::integrator || key == SceneKey::dt;
}

std::string scene_edit_name(const SceneEdit& edit) {
    const std::string_view name = scene_key_name(edit.key);
    if (!is_collider_key(edit.key)) return std::string(name);
    const std::string_view field = name.substr(name.find('.') + 1);
    return "colliders." + std::to_string(edit.collider) + "." + std::string(field);
}

std::optional<std::string> apply_scene_edits(Scene& scene, std::span<const SceneEdit> edits) {
    Scene edited = scene;
    for (const SceneEdit& edit : edits) {
        if (auto problem = edit_problem(edited, edit)) return problem;
        assign(edited, edit);
    }
    if (!edits.empty())
        if (auto problem = joint_problem(edited)) return problem;
    scene = std::move(edited);
    return std::nullopt;
}

std::optional<std::vector<SceneEdit>> scene_edits_between(const Scene& from, const Scene& to) {
    if (from.colliders.size() != to.colliders.size()) return std::nullopt;
    std::vector<SceneEdit> edits;
    const bool mesh = !from.cloth.mesh.empty();
    Scene reached = from;
    for (const SceneKeyInfo& info : scene_key_table()) {
        const SceneKey key = info.key;
        if (mesh ? is_grid_key(key) : key == SceneKey::cloth_density) continue;
        if (mesh && key == (from.cloth.mesh_particle_mass ? SceneKey::cloth_density
                                                          : SceneKey::cloth_particle_mass))
            continue;
        const std::uint32_t count =
            is_collider_key(key) ? static_cast<std::uint32_t>(from.colliders.size()) : 1;
        for (std::uint32_t c = 0; c < count; ++c) {
            SceneValue value = value_of(to, key, c);
            if (value == value_of(from, key, c)) continue;
            edits.push_back({key, std::move(value), is_collider_key(key) ? c : 0});
            assign(reached, edits.back());
        }
    }
    if (!(reached == to)) return std::nullopt;  // differs where no edit reaches
    return edits;
}

}  // namespace weft
