// Scene loading, the mesh part (scene_toml.cpp reads the rest): the [cloth] keys of a mesh
// cloth, and the OBJ file they name, read and checked while the scene loads so that a bad
// mesh is refused like any other bad input, with the OBJ's file and line.
#pragma once

#include <toml++/toml.h>
#include <optional>
#include <string_view>

#include "sim/scene/scene.h"
#include "sim/scene_io/toml_reader.h"

namespace weft {

// The keys of [cloth] when it has `mesh`: mesh, density or particle_mass (not both), origin,
// pins ("none" or vertex numbers), pin_group. The grid's other keys are refused with it.
void read_mesh_keys(TomlReader& reader, const toml::table& cloth, ClothSpec& spec);

// Reads the OBJ that cloth.mesh names, relative to the folder of `source_name` (the scene
// file), into spec.mesh_data, with spec.mesh made absolute so the scene reads back the same
// from anywhere. Checks the mesh's topology and pins. Returns the mesh's mean structural rest
// length (m), the spacing other checks measure against; nullopt after an error or for a grid.
std::optional<double> load_scene_mesh(TomlReader& reader, const toml::table& root,
                                      std::string_view source_name, ClothSpec& spec);

}  // namespace weft
