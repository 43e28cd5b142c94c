// A grid written as OBJ and loaded as a mesh scene against the grid builder's sheet of the
// same material: the same cloth, then step for step the same positions and velocities, bit for
// bit, and the same state hash. And meshes that are nearly that grid but not exactly (a vertex
// moved, the vertices shuffled) stay plain meshes and still hang.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "loaded_cloth.h"
#include "sim/build/cloth_builder.h"
#include "sim/core/simulation.h"
#include "sim/core/state_hash.h"
#include "sim/scene_io/scene_loader.h"

namespace weft {
namespace {

namespace fs = std::filesystem;

constexpr int rows = 9, cols = 12;
constexpr double spacing = 0.05;  // m

// Vertex r·cols + c + 1 of the grid builder's sheet with particle (0, 0) at 0: (c s, -r s, 0)
// hanging (vertical), (c s, 0, r s) lying (horizontal), each coordinate the double the grid
// builder computes, written so that it reads back exactly.
std::vector<Vec3> grid_vertices(Orientation orientation) {
    std::vector<Vec3> vertices;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) {
            const double across = c * spacing, down = r * spacing;  // m
            vertices.push_back(orientation == Orientation::vertical ? Vec3(across, -down, 0.0)
                                                                    : Vec3(across, 0.0, down));
        }
    return vertices;
}

// The OBJ text of `vertices` with one quad per cell, cell by cell in row order; quad
// corners given as 0-based grid indices mapped through `number` (0-based vertex -> its
// 1-based number in the file), wound (tl, bl, br, tr) or, `turned_over`, (tl, tr, br, bl).
std::string obj_text(const std::vector<Vec3>& vertices, const std::vector<std::uint32_t>& number,
                     bool turned_over = false) {
    std::string text;
    char line[128];
    for (const Vec3& v : vertices) {
        std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", v.x, v.y, v.z);
        text += line;
    }
    for (int r = 0; r + 1 < rows; ++r)
        for (int c = 0; c + 1 < cols; ++c) {
            const std::uint32_t tl = r * cols + c, tr = tl + 1, bl = tl + cols, br = bl + 1;
            const std::uint32_t corners[4] = {tl, turned_over ? tr : bl, br, turned_over ? bl : tr};
            text += "f";
            for (std::uint32_t corner : corners)
                text.append(" ").append(std::to_string(number[corner]));
            text += "\n";
        }
    return text;
}

std::vector<std::uint32_t> in_order() {
    std::vector<std::uint32_t> number(rows * cols);
    std::iota(number.begin(), number.end(), 1u);
    return number;
}

// The keys both scenes share: every spring family, gravity off the vertical, air drag and
// wind, and the integrator under test.
std::string shared_keys(Integrator integrator) {
    return std::string(R"(
[springs.structural]
stiffness = 600.0
damping = 0.4
[springs.shear]
enabled = true
stiffness = 350.0
damping = 0.3
[springs.bend]
enabled = true
stiffness = 60.0
damping = 0.05

[forces]
gravity = [0.5, -9.81, 0.25]
air_drag = 0.02
wind = [1.5, 0.0, 2.5]

[solver]
dt = 0.001
integrator = ")") +
           integrator_name(integrator) + "\"\n";
}

// The grid's origin, and the mesh's: the OBJ holds the sheet with particle (0, 0) at 0.
constexpr const char* origin = "origin = [-0.3, 0.45, 0.125]\n";
constexpr const char* particle_mass = "particle_mass = 0.008\n";

// A scratch folder for the scenes and their meshes, removed afterwards.
class GridAsMesh : public ::testing::Test {
  protected:
    void SetUp() override {
        // A parameterised test's name has a '/'.
        std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
        std::replace(name.begin(), name.end(), '/', '_');
        folder_ = fs::path(::testing::TempDir()) / ("grid_as_mesh_test_" + name);
        fs::create_directories(folder_);
    }
    void TearDown() override { fs::remove_all(folder_); }

    Scene load(const std::string& name, const std::string& text) {
        const fs::path path = folder_ / name;
        std::ofstream(path) << text;
        SceneLoadResult result = load_scene_file(path.string());
        EXPECT_TRUE(result.ok()) << result.error->message() << "\n" << text;
        return result.ok() ? *result.scene : Scene{};
    }

    // The grid builder's rows × cols sheet, its top row pinned.
    Scene grid_scene(Integrator integrator, Orientation orientation) {
        return load("grid.toml", std::string("[cloth]\nrows = ") + std::to_string(rows) +
                                     "\ncols = " + std::to_string(cols) + "\nspacing = " +
                                     std::to_string(spacing) + "\n" + particle_mass + origin +
                                     "orientation = \"" + orientation_name(orientation) +
                                     "\"\npins = \"top-row\"\n" + shared_keys(integrator));
    }

    // The mesh scene of `obj`, with the same material, pinned by the top row's vertex
    // numbers, or by `pins` when given.
    Scene mesh_scene(Integrator integrator, const std::string& obj,
                     std::string mass = particle_mass, std::string pins = "") {
        { std::ofstream(folder_ / "sheet.obj") << obj; }
        if (pins.empty()) {
            pins = "pins = [";
            for (int c = 0; c < cols; ++c) pins.append(c ? ", " : "").append(std::to_string(c + 1));
            pins += "]\n";
        }
        return load("mesh.toml", "[cloth]\nmesh = \"sheet.obj\"\n" + mass + origin + pins +
                                     shared_keys(integrator));
    }

    fs::path folder_;
};

struct Case {
    Integrator integrator;
    Orientation orientation;
};

class GridAsMeshSteps : public GridAsMesh, public ::testing::WithParamInterface<Case> {};

// Built: the grid builder's cloth, field by field (what the steps below depend on).
TEST_P(GridAsMeshSteps, BuildsTheGridBuildersCloth) {
    const auto [integrator, orientation] = GetParam();
    const Cloth grid = build_cloth(grid_scene(integrator, orientation));
    const Cloth mesh =
        build_cloth(mesh_scene(integrator, obj_text(grid_vertices(orientation), in_order())));
    EXPECT_EQ(mesh.rows, rows);
    EXPECT_EQ(mesh.cols, cols);
    EXPECT_EQ(mesh.spacing, spacing);
    EXPECT_FALSE(mesh.is_mesh());
    EXPECT_TRUE(testing::same_bits(mesh.positions, grid.positions));
    EXPECT_EQ(mesh.topology().masses, grid.topology().masses);
    EXPECT_EQ(mesh.topology().inverse_masses, grid.topology().inverse_masses);
    EXPECT_EQ(mesh.topology().pinned, grid.topology().pinned);
    ASSERT_EQ(mesh.topology().spring_groups.size(), 3u);
    ASSERT_EQ(mesh.topology().spring_groups.size(), grid.topology().spring_groups.size());
    for (std::size_t g = 0; g < grid.topology().spring_groups.size(); ++g) {
        const SpringGroup &m = mesh.topology().spring_groups[g],
                          &w = grid.topology().spring_groups[g];
        EXPECT_EQ(m.family, w.family);
        EXPECT_EQ(m.stiffness, w.stiffness);
        EXPECT_EQ(m.damping, w.damping);
        EXPECT_EQ(m.colour_starts, w.colour_starts) << spring_family_name(w.family);
        ASSERT_EQ(m.springs.size(), w.springs.size()) << spring_family_name(w.family);
        for (std::size_t s = 0; s < w.springs.size(); ++s) {
            EXPECT_EQ(m.springs[s].i, w.springs[s].i) << spring_family_name(w.family) << s;
            EXPECT_EQ(m.springs[s].j, w.springs[s].j) << spring_family_name(w.family) << s;
            EXPECT_EQ(m.springs[s].rest_length, w.springs[s].rest_length)
                << spring_family_name(w.family) << s;
        }
    }
    ASSERT_EQ(mesh.topology().triangles.size(), grid.topology().triangles.size());
    for (std::size_t t = 0; t < grid.topology().triangles.size(); ++t) {
        EXPECT_EQ(mesh.topology().triangles[t].a, grid.topology().triangles[t].a);
        EXPECT_EQ(mesh.topology().triangles[t].b, grid.topology().triangles[t].b);
        EXPECT_EQ(mesh.topology().triangles[t].c, grid.topology().triangles[t].c);
    }
    ASSERT_TRUE(grid_stencil_usable(mesh));
    ASSERT_EQ(mesh.topology().grid_stencil.directions.size(),
              grid.topology().grid_stencil.directions.size());
    for (std::size_t d = 0; d < grid.topology().grid_stencil.directions.size(); ++d)
        EXPECT_EQ(mesh.topology().grid_stencil.directions[d].rest_lengths,
                  grid.topology().grid_stencil.directions[d].rest_lengths);
}

// Stepped: every step's positions and velocities the same bits, and the same state hash;
// and the sheet did move (a comparison of two sheets at rest would prove nothing).
TEST_P(GridAsMeshSteps, StepsAsTheGridBuildersSheetBitForBit) {
    const auto [integrator, orientation] = GetParam();
    Simulation grid(grid_scene(integrator, orientation));
    Simulation mesh(mesh_scene(integrator, obj_text(grid_vertices(orientation), in_order())));
    const std::vector<Vec3> start = grid.cloth().positions;
    ASSERT_EQ(hash_state(mesh.cloth()), hash_state(grid.cloth()));
    for (int step = 0; step < 300; ++step) {
        ASSERT_FALSE(grid.step().diverged()) << "step " << step;
        ASSERT_FALSE(mesh.step().diverged()) << "step " << step;
        ASSERT_TRUE(testing::same_bits(mesh.cloth().positions, grid.cloth().positions))
            << "step " << step;
        ASSERT_TRUE(testing::same_bits(mesh.cloth().velocities, grid.cloth().velocities))
            << "step " << step;
        ASSERT_EQ(hash_state(mesh.cloth()), hash_state(grid.cloth())) << "step " << step;
    }
    // The bottom corner fell and swung by centimetres.
    const std::size_t corner = grid.cloth().particle_count() - 1;
    EXPECT_GT(glm::length(grid.cloth().positions[corner] - start[corner]), 0.01);
}

INSTANTIATE_TEST_SUITE_P(
    Integrators, GridAsMeshSteps,
    ::testing::Values(Case{Integrator::symplectic_euler, Orientation::vertical},
                      Case{Integrator::implicit_euler, Orientation::vertical},
                      Case{Integrator::velocity_verlet, Orientation::vertical},
                      Case{Integrator::rk4, Orientation::horizontal},
                      Case{Integrator::implicit_euler, Orientation::horizontal}),
    [](const ::testing::TestParamInfo<Case>& param_info) {
        std::string name = std::string(integrator_name(param_info.param.integrator)) + "_" +
                           orientation_name(param_info.param.orientation);
        std::replace(name.begin(), name.end(), '-', '_');
        return name;
    });

// Wound the other way, the grid keeps the file's front: the grid's triangles turned over,
// and the same springs and stencil.
TEST_F(GridAsMesh, WoundTheOtherWayKeepsTheFilesFront) {
    const Cloth grid = build_cloth(grid_scene(Integrator::symplectic_euler, Orientation::vertical));
    const Cloth mesh = build_cloth(mesh_scene(
        Integrator::symplectic_euler,
        obj_text(grid_vertices(Orientation::vertical), in_order(), /*turned_over=*/true)));
    ASSERT_TRUE(grid_stencil_usable(mesh));
    ASSERT_EQ(mesh.topology().triangles.size(), grid.topology().triangles.size());
    for (std::size_t t = 0; t < grid.topology().triangles.size(); ++t) {
        EXPECT_EQ(mesh.topology().triangles[t].a, grid.topology().triangles[t].a);
        EXPECT_EQ(mesh.topology().triangles[t].b, grid.topology().triangles[t].c);
        EXPECT_EQ(mesh.topology().triangles[t].c, grid.topology().triangles[t].b);
    }
    EXPECT_EQ(mesh.spring_count(), grid.spring_count());
}

// Given a density instead, the grid's springs and stencil still, with masses lumped from
// its triangles: an interior vertex is a corner of six of them, s² of cloth in all.
TEST_F(GridAsMesh, WithADensityTheMassesAreLumped) {
    const Cloth mesh = build_cloth(
        mesh_scene(Integrator::symplectic_euler,
                   obj_text(grid_vertices(Orientation::vertical), in_order()), "density = 0.4\n"));
    ASSERT_TRUE(grid_stencil_usable(mesh));
    double total = 0.0;  // kg
    for (double m : mesh.topology().masses) total += m;
    EXPECT_NEAR(total, 0.4 * (rows - 1) * (cols - 1) * spacing * spacing, 1e-15);
    EXPECT_NEAR(mesh.topology().masses[2 * cols + 3], 0.4 * spacing * spacing, 1e-15);
}

// Not exactly the grid: a plain mesh (one row, no stencil, its mesh extent) that hangs as
// the grid does, to within `tolerance` (m) after 200 steps.
void expect_plain_mesh_hanging_like_the_grid(Simulation& mesh, Simulation& grid,
                                             const std::vector<std::uint32_t>& number,
                                             double tolerance) {
    ASSERT_EQ(mesh.cloth().rows, 1);
    ASSERT_EQ(mesh.cloth().cols, rows * cols);
    EXPECT_TRUE(mesh.cloth().is_mesh());
    EXPECT_TRUE(mesh.cloth().topology().grid_stencil.directions.empty());
    EXPECT_EQ(mesh.cloth().spring_count(), grid.cloth().spring_count());
    for (int step = 0; step < 200; ++step) {
        ASSERT_FALSE(grid.step().diverged()) << "step " << step;
        ASSERT_FALSE(mesh.step().diverged()) << "step " << step;
    }
    double farthest = 0.0;  // m
    for (std::size_t p = 0; p < grid.cloth().particle_count(); ++p)
        farthest = std::max(farthest, glm::length(mesh.cloth().positions[number[p] - 1] -
                                                  grid.cloth().positions[p]));
    EXPECT_LT(farthest, tolerance);
}

TEST_F(GridAsMesh, AVertexOffTheGridMakesAPlainMesh) {
    std::vector<Vec3> vertices = grid_vertices(Orientation::vertical);
    vertices[4 * cols + 5].z = 1e-6;  // m, a thousandth of a millimetre out of the plane
    Simulation grid(grid_scene(Integrator::symplectic_euler, Orientation::vertical));
    Simulation mesh(mesh_scene(Integrator::symplectic_euler, obj_text(vertices, in_order())));
    // The moved vertex pulls its neighbours by about as much as it was moved.
    expect_plain_mesh_hanging_like_the_grid(mesh, grid, in_order(), 1e-5);
    // So near the grid that only the exact test tells: one rounding off.
    vertices[4 * cols + 5].z = 0.0;
    vertices[4 * cols + 5].x = std::nextafter(vertices[4 * cols + 5].x, 1.0);
    EXPECT_EQ(
        build_cloth(mesh_scene(Integrator::symplectic_euler, obj_text(vertices, in_order()))).rows,
        1);
}

TEST_F(GridAsMesh, ShuffledVerticesMakeAPlainMesh) {
    const std::vector<Vec3> placed = grid_vertices(Orientation::vertical);
    std::vector<std::uint32_t> number = in_order();
    std::shuffle(number.begin(), number.end(), std::mt19937(19));
    std::vector<Vec3> vertices(placed.size());
    for (std::size_t p = 0; p < placed.size(); ++p) vertices[number[p] - 1] = placed[p];
    std::string pins = "pins = [";
    for (int c = 0; c < cols; ++c) pins.append(c ? ", " : "").append(std::to_string(number[c]));
    pins += "]\n";
    Simulation grid(grid_scene(Integrator::symplectic_euler, Orientation::vertical));
    Simulation mesh(
        mesh_scene(Integrator::symplectic_euler, obj_text(vertices, number), particle_mass, pins));
    // The same springs summed in another order: apart by roundings only.
    expect_plain_mesh_hanging_like_the_grid(mesh, grid, number, 1e-9);
}

}  // namespace
}  // namespace weft
