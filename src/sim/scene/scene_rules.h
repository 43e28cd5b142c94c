// Scene rules: what makes a value of a scene acceptable, said once. The scene loader
// (scene_toml.cpp) checks what a file or --set gives with these; a typed live edit
// (scene_edit.h) checks its value with the same functions, so the panel, a recording and a
// scene file are refused for the same reasons, in the same words.
//
// Each check returns the problem as a sentence that names the key ("springs.shear.stiffness
// must be >= 0, got -5"), or nothing when the value is fine. Where the value came from (a
// file's line, --set, the panel) is the caller's to add.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "sim/scene/scene.h"

namespace weft {

// The largest cloth a scene may ask for. At ~0.5 KiB per particle with all spring families
// and integrator scratch, 4 Mi particles is about 2 GiB: beyond that a typo (rows = 1e6)
// would end in an out-of-memory kill instead of a message.
inline constexpr long long max_particles = 4'194'304;

// The range a number must lie in. Every number must also be finite.
struct NumberRule {
    std::optional<double> minimum;  // inclusive unless exclusive_minimum
    bool exclusive_minimum = false;
    std::optional<double> maximum;  // inclusive unless exclusive_maximum
    bool exclusive_maximum = false;
};

namespace scene_rules {
inline constexpr NumberRule any{};
inline constexpr NumberRule positive{0.0, true, std::nullopt};
inline constexpr NumberRule non_negative{0.0, false, std::nullopt};
inline constexpr NumberRule spring_stiffness = non_negative;  // N/m
inline constexpr NumberRule spring_damping = non_negative;    // N·s/m
inline constexpr NumberRule spacing = positive;               // m
inline constexpr NumberRule particle_mass = positive;         // kg
inline constexpr NumberRule density = positive;               // kg/m²
// A spring tears past this many rest lengths: at 1 or less a sheet at rest would shred.
inline constexpr NumberRule tear_max_stretch{1.0, true, std::nullopt};
// A strain: springs longer than (1 + max_strain) rest lengths are shortened. At 1 (100 %) or
// more it no longer limits anything a cloth does, so a value there is a mistake, most often a
// ratio of lengths (the old name max_stretch invited it: [tearing] max_stretch is one).
inline constexpr NumberRule strain_limit_max_strain{0.0, true, 1.0, true};
inline constexpr NumberRule self_collision_thickness = positive;  // m
inline constexpr NumberRule air_drag = non_negative;              // N·s/m
inline constexpr NumberRule gust{0.0, false, 1.0};                // share of the wind
inline constexpr NumberRule dt = positive;                        // s
inline constexpr NumberRule collider_radius = positive;           // m
inline constexpr NumberRule restitution{0.0, false, 1.0};
inline constexpr NumberRule friction = non_negative;
inline constexpr NumberRule fov_degrees{0.0, true, 179.0};
// A thickness of many spacings makes every particle the neighbour of every other: the pass
// turns into all pairs (a fuzzed 64² sheet with a 1 m thickness took minutes), and the flat
// sheet pushes itself apart. The shipped scenes use 0.5 to 0.75 spacings.
inline constexpr double max_thickness_spacings = 2.0;
}  // namespace scene_rules

// "KEY must be a finite number", "KEY must be >= 0, got -5", ...
std::optional<std::string> number_problem(std::string_view key, double value, NumberRule rule);
// Every component finite.
std::optional<std::string> vector_problem(std::string_view key, const Vec3d& value);
// cloth.rows or cloth.cols: a whole number from 1 to max_particles.
std::optional<std::string> grid_count_problem(std::string_view key, std::int64_t value);
// rows × cols within max_particles.
std::optional<std::string> grid_size_problem(std::int64_t rows, std::int64_t cols);
// A [row, col] pin inside the rows × cols grid.
std::optional<std::string> pin_problem(std::int64_t row, std::int64_t col, int rows, int cols);
// The self-collision thickness against the particle spacing (m; a mesh's mean edge length).
std::optional<std::string> thickness_problem(double thickness, double spacing, bool mesh);
// A plane's normal: not zero, and its length neither underflows nor overflows.
std::optional<std::string> normal_problem(const Vec3d& normal);
// Structural springs are what a cloth is: they cannot be switched off.
std::optional<std::string> structural_enabled_problem(bool enabled);
// A grid's key (rows, cols, spacing, particle_mass, layout, orientation) on a mesh cloth,
// or a mesh's key (density, pin_group) on a grid.
std::string not_for_mesh(std::string_view key);
std::string only_for_mesh(std::string_view key);
// A mesh weighed both ways: by cloth.density and by cloth.particle_mass.
std::string both_mesh_masses();

// A number as messages write it (shortest form that reads back well enough to recognise).
std::string format_number(double value);

}  // namespace weft
