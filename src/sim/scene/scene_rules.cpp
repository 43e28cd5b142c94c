#include "sim/scene/scene_rules.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace weft {

std::string format_number(double value) {
    std::ostringstream out;
    out << value;
    return out.str();
}

std::optional<std::string> number_problem(std::string_view key, double value, NumberRule rule) {
    const std::string name(key);
    if (!std::isfinite(value)) return name + " must be a finite number";
    if (rule.minimum && (rule.exclusive_minimum ? value <= *rule.minimum : value < *rule.minimum))
        return name + " must be " + (rule.exclusive_minimum ? "> " : ">= ") +
               format_number(*rule.minimum) + ", got " + format_number(value);
    if (rule.maximum && (rule.exclusive_maximum ? value >= *rule.maximum : value > *rule.maximum))
        return name + " must be " + (rule.exclusive_maximum ? "< " : "<= ") +
               format_number(*rule.maximum) + ", got " + format_number(value);
    return std::nullopt;
}

std::optional<std::string> vector_problem(std::string_view key, const Vec3d& value) {
    for (double component : value)
        if (!std::isfinite(component)) return std::string(key) + " must hold finite numbers";
    return std::nullopt;
}

std::optional<std::string> grid_count_problem(std::string_view key, std::int64_t value) {
    if (value >= 1 && value <= max_particles) return std::nullopt;
    return std::string(key) + " must be between 1 and " + std::to_string(max_particles) + ", got " +
           std::to_string(value);
}

std::optional<std::string> grid_size_problem(std::int64_t rows, std::int64_t cols) {
    if (rows * cols <= max_particles) return std::nullopt;
    return "cloth.rows × cloth.cols = " + std::to_string(rows * cols) +
           " particles, more than the limit of " + std::to_string(max_particles);
}

std::optional<std::string> pin_problem(std::int64_t row, std::int64_t col, int rows, int cols) {
    if (row >= 0 && row < rows && col >= 0 && col < cols) return std::nullopt;
    return "pin [" + std::to_string(row) + ", " + std::to_string(col) + "] is outside the " +
           std::to_string(rows) + "×" + std::to_string(cols) + " grid";
}

std::optional<std::string> thickness_problem(double thickness, double spacing, bool mesh) {
    const double most = scene_rules::max_thickness_spacings * spacing;
    if (!(thickness > most)) return std::nullopt;
    char text[240];
    std::snprintf(text, sizeof text,
                  "a thickness of %.4g m is more than %g particle spacings (%s = %.4g "
                  "m): every particle would be within it of dozens of others; at most %.4g m",
                  thickness, scene_rules::max_thickness_spacings,
                  mesh ? "the mesh's mean edge length" : "cloth.spacing", spacing, most);
    return std::string(text);
}

std::optional<std::string> normal_problem(const Vec3d& normal) {
    // Kept as written (make_colliders normalises it), so a scene saved and loaded again is
    // the same scene bit for bit; a length whose square underflows or overflows could not be
    // normalised.
    const double length =
        std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
    if (length > 0.0 && std::isfinite(length)) return std::nullopt;
    return "colliders.normal must not be zero (nor so large its length overflows)";
}

std::optional<std::string> structural_enabled_problem(bool enabled) {
    if (enabled) return std::nullopt;
    return "structural springs cannot be disabled";
}

std::string not_for_mesh(std::string_view key) {
    return std::string(key) +
           " does not apply with cloth.mesh: the mesh's vertices are the particles, where the "
           "file puts them";
}

std::string both_mesh_masses() {
    return "cloth.density and cloth.particle_mass cannot both be given: density lumps the "
           "masses from the triangles' areas, particle_mass gives every vertex the same; "
           "choose one";
}

std::string only_for_mesh(std::string_view key) {
    return std::string(key) + " applies only to a mesh (cloth.mesh)";
}

}  // namespace weft
