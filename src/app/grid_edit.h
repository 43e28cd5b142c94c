// The grid as the panel's grid section edits it: rows, cols, spacing, layout, orientation
// and pins, held as a draft while the user types and rebuilt only on Apply (a grid rebuilt
// at every keystroke would restart the cloth under the user's hands). ImGui-free, so it is
// tested.
#pragma once

#include <string>
#include <vector>

#include "sim/scene.h"

namespace weft::app {

// The draft as --set overrides of the scene format ("cloth.rows=40", "cloth.pins=\"none\"",
// "cloth.pins=[[0,0],[0,9]]"), so Apply is checked exactly like the command line: a refused
// grid (too many particles, a pin outside it) changes nothing and says why.
std::vector<std::string> grid_overrides(const ClothSpec& draft);

// Whether two specs build the same grid: rows, cols, spacing, layout, orientation and pins
// (mass and origin, which other controls edit, aside).
bool same_grid(const ClothSpec& a, const ClothSpec& b);

// Particles in the draft's grid, computed without overflow for any typed rows and cols.
long long grid_particle_count(const ClothSpec& draft);

// From this many particles up the panel warns before Apply: building and stepping such a
// cloth stalls the window for seconds (measured: 1024 x 1024 builds in about 1 s, 2048 x
// 2048 in about 10 s, on the 2-core machine this was written on). The loader refuses more
// than max_particles.
inline constexpr long long slow_grid_particles = 1'048'576;

}  // namespace weft::app
