#include "sim/scene_io/scene_toml_mesh.h"

#include <filesystem>

#include "sim/build/mesh_builder.h"
#include "sim/scene/obj_reader.h"

namespace weft {
namespace {

void read_mesh_pins(TomlReader& reader, const toml::table& cloth, ClothSpec& spec) {
    const toml::node* pins = cloth.get("pins");
    const toml::node* group = cloth.get("pin_group");
    spec.pin_preset = PinPreset::none;  // a mesh has no corners to pin by default
    spec.pin_list.clear();
    spec.pin_vertices.clear();
    spec.pin_group.clear();
    if (reader.failed()) return;
    if (pins && group) {
        reader.fail(*group, "cloth.pin_group",
                    "cloth.pins and cloth.pin_group cannot both be given: choose one");
        return;
    }
    if (group) {
        if (!reader.read_string(cloth, "cloth", "pin_group", spec.pin_group)) return;
        if (spec.pin_group.empty()) {
            reader.fail(*group, "cloth.pin_group", "cloth.pin_group must name a group of the OBJ");
            return;
        }
        spec.pin_preset = PinPreset::group;
        return;
    }
    if (!pins) return;
    const auto* list = pins->as_array();
    if (pins->is_string() && pins->as_string()->get() == "none") return;
    if (!list) {
        reader.fail(*pins, "cloth.pins",
                    "a mesh's cloth.pins must be \"none\" or a list of vertex numbers (1 is the "
                    "OBJ's first vertex), got " +
                        (pins->is_string() ? "\"" + pins->as_string()->get() + "\""
                                           : describe_type(*pins)));
        return;
    }
    spec.pin_preset = PinPreset::vertices;
    for (const toml::node& entry : *list) {
        if (!entry.is_integer() || entry.as_integer()->get() < 1) {
            reader.fail(entry, "cloth.pins",
                        "each pin of a mesh is a vertex number, an integer from 1 (the OBJ's "
                        "first vertex)");
            return;
        }
        spec.pin_vertices.push_back(entry.as_integer()->get());
    }
}

}  // namespace

void read_mesh_keys(TomlReader& reader, const toml::table& cloth, ClothSpec& spec) {
    for (const char* key : {"rows", "cols", "spacing", "layout", "orientation"})
        if (const toml::node* node = cloth.get(key)) {
            reader.fail(*node, std::string("cloth.") + key,
                        not_for_mesh(std::string("cloth.") + key));
            return;
        }
    if (!reader.read_string(cloth, "cloth", "mesh", spec.mesh)) return;
    if (spec.mesh.empty()) {
        reader.fail(*cloth.get("mesh"), "cloth.mesh", "cloth.mesh must name an OBJ file");
        return;
    }
    // Two ways to weigh the vertices: lumped from the triangles' areas (density), or all
    // alike (particle_mass), as the grid builder weighs its particles, so that a grid
    // written as OBJ can be the same material as the grid's sheet.
    const toml::node* particle_mass = cloth.get("particle_mass");
    if (particle_mass && cloth.get("density")) {
        reader.fail(*particle_mass, "cloth.particle_mass", both_mesh_masses());
        return;
    }
    spec.mesh_particle_mass = particle_mass != nullptr;
    if (particle_mass)
        reader.read_number(cloth, "cloth", "particle_mass", spec.particle_mass,
                           scene_rules::particle_mass);
    else
        reader.read_number(cloth, "cloth", "density", spec.density, scene_rules::density);
    reader.read_vec3(cloth, "cloth", "origin", spec.origin);
    read_mesh_pins(reader, cloth, spec);
}

std::optional<double> load_scene_mesh(TomlReader& reader, const toml::table& root,
                                      std::string_view source_name, ClothSpec& spec) {
    if (reader.failed() || spec.mesh.empty()) return std::nullopt;
    const toml::table& cloth = *root.get("cloth")->as_table();
    const toml::node& mesh_node = *cloth.get("mesh");
    namespace fs = std::filesystem;
    // Relative to the scene file's folder; absolute, so that the scene written back (live
    // edits, saving, recordings) names the same file wherever it is read from.
    fs::path path = fs::path(spec.mesh);
    if (path.is_relative()) path = fs::path(source_name).parent_path() / path;
    std::error_code ignored;
    const fs::path absolute = fs::absolute(path, ignored);
    spec.mesh = (absolute.empty() ? path : absolute).lexically_normal().string();
    try {
        auto mesh = std::make_shared<ObjMesh>(read_obj_file(spec.mesh));
        const MeshTopology topology = derive_mesh_topology(*mesh);
        if (auto problem = mesh_pin_problem(spec, *mesh)) {
            const toml::node* pins =
                cloth.get(spec.pin_preset == PinPreset::group ? "pin_group" : "pins");
            reader.fail(pins ? *pins : mesh_node,
                        spec.pin_preset == PinPreset::group ? "cloth.pin_group" : "cloth.pins",
                        *problem);
            return std::nullopt;
        }
        double total = 0.0;
        for (const Spring& spring : topology.structural) total += spring.rest_length;
        spec.mesh_data.obj = std::move(mesh);
        spec.mesh_data.mean_edge_length = total / static_cast<double>(topology.structural.size());
        return spec.mesh_data.mean_edge_length;
    } catch (const ObjError& error) {
        if (error.line() > 0)
            reader.fail_with(SceneError{error.where(), error.reason()});
        else  // the file as a whole: said at the key that names it
            reader.fail(mesh_node, "cloth.mesh", error.path() + ": " + error.reason());
        return std::nullopt;
    }
}

}  // namespace weft
