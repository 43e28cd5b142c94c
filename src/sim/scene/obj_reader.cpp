#include "sim/scene/obj_reader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <span>
#include <sstream>

#include "sim/scene/scene.h"
#include "sim/scene/scene_rules.h"

namespace weft {
namespace {

// A token as it may be shown in a message: at most 40 characters, anything that is not
// printable ASCII escaped, so a binary file read by mistake cannot garble the terminal.
std::string quoted(std::string_view token) {
    std::string out = "'";
    for (std::size_t k = 0; k < token.size() && k < 40; ++k) {
        const auto c = static_cast<unsigned char>(token[k]);
        if (c >= 0x20 && c < 0x7f) {
            out += static_cast<char>(c);
        } else {
            char escape[8];
            std::snprintf(escape, sizeof escape, "\\x%02x", c);
            out += escape;
        }
    }
    if (token.size() > 40) out += "...";
    return out + "'";
}

// Splits a line (comment already cut off) at spaces and tabs.
std::vector<std::string_view> tokens_of(std::string_view line) {
    std::vector<std::string_view> tokens;
    std::size_t k = 0;
    while (k < line.size()) {
        while (k < line.size() && (line[k] == ' ' || line[k] == '\t')) ++k;
        const std::size_t start = k;
        while (k < line.size() && line[k] != ' ' && line[k] != '\t') ++k;
        if (k > start) tokens.push_back(line.substr(start, k - start));
    }
    return tokens;
}

// Reads one line's statements into the mesh, keeping the groups the elements go to.
class ObjParser {
  public:
    explicit ObjParser(const std::string& path) { mesh_.path = path; }

    void read_line(std::string_view line, int number) {
        line_ = number;
        if (const auto hash = line.find('#'); hash != std::string_view::npos)
            line = line.substr(0, hash);
        const std::vector<std::string_view> tokens = tokens_of(line);
        if (tokens.empty()) return;
        const std::string_view keyword = tokens[0];
        const std::span<const std::string_view> arguments(tokens.data() + 1, tokens.size() - 1);
        if (keyword == "v") {
            read_vertex(arguments);
        } else if (keyword == "f") {
            read_face(arguments);
        } else if (keyword == "p") {
            read_points(arguments);
        } else if (keyword == "g" || keyword == "o") {
            current_groups_.clear();
            for (std::string_view name : arguments) current_groups_.push_back(group_index(name));
        } else if (keyword != "vt" && keyword != "vn" && keyword != "s" && keyword != "usemtl" &&
                   keyword != "mtllib" && keyword != "l") {
            fail("unknown OBJ statement " + quoted(keyword) +
                 " (read: v, f, p, g, o; skipped: vt, vn, s, usemtl, mtllib, l)");
        }
    }

    ObjMesh finish(int last_line) {
        if (mesh_.faces.empty()) {
            line_ = std::max(last_line, 1);
            fail("no faces: a cloth mesh needs at least one `f` element (" +
                 std::to_string(mesh_.vertices.size()) + " vertices read)");
        }
        std::vector<ObjGroup> kept;
        for (ObjGroup& group : mesh_.groups) {
            std::sort(group.vertices.begin(), group.vertices.end());
            group.vertices.erase(std::unique(group.vertices.begin(), group.vertices.end()),
                                 group.vertices.end());
            if (!group.vertices.empty()) kept.push_back(std::move(group));
        }
        mesh_.groups = std::move(kept);
        return std::move(mesh_);
    }

  private:
    [[noreturn]] void fail(const std::string& what) const {
        throw ObjError(mesh_.path, line_, what);
    }

    double number(std::string_view token) const {
        std::string_view digits = token;
        if (!digits.empty() && digits.front() == '+')
            digits.remove_prefix(1);  // from_chars: no '+'
        double value = 0.0;
        const auto [end, error] =
            std::from_chars(digits.data(), digits.data() + digits.size(), value);
        if (error == std::errc::result_out_of_range)
            fail("the number " + quoted(token) + " is out of range");
        if (error != std::errc() || end != digits.data() + digits.size() || digits.empty())
            fail("expected a number, got " + quoted(token));
        if (!std::isfinite(value)) fail("the coordinate " + quoted(token) + " is not finite");
        return value;
    }

    void read_vertex(std::span<const std::string_view> arguments) {
        if (arguments.size() < 3)
            fail("a vertex needs three coordinates x y z, got " + std::to_string(arguments.size()));
        if (arguments.size() > 4)
            fail("a vertex takes x y z and an optional w, got " + std::to_string(arguments.size()) +
                 " numbers");
        if (mesh_.vertices.size() >= static_cast<std::size_t>(max_particles))
            fail("more than " + std::to_string(max_particles) +
                 " vertices, the particle limit of a scene");
        Vec3 position;
        for (int k = 0; k < 3; ++k) position[k] = number(arguments[k]);
        if (arguments.size() == 4) number(arguments[3]);  // checked, then ignored
        mesh_.vertices.push_back(position);
        mesh_.vertex_lines.push_back(line_);
    }

    // A corner "i", "i/t", "i//n" or "i/t/n": the vertex index, 0-based. The texture and
    // normal indices are only checked to be integers (their arrays are not kept).
    std::uint32_t corner(std::string_view token) const {
        std::string_view parts[3];
        std::size_t count = 0;
        for (std::size_t start = 0;;) {
            const auto slash = token.find('/', start);
            if (count == 3) fail("a face corner has at most two '/', got " + quoted(token));
            parts[count++] =
                token.substr(start, slash == std::string_view::npos ? slash : slash - start);
            if (slash == std::string_view::npos) break;
            start = slash + 1;
        }
        for (std::size_t k = 1; k < count; ++k) {
            const bool may_be_empty = k == 1 && count == 3;  // i//n
            if (parts[k].empty() && may_be_empty) continue;
            long long ignored = 0;
            if (!integer(parts[k], ignored))
                fail("expected a face corner i, i/t, i//n or i/t/n, got " + quoted(token));
        }
        long long index = 0;
        if (!integer(parts[0], index))
            fail("expected a vertex number, got " + quoted(parts[0]) + " in " + quoted(token));
        const auto defined = static_cast<long long>(mesh_.vertices.size());
        if (index == 0) fail("vertex number 0 in " + quoted(token) + ": OBJ counts from 1");
        const long long resolved = index > 0 ? index - 1 : defined + index;
        if (resolved < 0 || resolved >= defined)
            fail("vertex " + quoted(parts[0]) + " is out of range: " + std::to_string(defined) +
                 " vertices are defined above this line");
        return static_cast<std::uint32_t>(resolved);
    }

    static bool integer(std::string_view text, long long& out) {
        if (!text.empty() && text.front() == '+') text.remove_prefix(1);
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), out);
        return !text.empty() && error == std::errc() && end == text.data() + text.size();
    }

    void read_face(std::span<const std::string_view> arguments) {
        if (arguments.size() < 3)
            fail("a face needs at least 3 vertices, got " + std::to_string(arguments.size()));
        if (arguments.size() > 4)
            fail("a face of " + std::to_string(arguments.size()) +
                 " vertices: only triangles and quads are read (split it into triangles)");
        if (mesh_.faces.size() >= static_cast<std::size_t>(max_particles))
            fail("more than " + std::to_string(max_particles) + " faces");
        ObjFace face;
        face.count = static_cast<std::uint8_t>(arguments.size());
        face.line = line_;
        for (std::size_t k = 0; k < arguments.size(); ++k) {
            face.vertices[k] = corner(arguments[k]);
            for (std::size_t before = 0; before < k; ++before)
                if (face.vertices[before] == face.vertices[k])
                    fail("the face uses vertex " + std::to_string(face.vertices[k] + 1) +
                         " twice (" + quoted(arguments[before]) + " and " + quoted(arguments[k]) +
                         ")");
        }
        mesh_.faces.push_back(face);
        add_to_groups(std::span<const std::uint32_t>(face.vertices.data(), face.count));
    }

    void read_points(std::span<const std::string_view> arguments) {
        if (arguments.empty()) fail("a point element needs at least one vertex");
        std::vector<std::uint32_t> vertices;
        for (std::string_view token : arguments) vertices.push_back(corner(token));
        add_to_groups(vertices);
    }

    void add_to_groups(std::span<const std::uint32_t> vertices) {
        for (const std::size_t g : current_groups_) {
            std::vector<std::uint32_t>& members = mesh_.groups[g].vertices;
            // Bounded by the file's size: each entry comes from a token on some line.
            members.insert(members.end(), vertices.begin(), vertices.end());
        }
    }

    std::size_t group_index(std::string_view name) {
        for (std::size_t g = 0; g < mesh_.groups.size(); ++g)
            if (mesh_.groups[g].name == name) return g;
        mesh_.groups.push_back({std::string(name), {}});
        return mesh_.groups.size() - 1;
    }

    ObjMesh mesh_;
    int line_ = 0;
    std::vector<std::size_t> current_groups_;  // indices into mesh_.groups
};

}  // namespace

bool LoadedMesh::operator==(const LoadedMesh& other) const {
    return obj == other.obj || (obj && other.obj && *obj == *other.obj);
}

const ObjGroup* ObjMesh::find_group(std::string_view name) const {
    for (const ObjGroup& group : groups)
        if (group.name == name) return &group;
    return nullptr;
}

ObjError::ObjError(std::string path, int line, std::string what)
    : std::runtime_error((line > 0 ? path + ":" + std::to_string(line) : path) + ": " + what),
      path_(std::move(path)),
      line_(line),
      reason_(std::move(what)) {}

std::string ObjError::where() const {
    return line_ > 0 ? path_ + ":" + std::to_string(line_) : path_;
}

ObjMesh read_obj_text(std::string_view text, const std::string& path) {
    ObjParser parser(path);
    int number = 0;
    while (!text.empty()) {
        const std::size_t end = text.find('\n');
        std::string_view line = text.substr(0, end);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);  // CRLF files
        parser.read_line(line, ++number);
        if (end == std::string_view::npos) break;
        text.remove_prefix(end + 1);
    }
    return parser.finish(number);
}

ObjMesh read_obj_file(const std::string& path) {
    // Only regular files: a FIFO or /dev/zero would block or never end.
    std::error_code error;
    const auto status = std::filesystem::status(path, error);
    if (error) throw ObjError(path, 0, "cannot read the mesh: " + error.message());
    if (!std::filesystem::is_regular_file(status)) throw ObjError(path, 0, "is not a regular file");
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (error) throw ObjError(path, 0, "cannot read the mesh: " + error.message());
    if (size > max_obj_file_bytes)
        throw ObjError(path, 0,
                       "the mesh file is " + std::to_string(size) + " bytes, more than the " +
                           std::to_string(max_obj_file_bytes) + " read");
    std::ifstream file(path, std::ios::binary);
    if (!file) throw ObjError(path, 0, "cannot open the mesh file");
    std::ostringstream text;
    text << file.rdbuf();
    return read_obj_text(text.str(), path);
}

}  // namespace weft
