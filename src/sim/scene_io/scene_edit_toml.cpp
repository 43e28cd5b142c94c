#include "sim/scene_io/scene_edit_toml.h"

#include <charconv>

#include "sim/scene_io/scene_writer.h"

namespace weft {
namespace {

// Splits "colliders.2.radius" into the key "colliders.radius" and the index 2.
bool split_collider_index(const std::string& key, std::string& plain, std::uint32_t& index) {
    const auto first = key.find('.');
    const auto second = key.find('.', first + 1);
    if (key.compare(0, first, "colliders") != 0 || second == std::string::npos) return false;
    const char* begin = key.data() + first + 1;
    const char* end = key.data() + second;
    auto [stop, error] = std::from_chars(begin, end, index);
    if (error != std::errc{} || stop != end || begin == end) return false;
    plain = "colliders" + key.substr(second);
    return true;
}

}  // namespace

namespace {

std::optional<SceneEdit> read_typed(TomlReader& reader, const std::string& key,
                                    const toml::node& value);

}  // namespace

std::optional<SceneEdit> read_scene_edit(TomlReader& reader, const std::string& key,
                                         const toml::node& value) {
    // The typed reads below see a copy of the value, which toml++ gives no position: an
    // error is said again at the value itself, where the file has it.
    TomlReader typed("", {});
    std::optional<SceneEdit> edit = read_typed(typed, key, value);
    if (!edit && typed.error()) reader.fail(value, key, typed.error()->what);
    return edit;
}

namespace {

std::optional<SceneEdit> read_typed(TomlReader& reader, const std::string& key,
                                    const toml::node& value) {
    SceneEdit edit;
    std::string plain = key;
    const bool indexed = split_collider_index(key, plain, edit.collider);
    // The strain limit's old name, as a recording made before the rename has it (the scene
    // loader takes it too, with a warning): the same strain.
    if (plain == "strain_limit.max_stretch") plain = "strain_limit.max_strain";
    const std::span<const SceneKeyInfo> keys = scene_key_table();
    std::size_t found = keys.size();
    for (std::size_t k = 0; k < keys.size(); ++k)
        if (plain == keys[k].name) found = k;
    if (found == keys.size() || indexed != is_collider_key(keys[found].key)) {
        std::string what = "'" + key + "' is not a setting a live edit can change";
        std::vector<std::string_view> names;
        for (const SceneKeyInfo& info : keys) names.push_back(info.name);
        if (auto suggestion = nearest_key(plain, names))
            what += " (did you mean '" + *suggestion + "'?)";
        reader.fail(value, key, what);
        return std::nullopt;
    }
    const SceneKeyInfo& info = keys[found];
    edit.key = info.key;
    // Read through the loader's own typed reads, from a table holding just this value, so a
    // wrong type gets the words a scene file's would.
    const auto dot = key.rfind('.');
    const std::string parent = key.substr(0, dot);
    const std::string leaf = key.substr(dot + 1);
    toml::table holder;
    value.visit([&](const auto& concrete) { holder.insert_or_assign(leaf, concrete); });
    switch (info.kind) {
        case ValueKind::count: {
            std::int64_t count = 0;
            if (!reader.read_int(holder, parent, leaf, count)) return std::nullopt;
            edit.value = count;
            return edit;
        }
        case ValueKind::flag: {
            bool enabled = false;
            if (!reader.read_bool(holder, parent, leaf, enabled)) return std::nullopt;
            edit.value = enabled;
            return edit;
        }
        case ValueKind::feature:
            if (value.is_boolean() && !value.as_boolean()->get()) {  // false: switched off
                edit.value = FeatureOff{};
                return edit;
            }
            [[fallthrough]];
        case ValueKind::number: {
            double number = 0.0;
            if (!reader.read_number(holder, parent, leaf, number)) return std::nullopt;
            edit.value = number;
            return edit;
        }
        case ValueKind::vector: {
            Vec3d vector{};
            if (!reader.read_vec3(holder, parent, leaf, vector)) return std::nullopt;
            edit.value = vector;
            return edit;
        }
        case ValueKind::choice: {
            int index = 0;
            if (!reader.read_choice(holder, parent, leaf, info.choices, index)) return std::nullopt;
            edit.value = info.choice_value(index);
            return edit;
        }
        case ValueKind::pins: {
            GridPins pins;
            if (value.is_string()) {
                int preset = 0;
                if (!reader.read_choice(holder, parent, leaf, pin_preset_names, preset))
                    return std::nullopt;
                pins.preset = static_cast<PinPreset>(preset);
                edit.value = pins;
                return edit;
            }
            const auto* list = value.as_array();
            if (!list) {
                reader.fail(value, key,
                            key + " must be a pin preset or a list of [row, col], got " +
                                describe_type(value));
                return std::nullopt;
            }
            pins.preset = PinPreset::list;
            for (const toml::node& entry : *list) {
                const auto* pair = entry.as_array();
                const bool is_pair = pair && pair->size() == 2 && pair->get(0)->is_integer() &&
                                     pair->get(1)->is_integer();
                const std::int64_t row = is_pair ? pair->get(0)->as_integer()->get() : -1;
                const std::int64_t col = is_pair ? pair->get(1)->as_integer()->get() : -1;
                if (!is_pair || row < 0 || col < 0 || row > max_particles || col > max_particles) {
                    reader.fail(entry, key, "each pin must be [row, col] with two integers");
                    return std::nullopt;
                }
                pins.list.push_back({static_cast<int>(row), static_cast<int>(col)});
            }
            edit.value = pins;
            return edit;
        }
    }
    return std::nullopt;
}

}  // namespace

std::optional<SceneEdit> scene_edit_from_override(const std::string& override_text,
                                                  SceneError& error) {
    std::string key;
    toml::table snippet;
    if (auto problem = parse_override(override_text, key, snippet)) {
        error = *problem;
        return std::nullopt;
    }
    TomlReader reader("--set", {key});
    std::optional<SceneEdit> edit = read_scene_edit(reader, key, *snippet.get("value"));
    if (!edit) error = reader.error().value_or(SceneError{"--set " + key, "not read"});
    return edit;
}

std::string scene_value_toml(const SceneValue& value) {
    return std::visit(
        [](const auto& v) -> std::string {
            using T = std::decay_t<decltype(v)>;
            auto quoted = [](std::string_view name) {
                std::string text(1, '"');
                return text.append(name).append(1, '"');
            };
            if constexpr (std::is_same_v<T, double>) {
                return toml_number(v);
            } else if constexpr (std::is_same_v<T, std::int64_t>) {
                return std::to_string(v);
            } else if constexpr (std::is_same_v<T, bool>) {
                return v ? "true" : "false";
            } else if constexpr (std::is_same_v<T, Vec3d>) {
                std::string text(1, '[');
                for (int k = 0; k < 3; ++k) text.append(k ? ", " : "").append(toml_number(v[k]));
                return text.append(1, ']');
            } else if constexpr (std::is_same_v<T, Integrator>) {
                return quoted(integrator_name(v));
            } else if constexpr (std::is_same_v<T, Layout>) {
                return quoted(layout_name(v));
            } else if constexpr (std::is_same_v<T, Orientation>) {
                return quoted(orientation_name(v));
            } else if constexpr (std::is_same_v<T, ContactResponse>) {
                return quoted(contact_response_name(v));
            } else if constexpr (std::is_same_v<T, GridPins>) {
                if (v.preset != PinPreset::list) return quoted(pin_preset_name(v.preset));
                std::string list = "[";
                for (std::size_t p = 0; p < v.list.size(); ++p)
                    list += (p ? ", [" : "[") + std::to_string(v.list[p].row) + ", " +
                            std::to_string(v.list[p].col) + "]";
                return list + "]";
            } else {
                return "false";  // FeatureOff
            }
        },
        value);
}

}  // namespace weft
