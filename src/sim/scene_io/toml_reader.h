// TomlReader: typed, checked reads from a parsed TOML document, with errors that name where
// the offending value came from — "FILE:LINE:COL" for the file, "--set KEY" for a value an
// override put there. The first error wins; every read after it is a no-op that returns
// false, so the scene loader can read straight through without checking each call.
#pragma once

#include <toml++/toml.h>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "sim/scene/scene.h"
#include "sim/scene/scene_rules.h"
#include "sim/scene_io/scene_loader.h"

namespace weft {

// The allowed key nearest to `key` by edit distance, if it is close enough to be a typo.
std::optional<std::string> nearest_key(std::string_view key,
                                       std::span<const std::string_view> allowed);

class TomlReader {
  public:
    TomlReader(std::string source_name, std::set<std::string> overridden_paths)
        : source_name_(std::move(source_name)), overridden_(std::move(overridden_paths)) {}

    bool failed() const { return error_.has_value(); }
    const std::optional<SceneError>& error() const { return error_; }

    // Records an error at `node` (a value read from `path`, a dotted key path).
    bool fail(const toml::node& node, const std::string& path, std::string what);
    bool fail_at(const toml::source_region& region, const std::string& path, std::string what);
    // Records `problem` (a scene rule's, scene_rules.h) at `node`, if there is one.
    bool check(const toml::node& node, const std::string& path,
               const std::optional<std::string>& problem);
    // Records an error found outside the document, e.g. at a line of the mesh file it names.
    bool fail_with(SceneError error);
    // Records a warning at `node`: "WHERE: WHAT", WHERE as an error's would be (the caller
    // says "warning: ").
    void warn(const toml::node& node, const std::string& path, const std::string& what);
    const std::vector<std::string>& warnings() const { return warnings_; }

    // Every key of `table` (at `path`; "" for the root) must be in `allowed`.
    bool check_keys(const toml::table& table, const std::string& path,
                    std::span<const std::string_view> allowed);
    bool check_keys(const toml::table& table, const std::string& path,
                    std::initializer_list<std::string_view> allowed) {
        return check_keys(table, path, std::span(allowed.begin(), allowed.size()));
    }

    // Typed reads of table[key]. A missing key leaves `out` unchanged and succeeds.
    bool read_int(const toml::table& table, const std::string& path, std::string_view key,
                  std::int64_t& out);
    // Numbers accept integers too; the value must pass `rule` (scene_rules.h), which also
    // refuses non-finite values.
    bool read_number(const toml::table& table, const std::string& path, std::string_view key,
                     double& out, NumberRule rule = scene_rules::any);
    bool read_bool(const toml::table& table, const std::string& path, std::string_view key,
                   bool& out);
    bool read_string(const toml::table& table, const std::string& path, std::string_view key,
                     std::string& out);
    // One of `names`; returns its index in `index`.
    bool read_choice(const toml::table& table, const std::string& path, std::string_view key,
                     std::span<const std::string_view> names, int& index);
    bool read_vec3(const toml::table& table, const std::string& path, std::string_view key,
                   Vec3d& out);

    // A sub-table (e.g. [cloth]); nullptr if absent, error if present but not a table.
    const toml::table* sub_table(const toml::table& table, const std::string& path,
                                 std::string_view key);

    static std::string join(const std::string& path, std::string_view key);

  private:
    std::string where(const toml::source_region& region, const std::string& path) const;

    std::string source_name_;
    std::set<std::string> overridden_;
    std::optional<SceneError> error_;
    std::vector<std::string> warnings_;
};

// Splits one --set style "KEY=VALUE" and parses VALUE into snippet["value"]. A VALUE that is
// not TOML (a bare word such as rk4 or explicit-euler) is taken as a string. A malformed one
// is refused as "--set KEY".
std::optional<SceneError> parse_override(const std::string& override_text, std::string& key,
                                         toml::table& snippet);

// "a string", "an integer", ...: for messages.
std::string describe_type(const toml::node& node);

}  // namespace weft
