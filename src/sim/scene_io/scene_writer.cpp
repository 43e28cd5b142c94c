#include "sim/scene_io/scene_writer.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "sim/scene/scene_keys.h"
#include "sim/scene_io/scene_edit_toml.h"

namespace weft {
namespace {

// Writes the keys the key table lists under `section` as `leaf = value  # unit`, in the
// table's order, except the keys `skip` names.
void write_keys(std::ostringstream& out, const Scene& scene, std::string_view section,
                std::uint32_t collider = 0, std::initializer_list<std::string_view> skip = {}) {
    for (const SceneKeyInfo& info : scene_key_table()) {
        const std::string_view leaf = info.leaf();
        if (info.section() != section || std::find(skip.begin(), skip.end(), leaf) != skip.end())
            continue;
        out << leaf << " = " << scene_value_toml(info.get(scene, collider));
        if (!info.unit.empty()) out << "  # " << info.unit;
        out << "\n";
    }
}

void spring_family(std::ostringstream& out, const Scene& scene, std::string_view name,
                   bool always_on) {
    const std::string section = "springs." + std::string(name);
    out << "\n[" << section << "]\n";
    if (always_on)
        write_keys(out, scene, section, 0, {"enabled"});
    else
        write_keys(out, scene, section);
}

// A grid's keys.
void grid_cloth(std::ostringstream& out, const Scene& scene) {
    write_keys(out, scene, "cloth", 0, {"density"});  // a mesh's
}

// A mesh's keys: the grid's do not apply (the loader refuses them beside `mesh`).
void mesh_cloth(std::ostringstream& out, const ClothSpec& cloth) {
    out << "mesh = " << toml_string(cloth.mesh) << "\n";
    if (cloth.mesh_particle_mass)
        out << "particle_mass = " << toml_number(cloth.particle_mass) << "  # kg, every vertex\n";
    else
        out << "density = " << toml_number(cloth.density) << "  # kg/m²\n";
    out << "origin = " << scene_value_toml(cloth.origin) << "  # m\n";
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
        grid_cloth(out, scene);
    }

    spring_family(out, scene, spring_family_names[0], true);
    spring_family(out, scene, spring_family_names[1], false);
    spring_family(out, scene, spring_family_names[2], false);

    if (scene.tear_max_stretch)
        out << "\n[tearing]\nmax_stretch = " << toml_number(*scene.tear_max_stretch) << "\n";
    if (scene.strain_limit_max_strain)
        out << "\n[strain_limit]\nmax_strain = " << toml_number(*scene.strain_limit_max_strain)
            << "\n";
    if (scene.self_collision_thickness)
        out << "\n[self_collision]\nthickness = " << toml_number(*scene.self_collision_thickness)
            << "  # m\n";

    out << "\n[forces]\n";
    // gust only when the wind gusts, so a steady scene reads as it did before gusts.
    if (scene.forces.gust != 0.0)
        write_keys(out, scene, "forces");
    else
        write_keys(out, scene, "forces", 0, {"gust"});

    out << "\n[solver]\n";
    write_keys(out, scene, "solver");

    for (std::uint32_t c = 0; c < scene.colliders.size(); ++c) {
        out << "\n[[colliders]]\n";
        // Both shapes' keys, so the collider reads back field for field whatever its type.
        out << "type = \"" << collider_type_names[static_cast<std::size_t>(scene.colliders[c].type)]
            << "\"\n";
        write_keys(out, scene, "colliders", c);
    }
    // Written only when off, so a scene with the floor reads as it did before there was one.
    if (!scene.floor_enabled) out << "\n[floor]\nenabled = false\n";

    out << "\n[camera]\n";
    write_keys(out, scene, "camera");
    return out.str();
}

}  // namespace weft
