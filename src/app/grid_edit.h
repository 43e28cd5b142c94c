// The grid as the panel's grid section edits it: rows, cols, spacing, layout, orientation
// and pins, held as a draft while the user types and rebuilt only on Apply (a grid rebuilt
// at every keystroke would restart the cloth under the user's hands). ImGui-free, so it is
// tested.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/demo_state.h"
#include "sim/scene/scene.h"

namespace weft::app {

// The draft as one batch of typed edits (scene_edit.h), so Apply is checked by the rules a
// scene file is: a refused grid (too many particles, a pin outside it) changes nothing and
// says why.
std::vector<SceneEdit> grid_edits(const ClothSpec& draft);

// Whether two specs build the same grid: rows, cols, spacing, layout, orientation and pins
// (mass and origin, which other controls edit, aside).
bool same_grid(const ClothSpec& a, const ClothSpec& b);

// Particles in the draft's grid, computed without overflow for any typed rows and cols.
long long grid_particle_count(const ClothSpec& draft);

// The most particles the panel's grid editor builds: 512 x 512, four times the largest
// shipped scene. The window steps at least once a frame and draws every triangle, so a
// frame costs a step and a draw of the whole sheet. Measured on the default scene grown in
// the window at 1280 x 720 (2 cores, Xvfb): 512 x 512 ran at 18.6 fps (5.7 ms a step, 12 ms
// drawing, 314 MB), 724 x 724 at 11.8 fps (601 MB), 1024 x 1024 at 5.2 fps (40 ms a step,
// 46 ms drawing, 1.2 GB), and a copy side by side doubles the stepping. Beyond the limit
// Apply is refused before anything is built, so a zero too many cannot freeze the window.
// Scene files and --set keep the loader's own limit (max_particles): a headless run may
// step a larger sheet.
inline constexpr long long max_window_grid_particles = 262'144;

// Apply: the draft rebuilt as the running cloth, or why not (and nothing changed): a grid
// over max_window_grid_particles, or one the scene loader refuses.
std::optional<std::string> apply_grid(DemoState& state, const ClothSpec& draft);

}  // namespace weft::app
