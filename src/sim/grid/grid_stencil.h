// GridStencil: the springs of a regular grid cloth seen as per-direction stencils, for the
// structured force pass (grid_force_pass.h).
//
// On a grid every spring joins particle (r, c) to (r + dr, c + dc) for one of six forward
// directions: structural (0,1) (1,0), shear (1,1) (1,-1), bend (0,2) (2,0). So a family is
// fully described by, per direction and per start particle, the rest length of the spring
// that starts there and whether it is still alive. Springs removed by tearing or the cut
// tool stay in the stencil, masked dead, so its loops keep their regular shape.
//
// The spring groups of Cloth stay the truth (picking, tearing, strain limiting, drawing and
// implicit Euler read them); this is derived from them when the grid is built and again
// after springs are removed. A cloth that is not a plain grid (the offset layout, hand-made
// test cloths) has an empty stencil and uses the general force pass.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace weft {

struct Cloth;

struct GridStencilDirection {
    int row_step = 0;       // dr: the spring joins (r, c) to (r + dr, c + dc)
    int col_step = 0;       // dc
    std::size_t group = 0;  // index into Cloth::spring_groups: material of the springs
    // m, per start particle r * cols + c, of the live spring that starts there; negative
    // (no_spring) where none does or it is dead. One array rather than lengths plus flags:
    // the force pass reads it for every spring, and at 256² each array is 3 MB.
    std::vector<double> rest_lengths;
    // The same rounded to float, for the force pass's float springs (grid_force_kernel.h):
    // read as they are instead of converted spring by spring, and half the bytes.
    std::vector<float> rest_lengths_float;
};

inline constexpr double no_spring = -1.0;  // the rest length that marks a dead spring

struct GridStencil {
    std::vector<GridStencilDirection> directions;  // empty: not a grid, use the general pass
    // Spring count of every group when the stencil was derived: a cheap check that nobody
    // has edited the groups since without going through topology_edits.h.
    std::vector<std::size_t> group_sizes;
};

// Derives cloth.topology().grid_stencil from cloth.topology().spring_groups, or leaves it empty
// when some spring is not one of its family's grid directions (or the layout is not a plain grid).
void build_grid_stencil(Cloth& cloth);

// True when the stencil describes the cloth's springs as they are now.
bool grid_stencil_usable(const Cloth& cloth);

}  // namespace weft
