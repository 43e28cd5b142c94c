// Builds a Cloth from a scene's cloth and spring settings. The grid is one builder of the
// general topology; code that steps or draws the cloth only sees the flat arrays.
#pragma once

#include "sim/core/cloth.h"
#include "sim/scene/scene.h"

namespace weft {

// Particle (row, col) is index row * cols + col. Structural springs join (r,c)-(r,c+1) and
// (r,c)-(r+1,c); shear springs both diagonals of every cell; bend springs (r,c)-(r,c+2) and
// (r,c)-(r+2,c). Rest lengths are the distances in the initial, flat configuration.
// Requires a validated scene.
Cloth build_grid_cloth(const Scene& scene);

// build_grid_cloth's topology on a cloth whose rows, cols and positions are set: the spring
// families the scene enables, each in that order (and so coloured alike), rest lengths from
// the positions, two triangles per cell and the grid stencil. The mesh builder gives a grid
// written as OBJ these, so that it steps as the grid builder's sheet does.
void add_grid_topology(const Scene& scene, Cloth& cloth);

// The offset layout: odd rows shifted by half a spacing and rows √3/2 spacings apart, so
// structural springs form equilateral triangles (six neighbours inside the sheet); shear
// springs join particles √3 spacings apart, bend springs 2 spacings apart along the
// lattice lines.
Cloth build_offset_cloth(const Scene& scene);

// The builder the scene asks for: its mesh (mesh_builder.h), or its layout's grid.
Cloth build_cloth(const Scene& scene);

}  // namespace weft
