#include "sim/scene_writer.h"

#include <cstdio>
#include <sstream>

namespace weft {
namespace {

std::string vec3(const Vec3d& v) {
    std::string text = "[";
    for (int k = 0; k < 3; ++k) text.append(k ? ", " : "").append(toml_number(v[k]));
    return text.append("]");
}

void spring_family(std::ostringstream& out, std::string_view name, const SpringFamilySpec& spec,
                   bool always_on) {
    out << "\n[springs." << name << "]\n";
    if (!always_on) out << "enabled = " << (spec.enabled ? "true" : "false") << "\n";
    out << "stiffness = " << toml_number(spec.stiffness) << "  # N/m\n";
    out << "damping = " << toml_number(spec.damping) << "  # N·s/m\n";
}

// A grid's keys.
void grid_cloth(std::ostringstream& out, const ClothSpec& cloth) {
    out << "rows = " << cloth.rows << "\ncols = " << cloth.cols << "\n";
    out << "spacing = " << toml_number(cloth.spacing) << "  # m\n";
    out << "particle_mass = " << toml_number(cloth.particle_mass) << "  # kg\n";
    out << "layout = \"" << layout_name(cloth.layout) << "\"\n";
    out << "orientation = \"" << orientation_name(cloth.orientation) << "\"\n";
    out << "origin = " << vec3(cloth.origin) << "  # m\n";
    if (const char* preset = pin_preset_name(cloth.pin_preset)) {
        out << "pins = \"" << preset << "\"\n";
    } else {
        out << "pins = [";
        for (std::size_t p = 0; p < cloth.pin_list.size(); ++p)
            out << (p ? ", " : "") << "[" << cloth.pin_list[p].row << ", " << cloth.pin_list[p].col
                << "]";
        out << "]\n";
    }
}

// A mesh's keys: the grid's do not apply (the loader refuses them beside `mesh`).
void mesh_cloth(std::ostringstream& out, const ClothSpec& cloth) {
    out << "mesh = " << toml_string(cloth.mesh) << "\n";
    if (cloth.mesh_particle_mass)
        out << "particle_mass = " << toml_number(cloth.particle_mass) << "  # kg, every vertex\n";
    else
        out << "density = " << toml_number(cloth.density) << "  # kg/m²\n";
    out << "origin = " << vec3(cloth.origin) << "  # m\n";
    if (cloth.pin_preset == PinPreset::group) {
        out << "pin_group = " << toml_string(cloth.pin_group) << "\n";
    } else if (cloth.pin_preset == PinPreset::vertices) {
        out << "pins = [";
        for (std::size_t p = 0; p < cloth.pin_vertices.size(); ++p)
            out << (p ? ", " : "") << cloth.pin_vertices[p];
        out << "]\n";
    } else {
        out << "pins = \"none\"\n";
    }
}

}  // namespace

std::string toml_number(double value) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", value);
    std::string s = text;
    if (s.find_first_of(".eEn") == std::string::npos) s += ".0";  // "n": nan/inf never occur
    return s;
}

std::string toml_string(const std::string& text) {
    std::string out(1, '"');
    for (unsigned char c : text) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += static_cast<char>(c);
        } else if (c < 0x20 || c == 0x7f) {
            char escape[8];
            std::snprintf(escape, sizeof escape, "\\u%04x", c);
            out += escape;
        } else {
            out += static_cast<char>(c);
        }
    }
    out += '"';
    return out;
}

std::string scene_to_toml(const Scene& scene) {
    std::ostringstream out;
    out << "# Saved by weft.\nname = " << toml_string(scene.name) << "\n";

    const ClothSpec& cloth = scene.cloth;
    out << "\n[cloth]\n";
    if (!cloth.mesh.empty()) {
        mesh_cloth(out, cloth);
    } else {
        grid_cloth(out, cloth);
    }

    spring_family(out, spring_family_names[0], scene.structural, true);
    spring_family(out, spring_family_names[1], scene.shear, false);
    spring_family(out, spring_family_names[2], scene.bend, false);

    if (scene.tear_max_stretch)
        out << "\n[tearing]\nmax_stretch = " << toml_number(*scene.tear_max_stretch) << "\n";
    if (scene.strain_limit_max_strain)
        out << "\n[strain_limit]\nmax_strain = " << toml_number(*scene.strain_limit_max_strain)
            << "\n";
    if (scene.self_collision_thickness)
        out << "\n[self_collision]\nthickness = " << toml_number(*scene.self_collision_thickness)
            << "  # m\n";

    out << "\n[forces]\n";
    out << "gravity = " << vec3(scene.forces.gravity) << "  # m/s²\n";
    out << "air_drag = " << toml_number(scene.forces.air_drag) << "  # N·s/m per particle\n";
    out << "wind = " << vec3(scene.forces.wind) << "  # m/s\n";
    if (scene.forces.gust != 0.0)
        out << "gust = " << toml_number(scene.forces.gust) << "  # share of the wind\n";

    out << "\n[solver]\n";
    out << "integrator = \"" << integrator_name(scene.solver.integrator) << "\"\n";
    out << "dt = " << toml_number(scene.solver.dt) << "  # s\n";

    for (const ColliderSpec& collider : scene.colliders) {
        out << "\n[[colliders]]\n";
        // Both shapes' keys, so the collider reads back field for field whatever its type.
        out << "type = \"" << collider_type_names[static_cast<std::size_t>(collider.type)]
            << "\"\n";
        out << "center = " << vec3(collider.center) << "  # m, sphere\n";
        out << "radius = " << toml_number(collider.radius) << "  # m, sphere\n";
        out << "point = " << vec3(collider.point) << "  # m, plane\n";
        out << "normal = " << vec3(collider.normal) << "  # plane\n";
        out << "response = \"" << contact_response_name(collider.response) << "\"\n";
        out << "restitution = " << toml_number(collider.restitution) << "\n";
        out << "friction = " << toml_number(collider.friction) << "\n";
    }
    // Written only when off, so a scene with the floor reads as it did before there was one.
    if (!scene.floor_enabled) out << "\n[floor]\nenabled = false\n";

    out << "\n[camera]\n";
    out << "position = " << vec3(scene.camera.position) << "  # m\n";
    out << "target = " << vec3(scene.camera.target) << "  # m\n";
    out << "fov_degrees = " << toml_number(scene.camera.fov_degrees) << "\n";
    return out.str();
}

}  // namespace weft
