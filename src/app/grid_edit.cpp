#include "app/grid_edit.h"

#include "sim/scene_loader.h"
#include "sim/scene_writer.h"

namespace weft::app {
namespace {

std::string pins_value(const ClothSpec& draft) {
    if (const char* preset = pin_preset_name(draft.pin_preset))
        return std::string("\"") + preset + "\"";
    std::string list = "[";
    for (std::size_t p = 0; p < draft.pin_list.size(); ++p)
        list += (p ? ",[" : "[") + std::to_string(draft.pin_list[p].row) + "," +
                std::to_string(draft.pin_list[p].col) + "]";
    return list + "]";
}

}  // namespace

std::vector<std::string> grid_overrides(const ClothSpec& draft) {
    return {
        "cloth.rows=" + std::to_string(draft.rows),
        "cloth.cols=" + std::to_string(draft.cols),
        "cloth.spacing=" + toml_number(draft.spacing),
        std::string("cloth.layout=\"") + layout_name(draft.layout) + "\"",
        std::string("cloth.orientation=\"") + orientation_name(draft.orientation) + "\"",
        "cloth.pins=" + pins_value(draft),
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
    return state.change(grid_overrides(draft));
}

}  // namespace weft::app
