#include "sim/grid/grid_stencil.h"

#include "sim/core/cloth.h"

namespace weft {
namespace {

// The forward directions of each family on a grid (cloth_builder.cpp builds these).
struct FamilyDirections {
    int steps[2][2];  // {dr, dc} twice
};

FamilyDirections directions_of(SpringFamily family) {
    switch (family) {
        case SpringFamily::structural:
            return {{{0, 1}, {1, 0}}};
        case SpringFamily::shear:
            return {{{1, 1}, {1, -1}}};
        case SpringFamily::bend:
            return {{{0, 2}, {2, 0}}};
    }
    return {{{0, 0}, {0, 0}}};
}

}  // namespace

void build_grid_stencil(Cloth& cloth) {
    GridStencil& stencil = cloth.edit_topology().grid_stencil;
    stencil = GridStencil{};
    const std::size_t count = cloth.particle_count();
    // A mesh's one "row" could pass for a grid whose springs happen to join neighbours.
    const bool plain_grid = !cloth.is_mesh() && cloth.odd_row_shift == 0.0 &&
                            cloth.row_pitch == 1.0 && cloth.rows >= 1 && cloth.cols >= 1 &&
                            static_cast<std::size_t>(cloth.rows) * cloth.cols == count;
    if (!plain_grid) return;
    const auto cols = static_cast<std::uint32_t>(cloth.cols);
    GridStencil built;
    for (std::size_t g = 0; g < cloth.topology().spring_groups.size(); ++g) {
        const SpringGroup& group = cloth.topology().spring_groups[g];
        const FamilyDirections family = directions_of(group.family);
        const std::size_t first = built.directions.size();
        for (const auto& step : family.steps) {
            GridStencilDirection direction;
            direction.row_step = step[0];
            direction.col_step = step[1];
            direction.group = g;
            direction.rest_lengths.assign(count, no_spring);
            built.directions.push_back(std::move(direction));
        }
        for (const Spring& spring : group.springs) {
            const auto row_i = static_cast<int>(spring.i / cols),
                       col_i = static_cast<int>(spring.i % cols);
            const auto row_j = static_cast<int>(spring.j / cols),
                       col_j = static_cast<int>(spring.j % cols);
            bool placed = false;
            for (std::size_t k = first; k < first + 2; ++k) {
                GridStencilDirection& direction = built.directions[k];
                if (row_j - row_i != direction.row_step || col_j - col_i != direction.col_step)
                    continue;
                if (direction.rest_lengths[spring.i] >= 0.0) return;  // a duplicate: not a grid
                if (!(spring.rest_length >= 0.0)) return;  // cannot be told from no_spring
                direction.rest_lengths[spring.i] = spring.rest_length;
                placed = true;
                break;
            }
            if (!placed) return;  // not one of the family's grid directions
        }
        built.group_sizes.push_back(group.springs.size());
    }
    for (GridStencilDirection& direction : built.directions)
        direction.rest_lengths_float.assign(direction.rest_lengths.begin(),
                                            direction.rest_lengths.end());
    stencil = std::move(built);
}

bool grid_stencil_usable(const Cloth& cloth) {
    const GridStencil& stencil = cloth.topology().grid_stencil;
    if (stencil.directions.empty() ||
        stencil.group_sizes.size() != cloth.topology().spring_groups.size())
        return false;
    for (std::size_t g = 0; g < cloth.topology().spring_groups.size(); ++g)
        if (stencil.group_sizes[g] != cloth.topology().spring_groups[g].springs.size())
            return false;
    return true;
}

}  // namespace weft
