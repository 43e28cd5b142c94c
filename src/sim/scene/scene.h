// Scene: the plain values a scene file describes (see docs/scene-format.md and the design
// notes). No behaviour lives here: the loader fills it, build_cloth() and Simulation read it.
// Every field has the default a scene file gets when it does not name the key.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace weft {

using Vec3d = std::array<double, 3>;

enum class Layout { grid, offset };
enum class Orientation { vertical, horizontal };
// `list` pins grid particles by [row, col]; `vertices` and `group` pin a mesh's vertices.
enum class PinPreset { none, top_corners, top_row, list, vertices, group };

enum class Integrator {
    explicit_euler,
    symplectic_euler,
    verlet,
    velocity_verlet,
    rk4,
    implicit_euler,
};

enum class ColliderType { sphere, plane };
enum class ContactResponse { impulse, repulsion };

struct GridIndex {
    int row = 0;
    int col = 0;

    bool operator==(const GridIndex&) const = default;
};

struct ObjMesh;  // obj_reader.h

// A mesh cloth's OBJ, read once by the scene loader and shared by every copy of the scene.
// Equal when the meshes are equal, wherever they are held.
struct LoadedMesh {
    std::shared_ptr<const ObjMesh> obj;
    // m, the mean rest length of its structural springs: what a grid's spacing is to checks
    // such as the self-collision thickness's.
    double mean_edge_length = 0.0;

    bool operator==(const LoadedMesh& other) const;
};

struct ClothSpec {
    int rows = 24;                // particles from top to bottom (>= 1)
    int cols = 24;                // particles from left to right (>= 1)
    double spacing = 0.05;        // m, structural rest length (> 0)
    double particle_mass = 0.01;  // kg, every particle (> 0)
    Layout layout = Layout::grid;
    Orientation orientation = Orientation::vertical;
    Vec3d origin = {0.0, 0.0, 0.0};  // m, position of particle (0, 0)
    PinPreset pin_preset = PinPreset::top_corners;
    std::vector<GridIndex> pin_list;  // used when pin_preset == list

    // Instead of a grid, a triangle mesh (mesh_builder.h). Then rows, cols, spacing, layout
    // and orientation do not apply, pins are none, vertices or group, and the masses come
    // from density, or from particle_mass when mesh_particle_mass.
    std::string mesh;                        // OBJ path, absolute once loaded; "" = a grid
    LoadedMesh mesh_data;                    // the OBJ, set by the scene loader
    double density = 0.2;                    // kg/m², mass per area of the mesh (> 0)
    bool mesh_particle_mass = false;         // particle_mass given: every vertex weighs that
    std::vector<std::int64_t> pin_vertices;  // vertex numbers as in the OBJ (1-based)
    std::string pin_group;                   // an OBJ group (g or o) whose vertices are pinned

    bool operator==(const ClothSpec&) const = default;
};

struct SpringFamilySpec {
    bool enabled = false;    // structural springs are always enabled
    double stiffness = 0.0;  // N/m
    double damping = 0.0;    // N·s/m, along the spring

    bool operator==(const SpringFamilySpec&) const = default;
};

struct ForcesSpec {
    Vec3d gravity = {0.0, -9.81, 0.0};  // m/s²
    double air_drag = 0.0;              // N·s/m per particle: f = -air_drag (v - wind)
    Vec3d wind = {0.0, 0.0, 0.0};       // m/s
    // Gusts: the wind's speed varies by up to this share of it, and it veers by up to half that
    // share, in time, smoothly and the same on every run (gusts.h). 0: a steady wind.
    double gust = 0.0;  // 0..1

    bool operator==(const ForcesSpec&) const = default;
};

struct SolverSpec {
    Integrator integrator = Integrator::symplectic_euler;
    double dt = 0.001;  // s (> 0)

    bool operator==(const SolverSpec&) const = default;
};

struct ColliderSpec {
    ColliderType type = ColliderType::sphere;
    Vec3d center = {0.0, -1.0, 0.0};  // m, sphere
    double radius = 0.3;              // m, sphere (> 0)
    Vec3d point = {0.0, -1.0, 0.0};   // m, plane
    Vec3d normal = {0.0, 1.0, 0.0};   // plane, towards the free side; any nonzero length
    ContactResponse response = ContactResponse::impulse;
    double restitution = 0.0;  // 0 = perfectly inelastic, 1 = elastic
    double friction = 0.3;     // Coulomb coefficient (>= 0)

    bool operator==(const ColliderSpec&) const = default;
};

struct CameraSpec {
    Vec3d position = {0.0, 0.0, 3.0};  // m
    Vec3d target = {0.0, -0.5, 0.0};   // m
    double fov_degrees = 50.0;         // vertical field of view, (0, 180)

    bool operator==(const CameraSpec&) const = default;
};

struct Scene {
    std::string name = "Untitled";
    ClothSpec cloth;
    SpringFamilySpec structural{true, 800.0, 0.5};
    SpringFamilySpec shear{false, 400.0, 0.5};
    SpringFamilySpec bend{false, 100.0, 0.1};
    std::optional<double> tear_max_stretch;          // [tearing] max_stretch (> 1)
    std::optional<double> strain_limit_max_strain;   // [strain_limit] max_strain (0 to 1)
    std::optional<double> self_collision_thickness;  // [self_collision] thickness, m (> 0)
    ForcesSpec forces;
    SolverSpec solver;
    std::vector<ColliderSpec> colliders;
    // [floor] enabled: the ground drawn under the cloth is a floor, a plane collider with
    // friction (floor.h), unless the scene has a ground plane of its own or says it has none.
    bool floor_enabled = true;
    CameraSpec camera;

    bool operator==(const Scene&) const = default;
};

// The one spelling of each choice in scene files, recordings and the panel, indexed by the
// enum's value. Everything that reads or writes a choice uses these tables.
inline constexpr std::array<std::string_view, 2> layout_names = {"grid", "offset"};
inline constexpr std::array<std::string_view, 2> orientation_names = {"vertical", "horizontal"};
// The presets a grid is pinned by in a scene file; a list of pins is written as one.
inline constexpr std::array<std::string_view, 3> pin_preset_names = {"none", "top-corners",
                                                                     "top-row"};
inline constexpr std::array<std::string_view, 6> integrator_names = {
    "explicit-euler", "symplectic-euler", "verlet", "velocity-verlet", "rk4", "implicit-euler"};
// [springs.structural], [springs.shear], [springs.bend]: SpringFamily's order (cloth.h).
inline constexpr std::array<std::string_view, 3> spring_family_names = {"structural", "shear",
                                                                        "bend"};
inline constexpr std::array<std::string_view, 2> collider_type_names = {"sphere", "plane"};
inline constexpr std::array<std::string_view, 2> contact_response_names = {"impulse", "repulsion"};

// The tables' entries as C strings (each is a literal, so it ends in a NUL).
const char* layout_name(Layout layout);
const char* orientation_name(Orientation orientation);
// A pin preset's spelling; nullptr for a list of pins (or a mesh's), written as one.
const char* pin_preset_name(PinPreset preset);
const char* integrator_name(Integrator integrator);
const char* contact_response_name(ContactResponse response);
// The integrator of that spelling, if any.
std::optional<Integrator> integrator_from_name(std::string_view name);

}  // namespace weft
