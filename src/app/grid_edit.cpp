#include "app/grid_edit.h"

#include "sim/scene_io/scene_loader.h"

namespace weft::app {
std::vector<SceneEdit> grid_edits(const ClothSpec& draft) {
    return {
        {SceneKey::cloth_rows, std::int64_t{draft.rows}},
        {SceneKey::cloth_cols, std::int64_t{draft.cols}},
        {SceneKey::cloth_spacing, draft.spacing},
        {SceneKey::cloth_layout, draft.layout},
        {SceneKey::cloth_orientation, draft.orientation},
        {SceneKey::cloth_pins,
         GridPins{draft.pin_preset,
                  draft.pin_preset == PinPreset::list ? draft.pin_list : std::vector<GridIndex>{}}},
    };
}

bool same_grid(const ClothSpec& a, const ClothSpec& b) {
    return a.rows == b.rows && a.cols == b.cols && a.spacing == b.spacing && a.layout == b.layout &&
           a.orientation == b.orientation && a.pin_preset == b.pin_preset &&
           (a.pin_preset != PinPreset::list || a.pin_list == b.pin_list);
}

long long grid_particle_count(const ClothSpec& draft) {
    return static_cast<long long>(draft.rows) * static_cast<long long>(draft.cols);
}

std::optional<std::string> apply_grid(DemoState& state, const ClothSpec& draft) {
    // Only a grid the loader would take is measured against the window's limit: -1000 rows
    // by -1000 cols are refused for their sign, not for a million particles.
    const long long particles = grid_particle_count(draft);
    if (draft.rows >= 1 && draft.cols >= 1 && particles > max_window_grid_particles)
        return "cloth.rows × cloth.cols = " + std::to_string(particles) +
               " particles, more than the window's limit of " +
               std::to_string(max_window_grid_particles) +
               ", the most it steps and draws at a usable frame rate (a headless run takes up "
               "to " +
               std::to_string(max_particles) + ")";
    return state.edit(grid_edits(draft));
}

}  // namespace weft::app
