#include "sim/build/mesh_builder.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <memory>
#include <stdexcept>

#include "sim/build/cloth_builder.h"
#include "sim/build/spring_coloring.h"

namespace weft {
namespace {

using Pair = std::pair<std::uint32_t, std::uint32_t>;  // (i, j), i < j

Pair ordered(std::uint32_t a, std::uint32_t b) {
    return a < b ? Pair{a, b} : Pair{b, a};
}

// One side of one face: the edge it lies on, which face, and which side (side k runs from
// corner k to corner k + 1).
struct Side {
    Pair edge;
    std::uint32_t face;
    std::uint8_t k;
};

std::string vertex_pair(const Pair& edge) {
    return std::to_string(edge.first + 1) + "–" + std::to_string(edge.second + 1);
}

// Springs as (i, j) pairs, sorted and each once, with their rest lengths in the file.
std::vector<Spring> springs_of(std::vector<Pair> pairs, const ObjMesh& mesh) {
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    std::vector<Spring> springs;
    springs.reserve(pairs.size());
    for (const auto& [i, j] : pairs)
        springs.push_back({i, j, glm::length(mesh.vertices[j] - mesh.vertices[i])});
    return springs;
}

// Adds the triangle (a, b, c) of the face for drawing and its area to its corners' shares.
void add_triangle(const ObjMesh& mesh, const ObjFace& face, std::uint32_t a, std::uint32_t b,
                  std::uint32_t c, MeshTopology& topology) {
    const Vec3 &pa = mesh.vertices[a], &pb = mesh.vertices[b], &pc = mesh.vertices[c];
    const double area = 0.5 * glm::length(glm::cross(pb - pa, pc - pa));  // m²
    const double longest =
        std::max({glm::length(pb - pa), glm::length(pc - pb), glm::length(pa - pc)});  // m
    if (!std::isfinite(area) || !std::isfinite(longest))
        throw ObjError(mesh.path, face.line,
                       "the triangle " + std::to_string(a + 1) + ", " + std::to_string(b + 1) +
                           ", " + std::to_string(c + 1) +
                           " is too large: its area overflows a double");
    // Zero area up to rounding: a sliver whose area is a trillionth of its longest side's
    // square (an equilateral triangle's is 0.43) would get almost no mass and a rest shape
    // that no force can hold.
    if (!(area > 1e-12 * longest * longest))
        throw ObjError(mesh.path, face.line,
                       "degenerate triangle " + std::to_string(a + 1) + ", " +
                           std::to_string(b + 1) + ", " + std::to_string(c + 1) +
                           ": its corners are on one line (zero area)");
    topology.triangles.push_back({a, b, c});
    for (const std::uint32_t corner : {a, b, c}) topology.areas[corner] += area / 3.0;
}

// The corner of a face opposite its side k, in the triangle that holds that side: for a
// quad, the split triangle (a, b, c) holds sides 0 and 1, (a, c, d) sides 2 and 3.
std::uint32_t opposite(const ObjFace& face, std::uint8_t k) {
    if (face.count == 3) return face.vertices[(k + 2) % 3];
    return (k == 0 || k == 3) ? face.vertices[2] : face.vertices[0];
}

// In a quad whose side k lies on an edge, the neighbours of that edge's two ends off it:
// (next to `end`, next to the other end).
std::pair<std::uint32_t, std::uint32_t> off_edge_neighbours(const ObjFace& quad, std::uint8_t k,
                                                            std::uint32_t end) {
    const auto& v = quad.vertices;
    const std::uint32_t before = v[(k + 3) % 4], after = v[(k + 2) % 4];
    // Side k runs v[k] -> v[k+1]; v[k]'s other neighbour is v[k-1], v[k+1]'s is v[k+2].
    return v[k] == end ? std::pair{before, after} : std::pair{after, before};
}

// The bend springs across an edge that faces `one` and `other` share.
void add_bend(const ObjMesh& mesh, const Side& one, const Side& other, std::vector<Pair>& bend) {
    const ObjFace& a = mesh.faces[one.face];
    const ObjFace& b = mesh.faces[other.face];
    std::pair<std::uint32_t, std::uint32_t> springs[2];
    int count = 0;
    if (a.count == 4 && b.count == 4) {
        const std::uint32_t u = a.vertices[one.k];
        const auto [p, q] = off_edge_neighbours(a, one.k, u);
        const auto [r, s] = off_edge_neighbours(b, other.k, u);
        springs[count++] = {p, r};
        springs[count++] = {q, s};
    } else {
        springs[count++] = {opposite(a, one.k), opposite(b, other.k)};
    }
    for (int n = 0; n < count; ++n) {
        if (springs[n].first == springs[n].second)
            throw ObjError(mesh.path, b.line,
                           "the faces on lines " + std::to_string(a.line) + " and " +
                               std::to_string(b.line) + " fold onto each other across the edge " +
                               vertex_pair(one.edge) + " (vertex " +
                               std::to_string(springs[n].first + 1) + " is on both sides)");
        // Two corners at one point (a seam closed with duplicated vertices, folded): a spring
        // of zero rest length would count as stretched without end.
        if (mesh.vertices[springs[n].first] == mesh.vertices[springs[n].second])
            throw ObjError(mesh.path, b.line,
                           "the faces on lines " + std::to_string(a.line) + " and " +
                               std::to_string(b.line) + " fold onto each other across the edge " +
                               vertex_pair(one.edge) + " (vertices " +
                               std::to_string(springs[n].first + 1) + " and " +
                               std::to_string(springs[n].second + 1) + " are at one point)");
        bend.push_back(ordered(springs[n].first, springs[n].second));
    }
}

SpringGroup make_group(SpringFamily family, const SpringFamilySpec& spec,
                       std::vector<Spring> springs, std::size_t particle_count) {
    SpringGroup group;
    group.family = family;
    group.stiffness = spec.stiffness;
    group.damping = spec.damping;
    group.springs = std::move(springs);
    colour_springs(group, particle_count);
    return group;
}

// A mesh that is exactly a grid builder's sheet: see find_grid.
struct MeshGrid {
    int rows = 0;
    int cols = 0;
    double spacing = 0.0;  // m
    // The quads wind (tl, tr, br, bl), against the grid's triangles (tl, bl, tr), (tr, bl,
    // br): the file's front is the grid's back.
    bool turned_over = false;
};

// Whether the quad is the cell whose top-left corner is `top_left`, wound either way and
// starting at any corner: (tl, bl, br, tr) as the grid's triangles are, or turned over.
std::optional<bool> cell_winding(const ObjFace& quad, std::uint32_t top_left, std::uint32_t cols) {
    const std::uint32_t tl = top_left, tr = tl + 1, bl = tl + cols, br = bl + 1;
    const auto& v = quad.vertices;
    int start = 0;
    while (start < 4 && v[start] != tl) ++start;
    if (start == 4) return std::nullopt;
    const std::uint32_t next = v[(start + 1) % 4], across = v[(start + 2) % 4],
                        last = v[(start + 3) % 4];
    if (across != br) return std::nullopt;
    if (next == bl && last == tr) return false;
    if (next == tr && last == bl) return true;
    return std::nullopt;
}

// The mesh as the grid builder's rows × cols sheet, or nullopt. Exactly, not nearly: only
// quads, one per cell in row-major order (cell (r, c) is face r (cols - 1) + c, its corners
// vertices r cols + c, +1, +cols, +cols+1, all wound alike); and vertex r cols + c at
// v₀ + c s u + r s w for the first vertex v₀, the spacing s = |v₁ - v₀| and u, w two
// coordinate axes (either sign), each coordinate equal to the double that sum gives, as
// the grid builder computes its particles (origin + (c s, -r s, 0) or (c s, 0, r s)). A
// grid builder's sheet written with %.17g from its origin at 0 is found; a grid nudged by a
// rounding, or a curved one, is not, and is built as any mesh is.
std::optional<MeshGrid> find_grid(const ObjMesh& mesh) {
    if (mesh.faces.empty()) return std::nullopt;
    for (const ObjFace& face : mesh.faces)
        if (face.count != 4) return std::nullopt;
    // The first cell's corners, sorted, are 0, 1, cols and cols + 1.
    auto first = mesh.faces[0].vertices;
    std::sort(first.begin(), first.end());
    const std::size_t count = mesh.vertices.size();
    const std::uint32_t cols = first[2];
    if (first[0] != 0 || first[1] != 1 || cols < 2 || first[3] != cols + 1 || count % cols != 0)
        return std::nullopt;
    const std::size_t rows = count / cols;
    if (rows < 2 || mesh.faces.size() != (rows - 1) * (cols - 1)) return std::nullopt;
    MeshGrid grid;
    grid.rows = static_cast<int>(rows);
    grid.cols = static_cast<int>(cols);
    for (std::size_t r = 0; r + 1 < rows; ++r)
        for (std::size_t c = 0; c + 1 < cols; ++c) {
            const auto winding = cell_winding(mesh.faces[r * (cols - 1) + c],
                                              static_cast<std::uint32_t>(r * cols + c), cols);
            if (!winding || (r + c > 0 && *winding != grid.turned_over)) return std::nullopt;
            grid.turned_over = *winding;
        }
    // The axes and the spacing: along a row the first step moves one coordinate only, down
    // a column another, by as much.
    const Vec3& corner = mesh.vertices[0];
    const auto axis_of = [&](const Vec3& step) -> std::optional<int> {
        int axis = -1;
        for (int k = 0; k < 3; ++k)
            if (step[k] != 0.0) {
                if (axis >= 0) return std::nullopt;
                axis = k;
            }
        return axis >= 0 ? std::optional<int>(axis) : std::nullopt;
    };
    const Vec3 along = mesh.vertices[1] - corner, down = mesh.vertices[cols] - corner;  // m
    const auto across_axis = axis_of(along), down_axis = axis_of(down);
    if (!across_axis || !down_axis || *across_axis == *down_axis) return std::nullopt;
    const double spacing = std::abs(along[*across_axis]);  // m
    if (!std::isfinite(spacing) || std::abs(down[*down_axis]) != spacing) return std::nullopt;
    const double across_sign = along[*across_axis] > 0.0 ? 1.0 : -1.0;
    const double down_sign = down[*down_axis] > 0.0 ? 1.0 : -1.0;
    for (std::size_t r = 0; r < rows; ++r)
        for (std::size_t c = 0; c < cols; ++c) {
            const Vec3& x = mesh.vertices[r * cols + c];
            for (int k = 0; k < 3; ++k) {
                // The grid builder's sum: the corner plus the offset (c s or r s, signed).
                double offset = 0.0;
                if (k == *across_axis) offset = across_sign * (static_cast<double>(c) * spacing);
                if (k == *down_axis) offset = down_sign * (static_cast<double>(r) * spacing);
                if (!(x[k] == corner[k] + offset)) return std::nullopt;
            }
        }
    grid.spacing = spacing;
    return grid;
}

// Every vertex's share of the triangles it is a corner of: a third of each one's area, m².
std::vector<double> lumped_areas(const ObjMesh& mesh, const std::vector<Triangle>& triangles) {
    std::vector<double> areas(mesh.vertices.size(), 0.0);
    for (const Triangle& t : triangles) {
        const Vec3 &pa = mesh.vertices[t.a], &pb = mesh.vertices[t.b], &pc = mesh.vertices[t.c];
        const double area = 0.5 * glm::length(glm::cross(pb - pa, pc - pa));  // m²
        for (const std::uint32_t corner : {t.a, t.b, t.c}) areas[corner] += area / 3.0;
    }
    return areas;
}

}  // namespace

MeshTopology derive_mesh_topology(const ObjMesh& mesh) {
    MeshTopology topology;
    topology.areas.assign(mesh.vertices.size(), 0.0);
    std::vector<Side> sides;
    std::vector<Pair> shear;
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const ObjFace& face = mesh.faces[f];
        const auto& v = face.vertices;
        add_triangle(mesh, face, v[0], v[1], v[2], topology);
        if (face.count == 4) {
            add_triangle(mesh, face, v[0], v[2], v[3], topology);
            shear.push_back(ordered(v[0], v[2]));
            shear.push_back(ordered(v[1], v[3]));
        }
        for (std::uint8_t k = 0; k < face.count; ++k)
            sides.push_back(
                {ordered(v[k], v[(k + 1) % face.count]), static_cast<std::uint32_t>(f), k});
    }
    // Faces that meet share an edge: sorted by edge, they sit next to each other.
    std::sort(sides.begin(), sides.end(), [](const Side& a, const Side& b) {
        return a.edge != b.edge ? a.edge < b.edge : a.face < b.face;
    });
    std::vector<Pair> structural, bend;
    for (std::size_t start = 0; start < sides.size();) {
        std::size_t end = start + 1;
        while (end < sides.size() && sides[end].edge == sides[start].edge) ++end;
        structural.push_back(sides[start].edge);
        if (end - start > 2) {
            const ObjFace& third = mesh.faces[sides[start + 2].face];
            throw ObjError(mesh.path, third.line,
                           "the edge " + vertex_pair(sides[start].edge) +
                               " is shared by more than two faces (lines " +
                               std::to_string(mesh.faces[sides[start].face].line) + ", " +
                               std::to_string(mesh.faces[sides[start + 1].face].line) + " and " +
                               std::to_string(third.line) + "): a cloth surface has at most two");
        }
        if (end - start == 2) add_bend(mesh, sides[start], sides[start + 1], bend);
        start = end;
    }
    for (std::size_t p = 0; p < mesh.vertices.size(); ++p)
        if (topology.areas[p] == 0.0)
            throw ObjError(mesh.path, mesh.vertex_lines[p],
                           "vertex " + std::to_string(p + 1) +
                               " is in no face: it would be a particle without mass");
    topology.structural = springs_of(std::move(structural), mesh);
    topology.shear = springs_of(std::move(shear), mesh);
    topology.bend = springs_of(std::move(bend), mesh);
    return topology;
}

std::optional<std::string> mesh_pin_problem(const ClothSpec& spec, const ObjMesh& mesh) {
    if (spec.pin_preset == PinPreset::vertices) {
        for (const std::int64_t number : spec.pin_vertices)
            if (number < 1 || number > static_cast<std::int64_t>(mesh.vertices.size()))
                return "pin " + std::to_string(number) + " is not a vertex of " + mesh.path +
                       " (it has vertices 1 to " + std::to_string(mesh.vertices.size()) + ")";
    } else if (spec.pin_preset == PinPreset::group) {
        if (!mesh.find_group(spec.pin_group)) {
            std::string known;
            for (const ObjGroup& group : mesh.groups)
                known += (known.empty() ? "" : ", ") + ("'" + group.name + "'");
            return "no group '" + spec.pin_group + "' in " + mesh.path +
                   (known.empty() ? " (it has no groups)" : " (its groups: " + known + ")");
        }
    } else if (spec.pin_preset != PinPreset::none) {
        return std::string("a mesh is pinned by \"none\", a list of vertex numbers or pin_group");
    }
    return std::nullopt;
}

Cloth build_mesh_cloth(const Scene& scene) {
    const ClothSpec& spec = scene.cloth;
    if (!spec.mesh_data.obj)
        throw std::invalid_argument("build_mesh_cloth: cloth.mesh " + spec.mesh + " is not loaded");
    const ObjMesh& mesh = *spec.mesh_data.obj;
    if (auto problem = mesh_pin_problem(spec, mesh)) throw std::invalid_argument(*problem);
    MeshTopology topology = derive_mesh_topology(mesh);  // its checks hold for a grid too
    const std::optional<MeshGrid> grid = find_grid(mesh);

    Cloth cloth;
    const std::size_t count = mesh.vertices.size();
    const Vec3 origin(spec.origin[0], spec.origin[1], spec.origin[2]);
    cloth.positions.resize(count);
    for (std::size_t p = 0; p < count; ++p) cloth.positions[p] = mesh.vertices[p] + origin;
    cloth.velocities.assign(count, Vec3(0.0));

    if (grid) {
        // The grid builder's sheet: its rows, spacing, springs in its order (so coloured
        // alike, and summed alike), rest lengths from the positions as placed, triangles and
        // stencil; no mesh extent or rest shape, so that guards, solvers and dumps see a grid.
        cloth.rows = grid->rows;
        cloth.cols = grid->cols;
        cloth.spacing = grid->spacing;
        add_grid_topology(scene, cloth);
        if (grid->turned_over)  // keep the file's front: (tl, bl, tr) becomes (tl, tr, bl)
            for (Triangle& t : cloth.edit_topology().triangles) std::swap(t.b, t.c);
        topology.areas = lumped_areas(mesh, cloth.topology().triangles);
    } else {
        cloth.rows = 1;
        cloth.cols = static_cast<int>(count);
        Vec3 low = mesh.vertices[0], high = mesh.vertices[0];
        for (const Vec3& x : mesh.vertices) {
            low = glm::min(low, x);
            high = glm::max(high, x);
        }
        cloth.mesh_extent = glm::length(high - low);
        cloth.mesh_rest_shape = std::make_shared<const std::vector<Vec3>>(cloth.positions);
        double total_rest = 0.0;
        for (const Spring& spring : topology.structural) total_rest += spring.rest_length;
        cloth.spacing = total_rest / static_cast<double>(topology.structural.size());
        cloth.edit_topology().spring_groups.push_back(make_group(
            SpringFamily::structural, scene.structural, std::move(topology.structural), count));
        if (scene.shear.enabled)
            cloth.edit_topology().spring_groups.push_back(
                make_group(SpringFamily::shear, scene.shear, std::move(topology.shear), count));
        if (scene.bend.enabled)
            cloth.edit_topology().spring_groups.push_back(
                make_group(SpringFamily::bend, scene.bend, std::move(topology.bend), count));
        cloth.edit_topology().triangles = std::move(topology.triangles);
        // No grid stencil: the structured passes are for grids (grid_stencil.h).
    }

    ClothTopology& weights = cloth.edit_topology();
    weights.masses.resize(count);
    weights.inverse_masses.resize(count);
    for (std::size_t p = 0; p < count; ++p) {
        weights.masses[p] =
            spec.mesh_particle_mass ? spec.particle_mass : spec.density * topology.areas[p];
        weights.inverse_masses[p] = 1.0 / weights.masses[p];
    }
    if (spec.pin_preset == PinPreset::vertices)
        for (const std::int64_t number : spec.pin_vertices)
            weights.inverse_masses[static_cast<std::size_t>(number - 1)] = 0.0;
    if (spec.pin_preset == PinPreset::group)
        for (const std::uint32_t p : mesh.find_group(spec.pin_group)->vertices)
            weights.inverse_masses[p] = 0.0;
    for (std::size_t p = 0; p < count; ++p)
        if (weights.inverse_masses[p] == 0.0)
            weights.pinned.push_back(static_cast<std::uint32_t>(p));
    return cloth;
}

}  // namespace weft
