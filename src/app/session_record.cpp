#include "app/session_record.h"

#include <toml++/toml.h>

#include <algorithm>
#include <cerrno>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "sim/build/topology_edits.h"
#include "sim/scene_io/scene_edit_toml.h"
#include "sim/scene_io/scene_loader.h"
#include "sim/scene_io/scene_writer.h"
#include "sim/scene_io/toml_input_guard.h"

namespace weft::app {
namespace {

std::string vec3(const Vec3& v) {
    std::string text = "[";
    for (int k = 0; k < 3; ++k) text.append(k ? ", " : "").append(toml_number(v[k]));
    return text.append("]");
}

constexpr ClothEvent::Kind all_kinds[] = {ClothEvent::Kind::grab,         ClothEvent::Kind::pull,
                                          ClothEvent::Kind::let_go,       ClothEvent::Kind::cut,
                                          ClothEvent::Kind::pin,          ClothEvent::Kind::unpin,
                                          ClothEvent::Kind::release_pins, ClothEvent::Kind::edit,
                                          ClothEvent::Kind::parameters,   ClothEvent::Kind::reset};

// Reading: every problem becomes one message with the position of the node at fault.
struct Reader {
    std::string source;
    std::string error;

    bool fail(const toml::node* node, const std::string& what) {
        if (!error.empty()) return false;
        if (node && node->source().begin.line > 0)
            error = source + ":" + std::to_string(node->source().begin.line) + ":" +
                    std::to_string(node->source().begin.column) + ": " + what;
        else
            error = source + ": " + what;
        return false;
    }
    bool unsigned_at(const toml::table& table, const char* key, std::uint64_t limit,
                     std::uint64_t& out) {
        const toml::node* node = table.get(key);
        const auto* integer = node ? node->as_integer() : nullptr;
        if (!integer || integer->get() < 0 || static_cast<std::uint64_t>(integer->get()) > limit)
            return fail(
                node ? node : &table,
                std::string(key) + " must be a whole number from 0 to " + std::to_string(limit));
        out = static_cast<std::uint64_t>(integer->get());
        return true;
    }
    bool finite_at(const toml::table& table, const char* key, double& out) {
        const toml::node* node = table.get(key);
        std::optional<double> value = node ? node->value<double>() : std::nullopt;
        if (!value || !std::isfinite(*value))
            return fail(node ? node : &table, std::string(key) + " must be a finite number");
        out = *value;
        return true;
    }
    bool vec3_at(const toml::table& table, const char* key, Vec3& out) {
        const toml::node* node = table.get(key);
        const auto* array = node ? node->as_array() : nullptr;
        if (!array || array->size() != 3)
            return fail(node ? node : &table, std::string(key) + " must be [x, y, z]");
        for (int k = 0; k < 3; ++k) {
            std::optional<double> value = array->get(static_cast<std::size_t>(k))->value<double>();
            if (!value || !std::isfinite(*value))
                return fail(node, std::string(key) + " must hold finite numbers");
            out[k] = *value;
        }
        return true;
    }
    bool string_at(const toml::table& table, const char* key, std::string& out) {
        const toml::node* node = table.get(key);
        const auto* text = node ? node->as_string() : nullptr;
        if (!text) return fail(node ? node : &table, std::string(key) + " must be a string");
        out = text->get();
        return true;
    }
};

constexpr std::uint64_t max_index = 0xffffffffu;
constexpr std::uint64_t max_step = std::uint64_t(1) << 62;

// edits = [{key = "springs.shear.stiffness", value = 250.0}, ...]: their types are checked
// here, their values when they are applied, as the panel's are.
bool read_edits(Reader& reader, const toml::table& table, std::vector<SceneEdit>& edits) {
    const toml::node* node = table.get("edits");
    const auto* list = node ? node->as_array() : nullptr;
    if (!list || list->empty())
        return reader.fail(node ? node : &table, "edits must be [{key = ..., value = ...}, ...]");
    for (const toml::node& entry : *list) {
        const auto* pair = entry.as_table();
        const toml::node* key = pair ? pair->get("key") : nullptr;
        const toml::node* value = pair ? pair->get("value") : nullptr;
        if (!key || !key->is_string() || !value || pair->size() != 2)
            return reader.fail(&entry, "each edit must be {key = \"a.setting\", value = ...}");
        TomlReader edit_reader(reader.source, {});
        std::optional<SceneEdit> edit =
            read_scene_edit(edit_reader, key->as_string()->get(), *value);
        if (!edit) {
            // "FILE:LINE:COL: what", as the reader's own errors read.
            if (reader.error.empty())
                reader.error = edit_reader.error()->where + ": " + edit_reader.error()->what;
            return false;
        }
        edits.push_back(std::move(*edit));
    }
    return true;
}

bool read_event(Reader& reader, const toml::table& table, TimedEvent& timed) {
    std::string kind_name;
    if (!reader.unsigned_at(table, "step", max_step, timed.step) ||
        !reader.string_at(table, "kind", kind_name))
        return false;
    ClothEvent& event = timed.event;
    bool known = false;
    for (ClothEvent::Kind kind : all_kinds)
        if (kind_name == event_kind_name(kind)) event.kind = kind, known = true;
    if (!known) return reader.fail(table.get("kind"), "unknown event kind '" + kind_name + "'");
    std::uint64_t index = 0;
    switch (event.kind) {
        case ClothEvent::Kind::grab:
            if (!reader.unsigned_at(table, "particle", max_index, index)) return false;
            event.hit.particle = static_cast<std::uint32_t>(index);
            if (!reader.unsigned_at(table, "triangle", max_index, index)) return false;
            event.hit.triangle = static_cast<std::uint32_t>(index);
            return reader.finite_at(table, "distance", event.hit.distance) &&
                   reader.vec3_at(table, "point", event.hit.point) &&
                   reader.finite_at(table, "radius", event.radius);
        case ClothEvent::Kind::pull:
            return reader.vec3_at(table, "target", event.target);
        case ClothEvent::Kind::cut: {
            const toml::node* node = table.get("springs");
            const auto* list = node ? node->as_array() : nullptr;
            if (!list) return reader.fail(node ? node : &table, "springs must be [[i, j], ...]");
            for (const toml::node& entry : *list) {
                const auto* pair = entry.as_array();
                const auto* i = pair && pair->size() == 2 ? pair->get(0)->as_integer() : nullptr;
                const auto* j = pair && pair->size() == 2 ? pair->get(1)->as_integer() : nullptr;
                if (!i || !j || i->get() < 0 || j->get() < 0 ||
                    static_cast<std::uint64_t>(i->get()) > max_index ||
                    static_cast<std::uint64_t>(j->get()) > max_index)
                    return reader.fail(&entry, "each spring must be [i, j] with particle indices");
                event.springs.push_back(edge_key(static_cast<std::uint32_t>(i->get()),
                                                 static_cast<std::uint32_t>(j->get())));
            }
            std::sort(event.springs.begin(), event.springs.end());
            return true;
        }
        case ClothEvent::Kind::pin:
        case ClothEvent::Kind::unpin:
            if (!reader.unsigned_at(table, "particle", max_index, index)) return false;
            event.particle = static_cast<std::uint32_t>(index);
            return true;
        case ClothEvent::Kind::edit:
            return read_edits(reader, table, event.edits);
        case ClothEvent::Kind::parameters: {  // format 1: a whole scene
            std::string scene_toml;
            if (!reader.string_at(table, "scene", scene_toml)) return false;
            SceneLoadResult checked = load_scene_text(scene_toml, "event scene");
            if (!checked.ok()) return reader.fail(table.get("scene"), checked.error->message());
            event.scene = std::make_shared<const Scene>(std::move(*checked.scene));
            return true;
        }
        case ClothEvent::Kind::let_go:
        case ClothEvent::Kind::release_pins:
        case ClothEvent::Kind::reset:
            return true;
    }
    return true;
}

}  // namespace

std::string session_to_toml(const SessionRecord& record) {
    std::ostringstream out;
    char hash[32];
    std::snprintf(hash, sizeof hash, "0x%016" PRIx64, record.final_state_hash);
    out << "# weft session recording: weft --replay FILE (or --headless --replay FILE)\n";
    out << "format = 2\nsteps = " << record.steps << "\nfinal_state_hash = \"" << hash << "\"\n";
    out << "scene = " << toml_string(record.scene_toml) << "\n";
    for (const TimedEvent& timed : record.events) {
        const ClothEvent& e = timed.event;
        out << "\n[[events]]\nstep = " << timed.step << "\nkind = \"" << event_kind_name(e.kind)
            << "\"\n";
        switch (e.kind) {
            case ClothEvent::Kind::grab:
                out << "particle = " << e.hit.particle << "\ntriangle = " << e.hit.triangle
                    << "\ndistance = " << toml_number(e.hit.distance)
                    << "\npoint = " << vec3(e.hit.point) << "\nradius = " << toml_number(e.radius)
                    << "\n";
                break;
            case ClothEvent::Kind::pull:
                out << "target = " << vec3(e.target) << "\n";
                break;
            case ClothEvent::Kind::cut:
                out << "springs = [";
                for (std::size_t s = 0; s < e.springs.size(); ++s)
                    out << (s ? ", " : "") << "[" << (e.springs[s] >> 32) << ", "
                        << (e.springs[s] & 0xffffffffu) << "]";
                out << "]\n";
                break;
            case ClothEvent::Kind::pin:
            case ClothEvent::Kind::unpin:
                out << "particle = " << e.particle << "\n";
                break;
            case ClothEvent::Kind::edit:
                out << "edits = [";
                for (std::size_t k = 0; k < e.edits.size(); ++k)
                    out << (k ? ", " : "") << "{key = \"" << scene_edit_name(e.edits[k])
                        << "\", value = " << scene_value_toml(e.edits[k].value) << "}";
                out << "]\n";
                break;
            case ClothEvent::Kind::parameters:
                out << "scene = " << toml_string(e.scene ? scene_to_toml(*e.scene) : "") << "\n";
                break;
            case ClothEvent::Kind::let_go:
            case ClothEvent::Kind::release_pins:
            case ClothEvent::Kind::reset:
                break;
        }
    }
    return out.str();
}

std::optional<SessionRecord> session_from_toml(std::string_view text, const std::string& source,
                                               std::string& error) {
    Reader reader{source, {}};
    // toml++ 3.3 misbehaves on some non-ASCII text outside strings (toml_input_guard.h).
    if (auto unsafe = find_unsafe_non_ascii(text)) {
        error = source + ":" + std::to_string(unsafe->line) + ":" + std::to_string(unsafe->column) +
                ": non-ASCII character outside a string";
        return std::nullopt;
    }
    toml::table root;
    try {
        root = toml::parse(text, source);
    } catch (const toml::parse_error& e) {
        error = source + ":" + std::to_string(e.source().begin.line) + ":" +
                std::to_string(e.source().begin.column) + ": " + std::string(e.description());
        return std::nullopt;
    }
    SessionRecord record;
    std::uint64_t format = 0;
    std::string hash_text;
    // Format 1 stored each parameter change as a whole scene; 2 stores typed edits. Both
    // replay.
    if (reader.unsigned_at(root, "format", 1000, format) && format != 1 && format != 2)
        reader.fail(root.get("format"),
                    "unknown format " + std::to_string(format) + " (this weft reads 1 and 2)");
    if (reader.error.empty() && reader.unsigned_at(root, "steps", max_step, record.steps) &&
        reader.string_at(root, "final_state_hash", hash_text)) {
        char* end = nullptr;
        record.final_state_hash = std::strtoull(hash_text.c_str(), &end, 16);
        if (hash_text.size() != 18 || hash_text.rfind("0x", 0) != 0 || *end != '\0')
            reader.fail(root.get("final_state_hash"),
                        "final_state_hash must be \"0x\" and 16 hex digits");
    }
    if (reader.error.empty() && reader.string_at(root, "scene", record.scene_toml)) {
        SceneLoadResult checked = load_scene_text(record.scene_toml, "recorded scene");
        if (!checked.ok()) reader.fail(root.get("scene"), checked.error->message());
    }
    if (const toml::node* events = root.get("events"); events && reader.error.empty()) {
        const auto* list = events->as_array();
        if (!list) reader.fail(events, "events must be an array of tables ([[events]])");
        for (std::size_t e = 0; list && reader.error.empty() && e < list->size(); ++e) {
            const auto* table = list->get(e)->as_table();
            TimedEvent timed;
            if (!table) {
                reader.fail(list->get(e), "each event must be a table");
            } else if (read_event(reader, *table, timed)) {
                if (!record.events.empty() && timed.step < record.events.back().step)
                    reader.fail(table, "events must come in order of step");
                else if (timed.step > record.steps)
                    reader.fail(table, "an event after the last step");
                else
                    record.events.push_back(std::move(timed));
            }
        }
    }
    if (!reader.error.empty()) {
        error = reader.error;
        return std::nullopt;
    }
    return record;
}

std::optional<SessionRecord> read_session_file(const std::string& path, std::string& error) {
    // A directory opens as a stream that reads as empty: name the real mistake instead.
    std::error_code ignored;
    if (std::filesystem::is_directory(path, ignored)) {
        error = path + ": is a directory, not a session file";
        return std::nullopt;
    }
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        error = path + ": cannot read file: " + std::strerror(errno);
        return std::nullopt;
    }
    std::ostringstream text;
    text << file.rdbuf();
    return session_from_toml(text.str(), path, error);
}

}  // namespace weft::app
