// OBJ reading: the subset of Wavefront OBJ that a cloth mesh needs, read into plain values
// for mesh_builder.h. Everything else a modeller writes about looks (texture coordinates,
// normals, smoothing groups, materials, lines) is skipped; anything it does not know, or
// that is wrong, is refused with the file, the 1-based line and the offending token.
//
//   v x y z [w]            a vertex (w, the rational weight, is ignored)
//   f a b c [d]            a triangle or a quad; each corner is i, i/t, i//n or i/t/n, where i
//                          counts vertices from 1, or back from the last one when negative
//   p a b ...              point elements: vertices that belong to the current groups
//   g NAME... / o NAME     the groups (or object) the following f and p elements belong to
//   vt vn s usemtl mtllib l, comments (#) and blank lines: skipped
#pragma once

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "sim/core/cloth.h"

namespace weft {

struct ObjFace {
    std::array<std::uint32_t, 4> vertices{};  // 0-based vertex indices, as wound in the file
    std::uint8_t count = 0;                   // 3: a triangle, 4: a quad
    int line = 0;                             // 1-based line of the `f` element

    bool operator==(const ObjFace&) const = default;
};

struct ObjGroup {
    std::string name;
    std::vector<std::uint32_t> vertices;  // 0-based, ascending, each once

    bool operator==(const ObjGroup&) const = default;
};

struct ObjMesh {
    std::string path;               // the file it was read from, for errors
    std::vector<Vec3> vertices;     // m, in file order
    std::vector<int> vertex_lines;  // 1-based line of each vertex's `v`
    std::vector<ObjFace> faces;     // in file order
    std::vector<ObjGroup> groups;   // in order of first appearance; only groups with vertices

    bool operator==(const ObjMesh&) const = default;
    const ObjGroup* find_group(std::string_view name) const;
};

// A refused OBJ file: where (path and 1-based line; line 0 when the whole file is meant,
// e.g. unreadable) and what.
class ObjError : public std::runtime_error {
  public:
    ObjError(std::string path, int line, std::string what);
    const std::string& path() const { return path_; }
    int line() const { return line_; }
    const std::string& reason() const { return reason_; }
    std::string where() const;  // "PATH:LINE", or "PATH" when line is 0

  private:
    std::string path_;
    int line_;
    std::string reason_;
};

// The largest OBJ file read, in bytes. A mesh at the particle limit (scene_rules.h) written
// with generous precision takes a few hundred MiB; beyond this a wrong path (a disk image, a
// video) would be read whole before the first line is refused.
inline constexpr std::uintmax_t max_obj_file_bytes = std::uintmax_t{1} << 30;

// Reads OBJ text; `path` stands in for the file in errors. Throws ObjError.
ObjMesh read_obj_text(std::string_view text, const std::string& path);

// Reads an OBJ file: a regular file no larger than max_obj_file_bytes. Throws ObjError.
ObjMesh read_obj_file(const std::string& path);

}  // namespace weft
