#include "sim/scene_io/toml_reader.h"

#include "sim/scene_io/toml_input_guard.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

namespace weft {
namespace {

std::size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
            diagonal = above;
        }
    }
    return row[b.size()];
}

}  // namespace

std::optional<std::string> nearest_key(std::string_view key,
                                       std::span<const std::string_view> allowed) {
    std::optional<std::string> best;
    std::size_t best_distance = std::max<std::size_t>(2, key.size() / 3) + 1;
    for (std::string_view candidate : allowed) {
        const std::size_t distance = edit_distance(key, candidate);
        if (distance < best_distance) {
            best_distance = distance;
            best = std::string(candidate);
        }
    }
    return best;
}

std::string describe_type(const toml::node& node) {
    switch (node.type()) {
        case toml::node_type::table:
            return "a table";
        case toml::node_type::array:
            return "an array";
        case toml::node_type::string:
            return "a string";
        case toml::node_type::integer:
            return "an integer";
        case toml::node_type::floating_point:
            return "a floating-point number";
        case toml::node_type::boolean:
            return "a boolean";
        case toml::node_type::date:
            return "a date";
        case toml::node_type::time:
            return "a time";
        case toml::node_type::date_time:
            return "a date-time";
        default:
            return "nothing";
    }
}

std::string TomlReader::join(const std::string& path, std::string_view key) {
    return path.empty() ? std::string(key) : path + "." + std::string(key);
}

std::string TomlReader::where(const toml::source_region& region, const std::string& path) const {
    // A value an override put there (or inside a table an override put there) is reported
    // by the override that did it, not by a position in a snippet the user never saw; so is
    // a table an override created on its way to its key ("--set nosuch.key=1").
    for (const std::string& key : overridden_)
        if (!path.empty() && key.size() > path.size() && key.compare(0, path.size(), path) == 0 &&
            key[path.size()] == '.' && region.begin.line == 0)
            return "--set " + key;
    for (std::string prefix = path; !prefix.empty();) {
        if (overridden_.count(prefix)) return "--set " + prefix;
        const auto dot = prefix.rfind('.');
        prefix = dot == std::string::npos ? std::string() : prefix.substr(0, dot);
    }
    if (region.begin.line == 0) return source_name_;
    return source_name_ + ":" + std::to_string(region.begin.line) + ":" +
           std::to_string(region.begin.column);
}

bool TomlReader::fail_at(const toml::source_region& region, const std::string& path,
                         std::string what) {
    if (!error_) error_ = SceneError{where(region, path), std::move(what)};
    return false;
}

bool TomlReader::fail_with(SceneError error) {
    if (!error_) error_ = std::move(error);
    return false;
}

void TomlReader::warn(const toml::node& node, const std::string& path, const std::string& what) {
    warnings_.push_back(where(node.source(), path) + ": " + what);
}

bool TomlReader::fail(const toml::node& node, const std::string& path, std::string what) {
    return fail_at(node.source(), path, std::move(what));
}

bool TomlReader::check_keys(const toml::table& table, const std::string& path,
                            std::span<const std::string_view> allowed) {
    if (failed()) return false;
    for (auto&& [key, node] : table) {
        if (std::find(allowed.begin(), allowed.end(), key.str()) != allowed.end()) continue;
        std::string what = "unknown key '" + std::string(key.str()) + "'";
        if (!path.empty()) what += " in [" + path + "]";
        if (auto suggestion = nearest_key(key.str(), allowed))
            what += " (did you mean '" + *suggestion + "'?)";
        return fail_at(key.source(), join(path, key.str()), what);
    }
    return true;
}

bool TomlReader::read_int(const toml::table& table, const std::string& path, std::string_view key,
                          std::int64_t& out) {
    const toml::node* node = table.get(key);
    if (failed()) return false;
    if (!node) return true;
    const std::string full = join(path, key);
    const auto* integer = node->as_integer();
    if (!integer)
        return fail(*node, full, full + " must be an integer, got " + describe_type(*node));
    out = integer->get();
    return true;
}

bool TomlReader::read_number(const toml::table& table, const std::string& path,
                             std::string_view key, double& out, NumberRule rule) {
    const toml::node* node = table.get(key);
    if (failed()) return false;
    if (!node) return true;
    const std::string full = join(path, key);
    double value = 0.0;
    if (const auto* integer = node->as_integer())
        value = static_cast<double>(integer->get());
    else if (const auto* floating = node->as_floating_point())
        value = floating->get();
    else
        return fail(*node, full, full + " must be a number, got " + describe_type(*node));
    if (!check(*node, full, number_problem(full, value, rule))) return false;
    out = value;
    return true;
}

bool TomlReader::check(const toml::node& node, const std::string& path,
                       const std::optional<std::string>& problem) {
    if (failed()) return false;
    return !problem || fail(node, path, *problem);
}

bool TomlReader::read_bool(const toml::table& table, const std::string& path, std::string_view key,
                           bool& out) {
    const toml::node* node = table.get(key);
    if (failed()) return false;
    if (!node) return true;
    const std::string full = join(path, key);
    const auto* boolean = node->as_boolean();
    if (!boolean)
        return fail(*node, full, full + " must be true or false, got " + describe_type(*node));
    out = boolean->get();
    return true;
}

bool TomlReader::read_string(const toml::table& table, const std::string& path,
                             std::string_view key, std::string& out) {
    const toml::node* node = table.get(key);
    if (failed()) return false;
    if (!node) return true;
    const std::string full = join(path, key);
    const auto* string = node->as_string();
    if (!string) return fail(*node, full, full + " must be a string, got " + describe_type(*node));
    out = string->get();
    return true;
}

bool TomlReader::read_choice(const toml::table& table, const std::string& path,
                             std::string_view key, std::span<const std::string_view> names,
                             int& index) {
    std::string value;
    const toml::node* node = table.get(key);
    if (!read_string(table, path, key, value) || !node) return !failed();
    const auto found = std::find(names.begin(), names.end(), value);
    if (found != names.end()) {
        index = static_cast<int>(found - names.begin());
        return true;
    }
    const std::string full = join(path, key);
    std::string what = full + " must be one of";
    for (std::string_view name : names) what += std::string(" \"") + std::string(name) + "\"";
    what += ", got \"" + value + "\"";
    if (auto suggestion = nearest_key(value, names))
        what += " (did you mean \"" + *suggestion + "\"?)";
    return fail(*node, full, what);
}

bool TomlReader::read_vec3(const toml::table& table, const std::string& path, std::string_view key,
                           Vec3d& out) {
    const toml::node* node = table.get(key);
    if (failed()) return false;
    if (!node) return true;
    const std::string full = join(path, key);
    const auto* array = node->as_array();
    if (!array || array->size() != 3)
        return fail(
            *node, full,
            full + " must be an array of 3 numbers, got " +
                (array ? "an array of " + std::to_string(array->size()) : describe_type(*node)));
    Vec3d value{};
    for (std::size_t k = 0; k < 3; ++k) {
        const toml::node& element = *array->get(k);
        if (const auto* integer = element.as_integer())
            value[k] = static_cast<double>(integer->get());
        else if (const auto* floating = element.as_floating_point())
            value[k] = floating->get();
        else
            return fail(element, full,
                        full + " must be an array of 3 numbers, element " + std::to_string(k + 1) +
                            " is " + describe_type(element));
        if (!std::isfinite(value[k]))
            return fail(element, full, full + " must hold finite numbers");
    }
    out = value;
    return true;
}

const toml::table* TomlReader::sub_table(const toml::table& table, const std::string& path,
                                         std::string_view key) {
    const toml::node* node = table.get(key);
    if (failed() || !node) return nullptr;
    if (const toml::table* sub = node->as_table()) return sub;
    const std::string full = join(path, key);
    fail(*node, full, full + " must be a table, got " + describe_type(*node));
    return nullptr;
}

std::optional<SceneError> parse_override(const std::string& override_text, std::string& key,
                                         toml::table& snippet) {
    const auto equals = override_text.find('=');
    key = override_text.substr(0, equals);
    const std::string where = "--set " + key;
    if (equals == std::string::npos) return SceneError{where, "expects KEY=VALUE"};
    const bool key_well_formed =
        !key.empty() && key.front() != '.' && key.back() != '.' &&
        key.find("..") == std::string::npos &&
        key.find_first_not_of(
            "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_.-") ==
            std::string::npos;
    if (!key_well_formed) return SceneError{where, "expects a dotted key such as solver.dt"};
    const std::string value_text = override_text.substr(equals + 1);
    if (find_unsafe_non_ascii("value = " + value_text))
        return SceneError{where, "non-ASCII character outside a string"};
    try {
        snippet = toml::parse("value = " + value_text);
    } catch (const toml::parse_error&) {
        snippet = toml::table{};
        snippet.insert_or_assign("value", value_text);
    }
    if (value_text.empty() || !snippet.get("value")) return SceneError{where, "has no value"};
    return std::nullopt;
}

}  // namespace weft
