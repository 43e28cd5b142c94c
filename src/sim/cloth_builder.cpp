#include "sim/cloth_builder.h"

#include <algorithm>
#include <glm/geometric.hpp>

namespace weft {
namespace {

Vec3 to_vec3(const Vec3d& v) {
    return {v[0], v[1], v[2]};
}

// Emits springs in particle order (each particle's springs to its right and lower
// neighbours), so consecutive springs touch nearby memory in the force pass.
SpringGroup make_group(SpringFamily family, const SpringFamilySpec& spec, const Cloth& cloth,
                       std::initializer_list<std::pair<int, int>> neighbour_offsets) {
    SpringGroup group;
    group.family = family;
    group.stiffness = spec.stiffness;
    group.damping = spec.damping;
    for (int r = 0; r < cloth.rows; ++r) {
        for (int c = 0; c < cloth.cols; ++c) {
            for (auto [dr, dc] : neighbour_offsets) {
                const int r2 = r + dr, c2 = c + dc;
                if (r2 < 0 || r2 >= cloth.rows || c2 < 0 || c2 >= cloth.cols) continue;
                const auto i = static_cast<std::uint32_t>(r * cloth.cols + c);
                const auto j = static_cast<std::uint32_t>(r2 * cloth.cols + c2);
                group.springs.push_back(
                    {i, j, glm::length(cloth.positions[j] - cloth.positions[i])});
            }
        }
    }
    return group;
}

}  // namespace

Cloth build_grid_cloth(const Scene& scene) {
    const ClothSpec& spec = scene.cloth;
    Cloth cloth;
    cloth.rows = spec.rows;
    cloth.cols = spec.cols;
    cloth.spacing = spec.spacing;
    const std::size_t count = static_cast<std::size_t>(spec.rows) * spec.cols;
    cloth.positions.resize(count);
    cloth.velocities.assign(count, Vec3(0.0));
    cloth.masses.assign(count, spec.particle_mass);
    cloth.inverse_masses.assign(count, 1.0 / spec.particle_mass);

    const Vec3 origin = to_vec3(spec.origin);
    for (int r = 0; r < spec.rows; ++r) {
        for (int c = 0; c < spec.cols; ++c) {
            const double across = c * spec.spacing, down = r * spec.spacing;
            const Vec3 offset = spec.orientation == Orientation::vertical ? Vec3(across, -down, 0.0)
                                                                          : Vec3(across, 0.0, down);
            cloth.positions[static_cast<std::size_t>(r) * spec.cols + c] = origin + offset;
        }
    }

    auto pin = [&](int r, int c) {
        cloth.inverse_masses[static_cast<std::size_t>(r) * spec.cols + c] = 0.0;
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
    }
    for (std::size_t i = 0; i < count; ++i)
        if (cloth.inverse_masses[i] == 0.0) cloth.pinned.push_back(static_cast<std::uint32_t>(i));

    cloth.spring_groups.push_back(
        make_group(SpringFamily::structural, scene.structural, cloth, {{0, 1}, {1, 0}}));
    if (scene.shear.enabled)
        cloth.spring_groups.push_back(
            make_group(SpringFamily::shear, scene.shear, cloth, {{1, 1}, {1, -1}}));
    if (scene.bend.enabled)
        cloth.spring_groups.push_back(
            make_group(SpringFamily::bend, scene.bend, cloth, {{0, 2}, {2, 0}}));

    for (int r = 0; r + 1 < spec.rows; ++r) {
        for (int c = 0; c + 1 < spec.cols; ++c) {
            const auto top_left = static_cast<std::uint32_t>(r * spec.cols + c);
            const auto top_right = top_left + 1;
            const auto bottom_left = top_left + static_cast<std::uint32_t>(spec.cols);
            const auto bottom_right = bottom_left + 1;
            cloth.triangles.push_back({top_left, bottom_left, top_right});
            cloth.triangles.push_back({top_right, bottom_left, bottom_right});
        }
    }
    return cloth;
}

}  // namespace weft
