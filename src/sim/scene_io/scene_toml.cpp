// Scene loading (scene_loader.h): the keys of the design notes' scene format, read from a
// TOML document with TomlReader, after the --set overrides have been written into it.
//
// Overrides go into the document before anything is checked, so a value from --set passes
// exactly the checks a value from the file does; TomlReader reports it as "--set KEY".
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "sim/scene/scene_keys.h"
#include "sim/scene_io/scene_loader.h"
#include "sim/scene_io/scene_toml_mesh.h"
#include "sim/scene_io/toml_input_guard.h"
#include "sim/scene_io/toml_reader.h"

namespace weft {

const char* layout_name(Layout layout) {
    return layout_names[static_cast<std::size_t>(layout)].data();
}

const char* orientation_name(Orientation orientation) {
    return orientation_names[static_cast<std::size_t>(orientation)].data();
}

const char* pin_preset_name(PinPreset preset) {
    const auto index = static_cast<std::size_t>(preset);
    return index < pin_preset_names.size() ? pin_preset_names[index].data() : nullptr;
}

const char* integrator_name(Integrator integrator) {
    return integrator_names[static_cast<std::size_t>(integrator)].data();
}

const char* contact_response_name(ContactResponse response) {
    return contact_response_names[static_cast<std::size_t>(response)].data();
}

std::optional<Integrator> integrator_from_name(std::string_view name) {
    for (std::size_t i = 0; i < integrator_names.size(); ++i)
        if (name == integrator_names[i]) return static_cast<Integrator>(i);
    return std::nullopt;
}

namespace {

// The keys the key table lists directly under `section` ("forces", "springs.shear",
// "colliders"), by their last name, in the table's order; then `extra`, the section's keys
// that only a file gives.
std::vector<std::string_view> section_keys(std::string_view section,
                                           std::initializer_list<std::string_view> extra = {}) {
    std::vector<std::string_view> keys;
    for (const SceneKeyInfo& info : scene_key_table())
        if (info.section() == section) keys.push_back(info.leaf());
    keys.insert(keys.end(), extra.begin(), extra.end());
    return keys;
}

int choice_index(const SceneValue& value) {
    return std::visit(
        [](const auto& v) {
            if constexpr (std::is_enum_v<std::decay_t<decltype(v)>>) return static_cast<int>(v);
            return 0;
        },
        value);
}

// Reads the keys of `table` that the key table lists under `section` and that are plain
// values (numbers, flags, vectors, choices), each by its kind and rule, in the table's
// order, into `scene` (into its collider `collider` for a collider's keys). A key the file
// leaves out keeps the value `scene` has. Counts, pins and optional features have reads
// of their own, which join keys.
void read_plain_keys(TomlReader& reader, const toml::table& table, std::string_view section,
                     Scene& scene, std::uint32_t collider = 0) {
    const std::string path(section);
    for (const SceneKeyInfo& info : scene_key_table()) {
        if (info.section() != section) continue;
        const std::string_view leaf = info.leaf();
        const SceneValue current = info.get(scene, collider);
        switch (info.kind) {
            case ValueKind::number: {
                double number = std::get<double>(current);
                if (reader.read_number(table, path, leaf, number, info.rule))
                    info.set(scene, number, collider);
                break;
            }
            case ValueKind::flag: {
                bool flag = std::get<bool>(current);
                if (reader.read_bool(table, path, leaf, flag)) info.set(scene, flag, collider);
                break;
            }
            case ValueKind::vector: {
                Vec3d vector = std::get<Vec3d>(current);
                if (reader.read_vec3(table, path, leaf, vector)) info.set(scene, vector, collider);
                break;
            }
            case ValueKind::choice: {
                int index = choice_index(current);
                if (reader.read_choice(table, path, leaf, info.choices, index))
                    info.set(scene, info.choice_value(index), collider);
                break;
            }
            case ValueKind::count:
            case ValueKind::pins:
            case ValueKind::feature:
                break;
        }
    }
}

// Reads a table of a spring family. For shear and bend, the table being there means the
// family is wanted unless it says `enabled = false`.
void read_spring_family(TomlReader& reader, const toml::table& springs, std::string_view family,
                        SpringFamilySpec& spec, Scene& scene) {
    const std::string path = TomlReader::join("springs", family);
    const toml::table* table = reader.sub_table(springs, "springs", family);
    if (!table) return;
    reader.check_keys(*table, path, section_keys(path));
    spec.enabled = true;
    read_plain_keys(reader, *table, path, scene);
}

void read_pins(TomlReader& reader, const toml::table& cloth, ClothSpec& spec) {
    const toml::node* node = cloth.get("pins");
    if (!node || reader.failed()) return;
    if (node->is_string()) {
        int preset = 0;
        if (reader.read_choice(cloth, "cloth", "pins", pin_preset_names, preset))
            spec.pin_preset = static_cast<PinPreset>(preset);
        return;
    }
    const auto* list = node->as_array();
    if (!list) {
        reader.fail(*node, "cloth.pins",
                    "cloth.pins must be \"none\", \"top-corners\", \"top-row\" or a list of "
                    "[row, col], got " +
                        describe_type(*node));
        return;
    }
    spec.pin_preset = PinPreset::list;
    spec.pin_list.clear();
    for (const toml::node& entry : *list) {
        const auto* pair = entry.as_array();
        const bool is_pair =
            pair && pair->size() == 2 && pair->get(0)->is_integer() && pair->get(1)->is_integer();
        if (!is_pair) {
            reader.fail(entry, "cloth.pins", "each pin must be [row, col] with two integers");
            return;
        }
        const std::int64_t row = pair->get(0)->as_integer()->get();
        const std::int64_t col = pair->get(1)->as_integer()->get();
        if (!reader.check(entry, "cloth.pins", pin_problem(row, col, spec.rows, spec.cols))) return;
        spec.pin_list.push_back({static_cast<int>(row), static_cast<int>(col)});
    }
}

void read_cloth(TomlReader& reader, const toml::table& root, Scene& scene) {
    const toml::table* cloth = reader.sub_table(root, "", "cloth");
    if (!cloth) return;
    ClothSpec& spec = scene.cloth;
    reader.check_keys(*cloth, "cloth", section_keys("cloth", {"mesh", "pin_group"}));
    if (cloth->get("mesh")) return read_mesh_keys(reader, *cloth, spec);
    for (const char* key : {"density", "pin_group"})
        if (const toml::node* node = cloth->get(key); node && !reader.failed())
            reader.fail(*node, std::string("cloth.") + key,
                        only_for_mesh(std::string("cloth.") + key));
    std::int64_t rows = spec.rows, cols = spec.cols;
    for (auto [key, count] : {std::pair{"rows", &rows}, std::pair{"cols", &cols}})
        if (reader.read_int(*cloth, "cloth", key, *count) && cloth->get(key))
            reader.check(*cloth->get(key), std::string("cloth.") + key,
                         grid_count_problem(std::string("cloth.") + key, *count));
    if (!reader.failed()) {
        // Blame the key the scene set (the larger one if it set both).
        const char* key =
            cloth->get("rows") && (rows >= cols || !cloth->get("cols")) ? "rows" : "cols";
        if (const toml::node* node = cloth->get(key))
            reader.check(*node, std::string("cloth.") + key, grid_size_problem(rows, cols));
    }
    spec.rows = static_cast<int>(rows);
    spec.cols = static_cast<int>(cols);
    read_plain_keys(reader, *cloth, "cloth", scene);  // density: refused on a grid above
    read_pins(reader, *cloth, spec);
}

void read_springs(TomlReader& reader, const toml::table& root, Scene& scene) {
    const toml::table* springs = reader.sub_table(root, "", "springs");
    if (!springs) return;
    reader.check_keys(*springs, "springs", spring_family_names);
    read_spring_family(reader, *springs, spring_family_names[0], scene.structural, scene);
    read_spring_family(reader, *springs, spring_family_names[1], scene.shear, scene);
    read_spring_family(reader, *springs, spring_family_names[2], scene.bend, scene);
    if (!reader.failed() && !scene.structural.enabled) {
        const toml::node& node = *springs->get(spring_family_names[0])->as_table()->get("enabled");
        reader.check(node, "springs.structural.enabled",
                     structural_enabled_problem(scene.structural.enabled));
    }
}

// An optional single-key table such as [tearing]: absent means the feature is off; present
// means on, with the key's value or its default.
void read_optional_feature(TomlReader& reader, const toml::table& root, SceneKey key,
                           Scene& scene) {
    const SceneKeyInfo& info = scene_key_info(key);
    const std::string path(info.section());
    const std::string_view leaf = info.leaf();
    const toml::table* table = reader.sub_table(root, "", path);
    if (!table) return;
    reader.check_keys(*table, path, {leaf});
    double value = info.feature_default;
    reader.read_number(*table, path, leaf, value, info.rule);
    info.set(scene, value, 0);
}

// [strain_limit] max_strain, a strain (0.1: springs are held within 10 % of their rest
// length). Its old name, max_stretch, is what [tearing] calls a ratio of lengths (1.6: torn
// at 160 %); a scene that still says it loads, with a warning, and the value means the same.
void read_strain_limit(TomlReader& reader, const toml::table& root, Scene& scene) {
    const toml::table* table = reader.sub_table(root, "", "strain_limit");
    if (!table) return;
    if (!reader.check_keys(*table, "strain_limit", {"max_strain", "max_stretch"})) return;
    const toml::node* old_name = table->get("max_stretch");
    if (old_name && table->contains("max_strain")) {
        reader.fail(*old_name, "strain_limit.max_stretch",
                    "strain_limit.max_stretch is the old name of strain_limit.max_strain: give "
                    "max_strain alone");
        return;
    }
    const SceneKeyInfo& info = scene_key_info(SceneKey::strain_limit_max_strain);
    double value = info.feature_default;
    if (!reader.read_number(*table, "strain_limit", old_name ? "max_stretch" : "max_strain", value,
                            info.rule))
        return;
    scene.strain_limit_max_strain = value;
    if (old_name)
        reader.warn(*old_name, "strain_limit.max_stretch",
                    "strain_limit.max_stretch is the old name of strain_limit.max_strain (the "
                    "same strain: " +
                        format_number(value) + ", " + format_number(100.0 * value) +
                        " % over rest length); rename it");
}

void read_forces_and_solver(TomlReader& reader, const toml::table& root, Scene& scene) {
    for (const char* section : {"forces", "solver"}) {
        if (const toml::table* table = reader.sub_table(root, "", section)) {
            reader.check_keys(*table, section, section_keys(section));
            read_plain_keys(reader, *table, section, scene);
        }
    }
}

void read_colliders(TomlReader& reader, const toml::table& root, Scene& scene) {
    const toml::node* node = root.get("colliders");
    if (!node || reader.failed()) return;
    const auto* list = node->as_array();
    if (!list) {
        reader.fail(*node, "colliders", "colliders must be an array of tables ([[colliders]])");
        return;
    }
    for (const toml::node& entry : *list) {
        const auto* table = entry.as_table();
        if (!table) {
            reader.fail(entry, "colliders", "each collider must be a table");
            return;
        }
        reader.check_keys(*table, "colliders", section_keys("colliders", {"type"}));
        int type = 0;
        reader.read_choice(*table, "colliders", "type", collider_type_names, type);
        scene.colliders.emplace_back().type = static_cast<ColliderType>(type);
        const auto index = static_cast<std::uint32_t>(scene.colliders.size() - 1);
        read_plain_keys(reader, *table, "colliders", scene, index);
        if (const toml::node* normal = table->get("normal");
            normal && !reader.check(*normal, "colliders.normal",
                                    normal_problem(scene.colliders[index].normal)))
            return;
    }
}

void read_camera(TomlReader& reader, const toml::table& root, Scene& scene) {
    const toml::table* camera = reader.sub_table(root, "", "camera");
    if (!camera) return;
    reader.check_keys(*camera, "camera", section_keys("camera"));
    read_plain_keys(reader, *camera, "camera", scene);
}

// Writes one "KEY=VALUE" override into the document.
std::optional<SceneError> apply_override(toml::table& root, const std::string& override_text,
                                         std::set<std::string>& overridden) {
    std::string key;
    toml::table snippet;
    if (auto error = parse_override(override_text, key, snippet)) return error;
    const toml::node* value = snippet.get("value");
    const std::string where = "--set " + key;

    toml::table* table = &root;
    std::string path;
    for (std::size_t start = 0;;) {
        const auto dot = key.find('.', start);
        const std::string segment = key.substr(start, dot == std::string::npos ? dot : dot - start);
        if (dot == std::string::npos) {
            value->visit([&](const auto& concrete) { table->insert_or_assign(segment, concrete); });
            overridden.insert(key);
            return std::nullopt;
        }
        path = TomlReader::join(path, segment);
        toml::node* next = table->get(segment);
        if (!next) next = &table->insert_or_assign(segment, toml::table{}).first->second;
        table = next->as_table();
        if (!table)
            return SceneError{where,
                              path + " is " + describe_type(*next) + ", not a table of keys"};
        start = dot + 1;
    }
}

}  // namespace

SceneLoadResult load_scene_text(std::string_view toml_text, std::string_view source_name,
                                const std::vector<std::string>& overrides) {
    SceneLoadResult result;
    const std::string source(source_name);
    if (auto unsafe = find_unsafe_non_ascii(toml_text)) {
        result.error = SceneError{
            source + ":" + std::to_string(unsafe->line) + ":" + std::to_string(unsafe->column),
            "non-ASCII character outside a string or comment"};
        return result;
    }
    toml::table root;
    try {
        root = toml::parse(toml_text, source);
    } catch (const toml::parse_error& error) {
        const auto& begin = error.source().begin;
        result.error = SceneError{
            source + ":" + std::to_string(begin.line) + ":" + std::to_string(begin.column),
            std::string(error.description())};
        return result;
    }
    std::set<std::string> overridden;
    for (const std::string& override_text : overrides) {
        if (auto error = apply_override(root, override_text, overridden)) {
            result.error = error;
            return result;
        }
    }

    TomlReader reader(source, overridden);
    Scene scene;
    reader.check_keys(root, "",
                      {"name", "cloth", "springs", "tearing", "strain_limit", "self_collision",
                       "forces", "solver", "colliders", "floor", "camera"});
    reader.read_string(root, "", "name", scene.name);
    read_cloth(reader, root, scene);
    const std::optional<double> mesh_spacing =
        load_scene_mesh(reader, root, source_name, scene.cloth);
    const double spacing = mesh_spacing.value_or(scene.cloth.spacing);  // m
    read_springs(reader, root, scene);
    read_optional_feature(reader, root, SceneKey::tear_max_stretch, scene);
    read_strain_limit(reader, root, scene);
    read_optional_feature(reader, root, SceneKey::self_collision_thickness, scene);
    if (!reader.failed() && scene.self_collision_thickness) {
        const toml::table& table = *root["self_collision"].as_table();
        const toml::node* node = table.get("thickness");
        reader.check(
            node ? *node : static_cast<const toml::node&>(table), "self_collision.thickness",
            thickness_problem(*scene.self_collision_thickness, spacing, mesh_spacing.has_value()));
    }
    read_forces_and_solver(reader, root, scene);
    read_colliders(reader, root, scene);
    if (const toml::table* floor = reader.sub_table(root, "", "floor")) {
        reader.check_keys(*floor, "floor", section_keys("floor"));
        read_plain_keys(reader, *floor, "floor", scene);
    }
    read_camera(reader, root, scene);
    if (reader.failed()) {
        result.error = reader.error();
        return result;
    }

    result.scene = std::move(scene);
    result.warnings = reader.warnings();
    return result;
}

SceneLoadResult load_scene_file(const std::string& path,
                                const std::vector<std::string>& overrides) {
    // On Linux a directory opens as a stream that reads as empty, and an empty scene is the
    // default sheet: without this check `weft assets/scenes` would run that sheet silently.
    std::error_code ignored;
    if (std::filesystem::is_directory(path, ignored)) {
        SceneLoadResult result;
        result.error = SceneError{path, "is a directory, not a scene file"};
        return result;
    }
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        SceneLoadResult result;
        result.error = SceneError{path, std::string("cannot read file: ") + std::strerror(errno)};
        return result;
    }
    std::ostringstream text;
    text << file.rdbuf();
    return load_scene_text(text.str(), path, overrides);
}

}  // namespace weft
