#include "sim/scene_edit.h"

#include "sim/scene_rules.h"

namespace weft {
namespace {

constexpr SceneKey all_keys[] = {
    SceneKey::cloth_rows,
    SceneKey::cloth_cols,
    SceneKey::cloth_spacing,
    SceneKey::cloth_particle_mass,
    SceneKey::cloth_layout,
    SceneKey::cloth_orientation,
    SceneKey::cloth_pins,
    SceneKey::cloth_origin,
    SceneKey::cloth_density,
    SceneKey::structural_enabled,
    SceneKey::structural_stiffness,
    SceneKey::structural_damping,
    SceneKey::shear_enabled,
    SceneKey::shear_stiffness,
    SceneKey::shear_damping,
    SceneKey::bend_enabled,
    SceneKey::bend_stiffness,
    SceneKey::bend_damping,
    SceneKey::tear_max_stretch,
    SceneKey::strain_limit_max_strain,
    SceneKey::self_collision_thickness,
    SceneKey::gravity,
    SceneKey::air_drag,
    SceneKey::wind,
    SceneKey::gust,
    SceneKey::integrator,
    SceneKey::dt,
    SceneKey::collider_center,
    SceneKey::collider_radius,
    SceneKey::collider_point,
    SceneKey::collider_normal,
    SceneKey::collider_response,
    SceneKey::collider_restitution,
    SceneKey::collider_friction,
    SceneKey::floor_enabled,
    SceneKey::camera_position,
    SceneKey::camera_target,
    SceneKey::camera_fov_degrees,
};
static_assert(std::size(all_keys) == scene_key_names.size());

bool is_grid_key(SceneKey key) {  // what only a grid has
    return key <= SceneKey::cloth_pins && key != SceneKey::cloth_particle_mass;
}

// The family a springs.* key edits.
template <class SceneType>  // Scene or const Scene
auto& family_of(SceneType& scene, SceneKey key) {
    const int family = (static_cast<int>(key) - static_cast<int>(SceneKey::structural_enabled)) / 3;
    return family == 0 ? scene.structural : family == 1 ? scene.shear : scene.bend;
}

template <class SceneType>
auto& feature_of(SceneType& scene, SceneKey key) {
    return key == SceneKey::tear_max_stretch          ? scene.tear_max_stretch
           : key == SceneKey::strain_limit_max_strain ? scene.strain_limit_max_strain
                                                      : scene.self_collision_thickness;
}

NumberRule feature_rule(SceneKey key) {
    return key == SceneKey::tear_max_stretch          ? scene_rules::tear_max_stretch
           : key == SceneKey::strain_limit_max_strain ? scene_rules::strain_limit_max_strain
                                                      : scene_rules::self_collision_thickness;
}

// The value `key` has in `scene` (its collider `collider`'s, for a collider key).
SceneValue value_of(const Scene& scene, SceneKey key, std::uint32_t collider) {
    const ClothSpec& cloth = scene.cloth;
    switch (key) {
        case SceneKey::cloth_rows:
            return std::int64_t{cloth.rows};
        case SceneKey::cloth_cols:
            return std::int64_t{cloth.cols};
        case SceneKey::cloth_spacing:
            return cloth.spacing;
        case SceneKey::cloth_particle_mass:
            return cloth.particle_mass;
        case SceneKey::cloth_layout:
            return cloth.layout;
        case SceneKey::cloth_orientation:
            return cloth.orientation;
        case SceneKey::cloth_pins:
            return GridPins{cloth.pin_preset, cloth.pin_preset == PinPreset::list
                                                  ? cloth.pin_list
                                                  : std::vector<GridIndex>{}};
        case SceneKey::cloth_origin:
            return cloth.origin;
        case SceneKey::cloth_density:
            return cloth.density;
        case SceneKey::structural_enabled:
        case SceneKey::shear_enabled:
        case SceneKey::bend_enabled:
            return family_of(scene, key).enabled;
        case SceneKey::structural_stiffness:
        case SceneKey::shear_stiffness:
        case SceneKey::bend_stiffness:
            return family_of(scene, key).stiffness;
        case SceneKey::structural_damping:
        case SceneKey::shear_damping:
        case SceneKey::bend_damping:
            return family_of(scene, key).damping;
        case SceneKey::tear_max_stretch:
        case SceneKey::strain_limit_max_strain:
        case SceneKey::self_collision_thickness: {
            const auto& feature = feature_of(scene, key);
            return feature ? SceneValue{*feature} : SceneValue{FeatureOff{}};
        }
        case SceneKey::gravity:
            return scene.forces.gravity;
        case SceneKey::air_drag:
            return scene.forces.air_drag;
        case SceneKey::wind:
            return scene.forces.wind;
        case SceneKey::gust:
            return scene.forces.gust;
        case SceneKey::integrator:
            return scene.solver.integrator;
        case SceneKey::dt:
            return scene.solver.dt;
        case SceneKey::collider_center:
            return scene.colliders[collider].center;
        case SceneKey::collider_radius:
            return scene.colliders[collider].radius;
        case SceneKey::collider_point:
            return scene.colliders[collider].point;
        case SceneKey::collider_normal:
            return scene.colliders[collider].normal;
        case SceneKey::collider_response:
            return scene.colliders[collider].response;
        case SceneKey::collider_restitution:
            return scene.colliders[collider].restitution;
        case SceneKey::collider_friction:
            return scene.colliders[collider].friction;
        case SceneKey::floor_enabled:
            return scene.floor_enabled;
        case SceneKey::camera_position:
            return scene.camera.position;
        case SceneKey::camera_target:
            return scene.camera.target;
        case SceneKey::camera_fov_degrees:
            return scene.camera.fov_degrees;
    }
    return 0.0;
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
    const bool feature = edit.key == SceneKey::tear_max_stretch ||
                         edit.key == SceneKey::strain_limit_max_strain ||
                         edit.key == SceneKey::self_collision_thickness;
    const bool same_type = current.index() == edit.value.index() ||
                           (feature && (std::holds_alternative<double>(edit.value) ||
                                        std::holds_alternative<FeatureOff>(edit.value)));
    if (!same_type) return name + " must be " + type_wanted(current);
    if (feature && std::holds_alternative<FeatureOff>(edit.value)) return std::nullopt;
    if (const auto* number = std::get_if<double>(&edit.value)) {
        NumberRule rule = scene_rules::any;
        switch (edit.key) {
            case SceneKey::cloth_spacing:
                rule = scene_rules::spacing;
                break;
            case SceneKey::cloth_particle_mass:
                rule = scene_rules::particle_mass;
                break;
            case SceneKey::cloth_density:
                rule = scene_rules::density;
                break;
            case SceneKey::structural_stiffness:
            case SceneKey::shear_stiffness:
            case SceneKey::bend_stiffness:
                rule = scene_rules::spring_stiffness;
                break;
            case SceneKey::structural_damping:
            case SceneKey::shear_damping:
            case SceneKey::bend_damping:
                rule = scene_rules::spring_damping;
                break;
            case SceneKey::tear_max_stretch:
            case SceneKey::strain_limit_max_strain:
            case SceneKey::self_collision_thickness:
                rule = feature_rule(edit.key);
                break;
            case SceneKey::air_drag:
                rule = scene_rules::air_drag;
                break;
            case SceneKey::gust:
                rule = scene_rules::gust;
                break;
            case SceneKey::dt:
                rule = scene_rules::dt;
                break;
            case SceneKey::collider_radius:
                rule = scene_rules::collider_radius;
                break;
            case SceneKey::collider_restitution:
                rule = scene_rules::restitution;
                break;
            case SceneKey::collider_friction:
                rule = scene_rules::friction;
                break;
            case SceneKey::camera_fov_degrees:
                rule = scene_rules::fov_degrees;
                break;
            default:
                break;
        }
        return number_problem(name, *number, rule);
    }
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
    ClothSpec& cloth = scene.cloth;
    const SceneValue& value = edit.value;
    switch (edit.key) {
        case SceneKey::cloth_rows:
            cloth.rows = static_cast<int>(std::get<std::int64_t>(value));
            return;
        case SceneKey::cloth_cols:
            cloth.cols = static_cast<int>(std::get<std::int64_t>(value));
            return;
        case SceneKey::cloth_spacing:
            cloth.spacing = std::get<double>(value);
            return;
        case SceneKey::cloth_particle_mass:
            cloth.particle_mass = std::get<double>(value);
            return;
        case SceneKey::cloth_layout:
            cloth.layout = std::get<Layout>(value);
            return;
        case SceneKey::cloth_orientation:
            cloth.orientation = std::get<Orientation>(value);
            return;
        case SceneKey::cloth_pins:
            cloth.pin_preset = std::get<GridPins>(value).preset;
            cloth.pin_list = std::get<GridPins>(value).list;
            return;
        case SceneKey::cloth_origin:
            cloth.origin = std::get<Vec3d>(value);
            return;
        case SceneKey::cloth_density:
            cloth.density = std::get<double>(value);
            return;
        case SceneKey::structural_enabled:
        case SceneKey::shear_enabled:
        case SceneKey::bend_enabled:
            family_of(scene, edit.key).enabled = std::get<bool>(value);
            return;
        case SceneKey::structural_stiffness:
        case SceneKey::shear_stiffness:
        case SceneKey::bend_stiffness:
            family_of(scene, edit.key).stiffness = std::get<double>(value);
            return;
        case SceneKey::structural_damping:
        case SceneKey::shear_damping:
        case SceneKey::bend_damping:
            family_of(scene, edit.key).damping = std::get<double>(value);
            return;
        case SceneKey::tear_max_stretch:
        case SceneKey::strain_limit_max_strain:
        case SceneKey::self_collision_thickness:
            if (const auto* number = std::get_if<double>(&value))
                feature_of(scene, edit.key) = *number;
            else
                feature_of(scene, edit.key).reset();
            return;
        case SceneKey::gravity:
            scene.forces.gravity = std::get<Vec3d>(value);
            return;
        case SceneKey::air_drag:
            scene.forces.air_drag = std::get<double>(value);
            return;
        case SceneKey::wind:
            scene.forces.wind = std::get<Vec3d>(value);
            return;
        case SceneKey::gust:
            scene.forces.gust = std::get<double>(value);
            return;
        case SceneKey::integrator:
            scene.solver.integrator = std::get<Integrator>(value);
            return;
        case SceneKey::dt:
            scene.solver.dt = std::get<double>(value);
            return;
        case SceneKey::collider_center:
            scene.colliders[edit.collider].center = std::get<Vec3d>(value);
            return;
        case SceneKey::collider_radius:
            scene.colliders[edit.collider].radius = std::get<double>(value);
            return;
        case SceneKey::collider_point:
            scene.colliders[edit.collider].point = std::get<Vec3d>(value);
            return;
        case SceneKey::collider_normal:
            scene.colliders[edit.collider].normal = std::get<Vec3d>(value);
            return;
        case SceneKey::collider_response:
            scene.colliders[edit.collider].response = std::get<ContactResponse>(value);
            return;
        case SceneKey::collider_restitution:
            scene.colliders[edit.collider].restitution = std::get<double>(value);
            return;
        case SceneKey::collider_friction:
            scene.colliders[edit.collider].friction = std::get<double>(value);
            return;
        case SceneKey::floor_enabled:
            scene.floor_enabled = std::get<bool>(value);
            return;
        case SceneKey::camera_position:
            scene.camera.position = std::get<Vec3d>(value);
            return;
        case SceneKey::camera_target:
            scene.camera.target = std::get<Vec3d>(value);
            return;
        case SceneKey::camera_fov_degrees:
            scene.camera.fov_degrees = std::get<double>(value);
            return;
    }
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
    const std::string_view name = scene_key_names[static_cast<std::size_t>(edit.key)];
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
    for (SceneKey key : all_keys) {
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
