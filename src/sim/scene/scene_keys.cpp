#include "sim/scene/scene_keys.h"

#include <charconv>
#include <sstream>

#include "sim/scene/scene_rules.h"

namespace weft {
namespace {

// Readers and writers of the Scene's members, one template per shape of path.

template <auto Member>  // a member of Scene
SceneValue get_top(const Scene& scene, std::uint32_t) {
    return SceneValue{scene.*Member};
}
template <auto Member>
void set_top(Scene& scene, const SceneValue& value, std::uint32_t) {
    using T = std::remove_cvref_t<decltype(scene.*Member)>;
    scene.*Member = std::get<T>(value);
}

template <auto Outer, auto Inner>  // a member of a member of Scene
SceneValue get_in(const Scene& scene, std::uint32_t) {
    return SceneValue{(scene.*Outer).*Inner};
}
template <auto Outer, auto Inner>
void set_in(Scene& scene, const SceneValue& value, std::uint32_t) {
    using T = std::remove_cvref_t<decltype((scene.*Outer).*Inner)>;
    (scene.*Outer).*Inner = std::get<T>(value);
}

template <auto Count>  // cloth.rows, cloth.cols: an int held as a 64-bit count
SceneValue get_count(const Scene& scene, std::uint32_t) {
    return std::int64_t{scene.cloth.*Count};
}
template <auto Count>
void set_count(Scene& scene, const SceneValue& value, std::uint32_t) {
    scene.cloth.*Count = static_cast<int>(std::get<std::int64_t>(value));
}

template <auto Feature>  // an optional table's value, or FeatureOff
SceneValue get_feature(const Scene& scene, std::uint32_t) {
    const std::optional<double>& feature = scene.*Feature;
    return feature ? SceneValue{*feature} : SceneValue{FeatureOff{}};
}
template <auto Feature>
void set_feature(Scene& scene, const SceneValue& value, std::uint32_t) {
    if (const auto* number = std::get_if<double>(&value))
        scene.*Feature = *number;
    else
        (scene.*Feature).reset();
}

template <auto Field>  // a member of the collider at index c
SceneValue get_collider(const Scene& scene, std::uint32_t c) {
    return SceneValue{scene.colliders[c].*Field};
}
template <auto Field>
void set_collider(Scene& scene, const SceneValue& value, std::uint32_t c) {
    using T = std::remove_cvref_t<decltype(scene.colliders[c].*Field)>;
    scene.colliders[c].*Field = std::get<T>(value);
}

SceneValue get_pins(const Scene& scene, std::uint32_t) {
    const ClothSpec& cloth = scene.cloth;
    return GridPins{cloth.pin_preset, cloth.pin_preset == PinPreset::list
                                          ? cloth.pin_list
                                          : std::vector<GridIndex>{}};
}
void set_pins(Scene& scene, const SceneValue& value, std::uint32_t) {
    scene.cloth.pin_preset = std::get<GridPins>(value).preset;
    scene.cloth.pin_list = std::get<GridPins>(value).list;
}

template <class Enum>
SceneValue choice_of(int index) {
    return static_cast<Enum>(index);
}

constexpr NumberRule none{};

const SceneKeyInfo table[] = {
    {SceneKey::cloth_rows,
     "cloth.rows",
     ValueKind::count,
     "",
     none,
     {},
     0.0,
     "particles from top to bottom (a grid)",
     get_count<&ClothSpec::rows>,
     set_count<&ClothSpec::rows>,
     nullptr},
    {SceneKey::cloth_cols,
     "cloth.cols",
     ValueKind::count,
     "",
     none,
     {},
     0.0,
     "particles from left to right (a grid)",
     get_count<&ClothSpec::cols>,
     set_count<&ClothSpec::cols>,
     nullptr},
    {SceneKey::cloth_spacing,
     "cloth.spacing",
     ValueKind::number,
     "m",
     scene_rules::spacing,
     {},
     0.0,
     "rest length of a structural spring (a grid)",
     get_in<&Scene::cloth, &ClothSpec::spacing>,
     set_in<&Scene::cloth, &ClothSpec::spacing>,
     nullptr},
    {SceneKey::cloth_particle_mass,
     "cloth.particle_mass",
     ValueKind::number,
     "kg",
     scene_rules::particle_mass,
     {},
     0.0,
     "mass of every particle (a grid; a mesh weighed per vertex instead of by density)",
     get_in<&Scene::cloth, &ClothSpec::particle_mass>,
     set_in<&Scene::cloth, &ClothSpec::particle_mass>,
     nullptr},
    {SceneKey::cloth_layout, "cloth.layout", ValueKind::choice, "", none, layout_names, 0.0,
     "square cells, or rows offset by half a spacing into equilateral triangles",
     get_in<&Scene::cloth, &ClothSpec::layout>, set_in<&Scene::cloth, &ClothSpec::layout>,
     choice_of<Layout>},
    {SceneKey::cloth_orientation, "cloth.orientation", ValueKind::choice, "", none,
     orientation_names, 0.0,
     "where row r, col c starts: origin + (c, -r, 0) spacings, or (c, 0, r)",
     get_in<&Scene::cloth, &ClothSpec::orientation>, set_in<&Scene::cloth, &ClothSpec::orientation>,
     choice_of<Orientation>},
    {SceneKey::cloth_pins, "cloth.pins", ValueKind::pins, "", none, pin_preset_names, 0.0,
     "pinned particles: a preset, or a list of [row, col] (a grid)", get_pins, set_pins, nullptr},
    {SceneKey::cloth_origin,
     "cloth.origin",
     ValueKind::vector,
     "m",
     none,
     {},
     0.0,
     "where particle (0, 0) starts; a mesh's (0, 0, 0)",
     get_in<&Scene::cloth, &ClothSpec::origin>,
     set_in<&Scene::cloth, &ClothSpec::origin>,
     nullptr},
    {SceneKey::cloth_density,
     "cloth.density",
     ValueKind::number,
     "kg/m²",
     scene_rules::density,
     {},
     0.0,
     "a mesh's mass per area, lumped onto its vertices",
     get_in<&Scene::cloth, &ClothSpec::density>,
     set_in<&Scene::cloth, &ClothSpec::density>,
     nullptr},
    {SceneKey::structural_enabled,
     "springs.structural.enabled",
     ValueKind::flag,
     "",
     none,
     {},
     0.0,
     "always true: structural springs are what a cloth is",
     get_in<&Scene::structural, &SpringFamilySpec::enabled>,
     set_in<&Scene::structural, &SpringFamilySpec::enabled>,
     nullptr},
    {SceneKey::structural_stiffness,
     "springs.structural.stiffness",
     ValueKind::number,
     "N/m",
     scene_rules::spring_stiffness,
     {},
     0.0,
     "spring constant between neighbours",
     get_in<&Scene::structural, &SpringFamilySpec::stiffness>,
     set_in<&Scene::structural, &SpringFamilySpec::stiffness>,
     nullptr},
    {SceneKey::structural_damping,
     "springs.structural.damping",
     ValueKind::number,
     "N·s/m",
     scene_rules::spring_damping,
     {},
     0.0,
     "damper along each structural spring",
     get_in<&Scene::structural, &SpringFamilySpec::damping>,
     set_in<&Scene::structural, &SpringFamilySpec::damping>,
     nullptr},
    {SceneKey::shear_enabled,
     "springs.shear.enabled",
     ValueKind::flag,
     "",
     none,
     {},
     0.0,
     "diagonal springs; true when the [springs.shear] table is given",
     get_in<&Scene::shear, &SpringFamilySpec::enabled>,
     set_in<&Scene::shear, &SpringFamilySpec::enabled>,
     nullptr},
    {SceneKey::shear_stiffness,
     "springs.shear.stiffness",
     ValueKind::number,
     "N/m",
     scene_rules::spring_stiffness,
     {},
     0.0,
     "spring constant across each cell's diagonals",
     get_in<&Scene::shear, &SpringFamilySpec::stiffness>,
     set_in<&Scene::shear, &SpringFamilySpec::stiffness>,
     nullptr},
    {SceneKey::shear_damping,
     "springs.shear.damping",
     ValueKind::number,
     "N·s/m",
     scene_rules::spring_damping,
     {},
     0.0,
     "damper along each shear spring",
     get_in<&Scene::shear, &SpringFamilySpec::damping>,
     set_in<&Scene::shear, &SpringFamilySpec::damping>,
     nullptr},
    {SceneKey::bend_enabled,
     "springs.bend.enabled",
     ValueKind::flag,
     "",
     none,
     {},
     0.0,
     "springs to the particle two along; true when the [springs.bend] table is given",
     get_in<&Scene::bend, &SpringFamilySpec::enabled>,
     set_in<&Scene::bend, &SpringFamilySpec::enabled>,
     nullptr},
    {SceneKey::bend_stiffness,
     "springs.bend.stiffness",
     ValueKind::number,
     "N/m",
     scene_rules::spring_stiffness,
     {},
     0.0,
     "spring constant of the bend springs",
     get_in<&Scene::bend, &SpringFamilySpec::stiffness>,
     set_in<&Scene::bend, &SpringFamilySpec::stiffness>,
     nullptr},
    {SceneKey::bend_damping,
     "springs.bend.damping",
     ValueKind::number,
     "N·s/m",
     scene_rules::spring_damping,
     {},
     0.0,
     "damper along each bend spring",
     get_in<&Scene::bend, &SpringFamilySpec::damping>,
     set_in<&Scene::bend, &SpringFamilySpec::damping>,
     nullptr},
    {SceneKey::tear_max_stretch,
     "tearing.max_stretch",
     ValueKind::feature,
     "",
     scene_rules::tear_max_stretch,
     {},
     1.6,
     "a spring longer than this many rest lengths tears",
     get_feature<&Scene::tear_max_stretch>,
     set_feature<&Scene::tear_max_stretch>,
     nullptr},
    {SceneKey::strain_limit_max_strain,
     "strain_limit.max_strain",
     ValueKind::feature,
     "",
     scene_rules::strain_limit_max_strain,
     {},
     0.1,
     "springs are held within (1 + max_strain) rest lengths after each step (old name: "
     "max_stretch)",
     get_feature<&Scene::strain_limit_max_strain>,
     set_feature<&Scene::strain_limit_max_strain>,
     nullptr},
    {SceneKey::self_collision_thickness,
     "self_collision.thickness",
     ValueKind::feature,
     "m",
     scene_rules::self_collision_thickness,
     {},
     0.01,
     "particles not joined by a spring are kept this far apart (at most 2 spacings)",
     get_feature<&Scene::self_collision_thickness>,
     set_feature<&Scene::self_collision_thickness>,
     nullptr},
    {SceneKey::gravity,
     "forces.gravity",
     ValueKind::vector,
     "m/s²",
     none,
     {},
     0.0,
     "acceleration of gravity",
     get_in<&Scene::forces, &ForcesSpec::gravity>,
     set_in<&Scene::forces, &ForcesSpec::gravity>,
     nullptr},
    {SceneKey::air_drag,
     "forces.air_drag",
     ValueKind::number,
     "N·s/m",
     scene_rules::air_drag,
     {},
     0.0,
     "per particle: f = -air_drag (v - wind)",
     get_in<&Scene::forces, &ForcesSpec::air_drag>,
     set_in<&Scene::forces, &ForcesSpec::air_drag>,
     nullptr},
    {SceneKey::wind,
     "forces.wind",
     ValueKind::vector,
     "m/s",
     none,
     {},
     0.0,
     "velocity of the air, felt through the air drag",
     get_in<&Scene::forces, &ForcesSpec::wind>,
     set_in<&Scene::forces, &ForcesSpec::wind>,
     nullptr},
    {SceneKey::gust,
     "forces.gust",
     ValueKind::number,
     "",
     scene_rules::gust,
     {},
     0.0,
     "share by which the wind's speed varies in gusts (it veers by half that); 0: steady",
     get_in<&Scene::forces, &ForcesSpec::gust>,
     set_in<&Scene::forces, &ForcesSpec::gust>,
     nullptr},
    {SceneKey::integrator, "solver.integrator", ValueKind::choice, "", none, integrator_names, 0.0,
     "the time-stepping method", get_in<&Scene::solver, &SolverSpec::integrator>,
     set_in<&Scene::solver, &SolverSpec::integrator>, choice_of<Integrator>},
    {SceneKey::dt,
     "solver.dt",
     ValueKind::number,
     "s",
     scene_rules::dt,
     {},
     0.0,
     "time step",
     get_in<&Scene::solver, &SolverSpec::dt>,
     set_in<&Scene::solver, &SolverSpec::dt>,
     nullptr},
    {SceneKey::collider_center,
     "colliders.center",
     ValueKind::vector,
     "m",
     none,
     {},
     0.0,
     "a sphere's centre",
     get_collider<&ColliderSpec::center>,
     set_collider<&ColliderSpec::center>,
     nullptr},
    {SceneKey::collider_radius,
     "colliders.radius",
     ValueKind::number,
     "m",
     scene_rules::collider_radius,
     {},
     0.0,
     "a sphere's radius",
     get_collider<&ColliderSpec::radius>,
     set_collider<&ColliderSpec::radius>,
     nullptr},
    {SceneKey::collider_point,
     "colliders.point",
     ValueKind::vector,
     "m",
     none,
     {},
     0.0,
     "a point of a plane",
     get_collider<&ColliderSpec::point>,
     set_collider<&ColliderSpec::point>,
     nullptr},
    {SceneKey::collider_normal,
     "colliders.normal",
     ValueKind::vector,
     "",
     none,
     {},
     0.0,
     "a plane's normal, towards its free side; any length but zero",
     get_collider<&ColliderSpec::normal>,
     set_collider<&ColliderSpec::normal>,
     nullptr},
    {SceneKey::collider_response, "colliders.response", ValueKind::choice, "", none,
     contact_response_names, 0.0, "impulse contacts, or a penalty force",
     get_collider<&ColliderSpec::response>, set_collider<&ColliderSpec::response>,
     choice_of<ContactResponse>},
    {SceneKey::collider_restitution,
     "colliders.restitution",
     ValueKind::number,
     "",
     scene_rules::restitution,
     {},
     0.0,
     "share of the normal speed kept in a bounce",
     get_collider<&ColliderSpec::restitution>,
     set_collider<&ColliderSpec::restitution>,
     nullptr},
    {SceneKey::collider_friction,
     "colliders.friction",
     ValueKind::number,
     "",
     scene_rules::friction,
     {},
     0.0,
     "Coulomb friction coefficient",
     get_collider<&ColliderSpec::friction>,
     set_collider<&ColliderSpec::friction>,
     nullptr},
    {SceneKey::floor_enabled,
     "floor.enabled",
     ValueKind::flag,
     "",
     none,
     {},
     0.0,
     "the ground drawn under the cloth is a floor it lands on",
     get_top<&Scene::floor_enabled>,
     set_top<&Scene::floor_enabled>,
     nullptr},
    {SceneKey::camera_position,
     "camera.position",
     ValueKind::vector,
     "m",
     none,
     {},
     0.0,
     "where the eye is",
     get_in<&Scene::camera, &CameraSpec::position>,
     set_in<&Scene::camera, &CameraSpec::position>,
     nullptr},
    {SceneKey::camera_target,
     "camera.target",
     ValueKind::vector,
     "m",
     none,
     {},
     0.0,
     "the point the eye looks at",
     get_in<&Scene::camera, &CameraSpec::target>,
     set_in<&Scene::camera, &CameraSpec::target>,
     nullptr},
    {SceneKey::camera_fov_degrees,
     "camera.fov_degrees",
     ValueKind::number,
     "degrees",
     scene_rules::fov_degrees,
     {},
     0.0,
     "vertical field of view",
     get_in<&Scene::camera, &CameraSpec::fov_degrees>,
     set_in<&Scene::camera, &CameraSpec::fov_degrees>,
     nullptr},
};
static_assert(std::size(table) == scene_key_count);

bool table_in_enum_order() {
    for (std::size_t k = 0; k < std::size(table); ++k)
        if (static_cast<std::size_t>(table[k].key) != k) return false;
    return true;
}

std::string shortest(double value) {
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, value).ptr;
    return std::string(text, end);
}

std::string quoted(std::string_view name) {
    std::string text(1, '"');
    text.append(name);
    text.push_back('"');
    return text;
}

std::string value_text(const SceneValue& value, const SceneKeyInfo& info) {
    return std::visit(
        [&](const auto& v) -> std::string {
            using T = std::decay_t<decltype(v)>;
            std::ostringstream out;
            if constexpr (std::is_same_v<T, double>) out << shortest(v);
            if constexpr (std::is_same_v<T, std::int64_t>) out << v;
            if constexpr (std::is_same_v<T, bool>) out << (v ? "true" : "false");
            if constexpr (std::is_same_v<T, Vec3d>)
                out << '[' << shortest(v[0]) << ", " << shortest(v[1]) << ", " << shortest(v[2])
                    << ']';
            if constexpr (std::is_same_v<T, GridPins>)
                out << quoted(pin_preset_names[static_cast<std::size_t>(v.preset)]);
            if constexpr (std::is_same_v<T, FeatureOff>)
                out << "off (table absent); " << shortest(info.feature_default)
                    << " when the table is given";
            if constexpr (std::is_enum_v<T>)
                out << quoted(info.choices[static_cast<std::size_t>(v)]);
            return out.str();
        },
        value);
}

std::string range_text(const SceneKeyInfo& info) {
    switch (info.kind) {
        case ValueKind::count:
            return "1 to " + std::to_string(max_particles) + " (rows × cols at most that)";
        case ValueKind::flag:
            return "true, false";
        case ValueKind::vector:
            return "3 finite numbers";
        case ValueKind::pins:
        case ValueKind::choice: {
            std::ostringstream names;
            for (std::size_t i = 0; i < info.choices.size(); ++i)
                names << (i ? ", " : "") << quoted(info.choices[i]);
            if (info.kind == ValueKind::pins) names << ", or [[row, col], ...]";
            return names.str();
        }
        case ValueKind::number:
        case ValueKind::feature: {
            const NumberRule& rule = info.rule;
            std::ostringstream text;
            if (rule.minimum)
                text << (rule.exclusive_minimum ? "> " : "≥ ") << shortest(*rule.minimum);
            if (rule.minimum && rule.maximum) text << " and ";
            if (rule.maximum)
                text << (rule.exclusive_maximum ? "< " : "≤ ") << shortest(*rule.maximum);
            if (!rule.minimum && !rule.maximum) text << "any finite number";
            if (info.kind == ValueKind::feature) text << ", or false (off)";
            return text.str();
        }
    }
    return "";
}

}  // namespace

std::span<const SceneKeyInfo> scene_key_table() {
    static const bool ordered = table_in_enum_order();
    if (!ordered) std::abort();  // a programming error in the table above
    return table;
}

const SceneKeyInfo& scene_key_info(SceneKey key) {
    return scene_key_table()[static_cast<std::size_t>(key)];
}

std::string scene_format_markdown() {
    Scene defaults;
    defaults.colliders.emplace_back();  // a collider's defaults
    std::ostringstream out;
    out << "# Scene format\n\n"
           "<!-- Written by weft-make-scene-format from src/sim/scene/scene_keys.cpp; the test\n"
           "     tools.scene_format checks that it matches. Do not edit by hand. -->\n\n"
           "A scene file is TOML. Every key has a default, so a file names only what it changes;\n"
           "an empty file is a 24 × 24 sheet of these defaults. Anything wrong (an unknown key, a "
           "wrong type, a\n"
           "value out of its range) is refused with an error that names the file, line and\n"
           "column, and nothing runs. `--set KEY=VALUE` takes the same keys by their dotted\n"
           "paths, checked alike; the panel and a recording change the same keys by typed\n"
           "edits, checked by the same rules.\n\n"
           "## Keys that edits can change\n\n"
           "| key | unit | default | range | meaning |\n"
           "|---|---|---|---|---|\n";
    for (const SceneKeyInfo& info : scene_key_table()) {
        out << "| `" << info.name << "` | " << (info.unit.empty() ? "–" : info.unit) << " | "
            << value_text(info.get(defaults, 0), info) << " | " << range_text(info) << " | "
            << info.doc << " |\n";
    }
    out << "\nA collider's keys belong to one `[[colliders]]` entry; `--set` and edits name it by\n"
           "its index, as in `colliders.0.radius`. An optional feature's table ([tearing],\n"
           "[strain_limit], [self_collision]) switches the feature on; in an edit, `false`\n"
           "switches it off.\n\n"
           "## Keys only a scene file gives\n\n"
           "| key | meaning |\n"
           "|---|---|\n"
           "| `name` | the scene's title, shown in the window |\n"
           "| `cloth.mesh` | an OBJ file of triangles or quads, relative to the scene file: the "
           "cloth "
           "is that mesh instead of a grid (then the grid's keys are refused) |\n"
           "| `cloth.pins` (mesh) | `\"none\"`, or a list of vertex numbers as in the OBJ "
           "(from 1) |\n"
           "| `cloth.pin_group` | a mesh: the OBJ group (`g` or `o`) whose vertices are pinned |\n"
           "| `colliders.type` | `\"sphere\"` or `\"plane\"` (default `\"sphere\"`) |\n";
    return out.str();
}

}  // namespace weft
