// The triangles a cloth's shadow is drawn from. A shadow is one flat colour, so a grid's
// shadow needs none of its fine detail: wherever a block of b x b cells is whole, two
// triangles across the block's corners cover what its 2 b² triangles do, up to how far the
// cloth bends inside the block. The cells a side leaves over make one narrower block at the
// far edge. Torn or cut blocks keep their own intact triangles, so the shadow shows every
// hole.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "raster/mesh.h"
#include "sim/core/cloth.h"

namespace weft::view {

// Cells per side of a shadow block on this cloth: about 32 blocks along its longer side,
// 1 (every triangle kept) for a mesh cloth or a small grid.
int shadow_block_cells(const Cloth& cloth);

// The shadow's triangles for `intact` (the cloth's intact triangles, two per whole grid cell),
// with blocks of `block_cells` cells per side. Indices are the cloth's particles; `used` gets
// every particle they name, once, ascending.
void find_shadow_triangles(const Cloth& cloth, std::span<const raster::TriangleIndices> intact,
                           int block_cells, std::vector<raster::TriangleIndices>& shadow,
                           std::vector<std::uint32_t>& used);

}  // namespace weft::view
