#include "sim/build/cloth_builder.h"

#include "sim/build/mesh_builder.h"
#include "sim/build/spring_coloring.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <vector>

namespace weft {
namespace {

Vec3 to_vec3(const Vec3d& v) {
    return {v[0], v[1], v[2]};
}

using NeighbourOffsets = std::vector<std::pair<int, int>>;  // (row, col) steps to a neighbour

// The springs of one family: from every particle to its neighbours at the given offsets
// (forward offsets only, so each spring appears once). Offsets may depend on the row's
// parity (the offset layout). Springs come in particle order, so consecutive springs touch
// nearby memory in the force pass.
SpringGroup make_group(SpringFamily family, const SpringFamilySpec& spec, const Cloth& cloth,
                       const NeighbourOffsets& even_rows, const NeighbourOffsets& odd_rows) {
    SpringGroup group;
    group.family = family;
    group.stiffness = spec.stiffness;
    group.damping = spec.damping;
    for (int r = 0; r < cloth.rows; ++r) {
        for (int c = 0; c < cloth.cols; ++c) {
            for (auto [dr, dc] : (r % 2 ? odd_rows : even_rows)) {
                const int r2 = r + dr, c2 = c + dc;
                if (r2 < 0 || r2 >= cloth.rows || c2 < 0 || c2 >= cloth.cols) continue;
                const auto i = static_cast<std::uint32_t>(r * cloth.cols + c);
                const auto j = static_cast<std::uint32_t>(r2 * cloth.cols + c2);
                group.springs.push_back(
                    {i, j, glm::length(cloth.positions[j] - cloth.positions[i])});
            }
        }
    }
    colour_springs(group, cloth.particle_count());
    return group;
}

// Particles, masses and pins; `row_shift(r)` is the row's x offset in spacings and
// `row_pitch` the distance between rows in spacings.
Cloth place_particles(const ClothSpec& spec, double row_pitch, double odd_row_shift) {
    Cloth cloth;
    cloth.rows = spec.rows;
    cloth.cols = spec.cols;
    cloth.spacing = spec.spacing;
    cloth.row_pitch = row_pitch;
    cloth.odd_row_shift = odd_row_shift;
    const std::size_t count = static_cast<std::size_t>(spec.rows) * spec.cols;
    cloth.positions.resize(count);
    cloth.velocities.assign(count, Vec3(0.0));
    ClothTopology& topology = cloth.edit_topology();
    topology.masses.assign(count, spec.particle_mass);
    topology.inverse_masses.assign(count, 1.0 / spec.particle_mass);
    const Vec3 origin = to_vec3(spec.origin);
    for (int r = 0; r < spec.rows; ++r) {
        for (int c = 0; c < spec.cols; ++c) {
            const double across = (c + (r % 2 ? odd_row_shift : 0.0)) * spec.spacing;
            const double down = r * row_pitch * spec.spacing;
            const Vec3 offset = spec.orientation == Orientation::vertical ? Vec3(across, -down, 0.0)
                                                                          : Vec3(across, 0.0, down);
            cloth.positions[static_cast<std::size_t>(r) * spec.cols + c] = origin + offset;
        }
    }
    auto pin = [&](int r, int c) {
        topology.inverse_masses[static_cast<std::size_t>(r) * spec.cols + c] = 0.0;
    };
    switch (spec.pin_preset) {
        case PinPreset::none:
            break;
        case PinPreset::top_corners:
            pin(0, 0);
            pin(0, spec.cols - 1);
            break;
        case PinPreset::top_row:
            for (int c = 0; c < spec.cols; ++c) pin(0, c);
            break;
        case PinPreset::list:
            for (const GridIndex& p : spec.pin_list) pin(p.row, p.col);
            break;
        case PinPreset::vertices:  // a mesh's pins (mesh_builder.cpp)
        case PinPreset::group:
            break;
    }
    for (std::size_t i = 0; i < count; ++i)
        if (topology.inverse_masses[i] == 0.0)
            topology.pinned.push_back(static_cast<std::uint32_t>(i));
    return cloth;
}

void add_families(const Scene& scene, Cloth& cloth, const NeighbourOffsets (&even)[3],
                  const NeighbourOffsets (&odd)[3]) {
    std::vector<SpringGroup>& groups = cloth.edit_topology().spring_groups;
    groups.push_back(
        make_group(SpringFamily::structural, scene.structural, cloth, even[0], odd[0]));
    if (scene.shear.enabled)
        groups.push_back(make_group(SpringFamily::shear, scene.shear, cloth, even[1], odd[1]));
    if (scene.bend.enabled)
        groups.push_back(make_group(SpringFamily::bend, scene.bend, cloth, even[2], odd[2]));
}

}  // namespace

void add_grid_topology(const Scene& scene, Cloth& cloth) {
    // Structural: right and down; shear: both diagonals; bend: two right and two down.
    const NeighbourOffsets families[3] = {{{0, 1}, {1, 0}}, {{1, 1}, {1, -1}}, {{0, 2}, {2, 0}}};
    add_families(scene, cloth, families, families);
    std::vector<Triangle>& triangles = cloth.edit_topology().triangles;
    for (int r = 0; r + 1 < cloth.rows; ++r) {
        for (int c = 0; c + 1 < cloth.cols; ++c) {
            const auto top_left = static_cast<std::uint32_t>(r * cloth.cols + c);
            const auto top_right = top_left + 1;
            const auto bottom_left = top_left + static_cast<std::uint32_t>(cloth.cols);
            const auto bottom_right = bottom_left + 1;
            triangles.push_back({top_left, bottom_left, top_right});
            triangles.push_back({top_right, bottom_left, bottom_right});
        }
    }
    build_grid_stencil(cloth);
}

Cloth build_grid_cloth(const Scene& scene) {
    Cloth cloth = place_particles(scene.cloth, 1.0, 0.0);
    add_grid_topology(scene, cloth);
    return cloth;
}

Cloth build_offset_cloth(const Scene& scene) {
    // Odd rows shifted right by half a spacing, rows √3/2 spacings apart: every particle and
    // its neighbours form equilateral triangles. Below an even-row particle (r, c) sit
    // (r+1, c-1) and (r+1, c); below an odd-row one, (r+1, c) and (r+1, c+1).
    Cloth cloth = place_particles(scene.cloth, std::sqrt(3.0) / 2.0, 0.5);
    // Structural (distance s): right and the two below. Shear (√3 s): the far corners of the
    // two triangles on either side of an edge — two rows down, and one row down 1.5 s to
    // either side. Bend (2 s): two along each lattice line.
    const NeighbourOffsets even[3] = {
        {{0, 1}, {1, -1}, {1, 0}}, {{2, 0}, {1, -2}, {1, 1}}, {{0, 2}, {2, -1}, {2, 1}}};
    const NeighbourOffsets odd[3] = {
        {{0, 1}, {1, 0}, {1, 1}}, {{2, 0}, {1, -1}, {1, 2}}, {{0, 2}, {2, -1}, {2, 1}}};
    add_families(scene, cloth, even, odd);
    std::vector<Triangle>& triangles = cloth.edit_topology().triangles;
    const auto index = [&](int r, int c) { return static_cast<std::uint32_t>(r * cloth.cols + c); };
    for (int r = 0; r + 1 < cloth.rows; ++r) {
        const int shift = r % 2;  // the lower row's neighbours sit `shift` columns further right
        for (int c = 0; c + 1 < cloth.cols; ++c) {
            // Counter-clockwise seen from the front, like the grid's.
            if (shift == 0) {
                triangles.push_back({index(r, c), index(r + 1, c), index(r, c + 1)});
                triangles.push_back({index(r, c + 1), index(r + 1, c), index(r + 1, c + 1)});
            } else {
                triangles.push_back({index(r, c), index(r + 1, c + 1), index(r, c + 1)});
                triangles.push_back({index(r, c), index(r + 1, c), index(r + 1, c + 1)});
            }
        }
    }
    return cloth;
}

Cloth build_cloth(const Scene& scene) {
    if (!scene.cloth.mesh.empty()) return build_mesh_cloth(scene);
    return scene.cloth.layout == Layout::offset ? build_offset_cloth(scene)
                                                : build_grid_cloth(scene);
}

}  // namespace weft
