// The mesh builder: springs, masses and pins derived from an OBJ mesh, against the grid
// builder where the mesh is a grid and against hand-counted meshes elsewhere; and a mesh
// cloth steps with every integrator.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <set>
#include <sstream>
#include <tuple>

#include "sim/build/cloth_builder.h"
#include "sim/build/mesh_builder.h"
#include "sim/core/simulation.h"

namespace weft {
namespace {

// A spring as a comparable value; rest lengths rounded to 1e-12 m so that the grid's
// c·s - (c-1)·s and the mesh's file distances compare equal.
using SpringKey = std::tuple<std::uint32_t, std::uint32_t, long long>;

std::set<SpringKey> spring_set(const Cloth& cloth, SpringFamily family) {
    std::set<SpringKey> keys;
    if (const SpringGroup* group = cloth.find_group(family))
        for (const Spring& s : group->springs)
            keys.insert(
                {std::min(s.i, s.j), std::max(s.i, s.j), std::llround(s.rest_length * 1e12)});
    return keys;
}

Scene mesh_scene(const std::string& obj_text) {
    Scene scene;
    scene.cloth.mesh = "test.obj";
    scene.cloth.mesh_data.obj = std::make_shared<ObjMesh>(read_obj_text(obj_text, "test.obj"));
    scene.cloth.pin_preset = PinPreset::none;
    return scene;
}

// The grid builder's vertical rows × cols sheet, written as OBJ: vertex r·cols + c + 1 at
// (c s, -r s, 0), one quad per cell wound as the grid's triangles are (counter-clockwise
// seen from +z); or two triangles per cell when `triangles`.
std::string grid_obj(int rows, int cols, double spacing, bool triangles = false) {
    std::ostringstream out;
    out.precision(17);
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) out << "v " << c * spacing << " " << -r * spacing << " 0\n";
    for (int r = 0; r + 1 < rows; ++r)
        for (int c = 0; c + 1 < cols; ++c) {
            const int top_left = r * cols + c + 1, top_right = top_left + 1;
            const int bottom_left = top_left + cols, bottom_right = bottom_left + 1;
            if (triangles)
                out << "f " << top_left << " " << bottom_left << " " << top_right << "\nf "
                    << top_right << " " << bottom_left << " " << bottom_right << "\n";
            else
                out << "f " << top_left << " " << bottom_left << " " << bottom_right << " "
                    << top_right << "\n";
        }
    return out.str();
}

class GridWrittenAsQuads : public ::testing::TestWithParam<std::pair<int, int>> {};

// Spring sets and interior masses only: the grid builder gives every particle the same
// mass, while lumping gives a boundary particle only the area around it (a corner a quarter
// or half of an interior one's), so their masses differ there by design. An interior particle
// is a corner of six of the split triangles (s²/2 each, a third to each corner): s² of
// cloth, the same mass as the grid's when particle_mass = density × s².
TEST_P(GridWrittenAsQuads, GetsTheGridBuildersSpringsAndInteriorMasses) {
    const auto [rows, cols] = GetParam();
    const double spacing = 0.05, density = 0.3;  // m, kg/m²
    Scene grid;
    grid.cloth.rows = rows;
    grid.cloth.cols = cols;
    grid.cloth.spacing = spacing;
    grid.cloth.particle_mass = density * spacing * spacing;
    grid.shear.enabled = true;
    grid.bend.enabled = true;
    Scene mesh = mesh_scene(grid_obj(rows, cols, spacing));
    mesh.cloth.density = density;
    mesh.shear.enabled = true;
    mesh.bend.enabled = true;
    const Cloth from_grid = build_grid_cloth(grid);
    const Cloth from_mesh = build_mesh_cloth(mesh);
    ASSERT_EQ(from_mesh.particle_count(), from_grid.particle_count());
    EXPECT_EQ(from_mesh.positions, from_grid.positions);
    for (SpringFamily family : {SpringFamily::structural, SpringFamily::shear, SpringFamily::bend})
        EXPECT_EQ(spring_set(from_mesh, family), spring_set(from_grid, family))
            << spring_family_name(family);
    double total = 0.0;
    for (std::size_t p = 0; p < from_mesh.particle_count(); ++p) {
        total += from_mesh.topology().masses[p];
        const int r = static_cast<int>(p) / cols, c = static_cast<int>(p) % cols;
        if (r > 0 && r + 1 < rows && c > 0 && c + 1 < cols) {
            EXPECT_NEAR(from_mesh.topology().masses[p], from_grid.topology().masses[p], 1e-15)
                << "particle " << p;
        }
    }
    EXPECT_NEAR(total, density * (rows - 1) * (cols - 1) * spacing * spacing, 1e-15);
}

INSTANTIATE_TEST_SUITE_P(Sizes, GridWrittenAsQuads,
                         ::testing::Values(std::pair{3, 3}, std::pair{4, 6}, std::pair{7, 5}));

TEST(MeshBuilder, SplitsQuadsAlongTheirFirstDiagonalForDrawing) {
    const Scene scene = mesh_scene("v 0 0 0\nv 0 -1 0\nv 1 -1 0\nv 1 0 0\nf 1 2 3 4\n");
    const Cloth cloth = build_mesh_cloth(scene);
    ASSERT_EQ(cloth.topology().triangles.size(), 2u);
    EXPECT_EQ(cloth.topology().triangles[0].a, 0u);
    EXPECT_EQ(cloth.topology().triangles[0].b, 1u);
    EXPECT_EQ(cloth.topology().triangles[0].c, 2u);
    EXPECT_EQ(cloth.topology().triangles[1].a, 0u);
    EXPECT_EQ(cloth.topology().triangles[1].b, 2u);
    EXPECT_EQ(cloth.topology().triangles[1].c, 3u);
    // Four sides, not the split diagonal.
    EXPECT_EQ(spring_set(cloth, SpringFamily::structural).size(), 4u);
    EXPECT_TRUE(cloth.topology().grid_stencil.directions.empty());
    EXPECT_EQ(cloth.rows, 1);
    EXPECT_EQ(cloth.cols, 4);
}

TEST(MeshBuilder, TwoTrianglesSharingAnEdgeGetOneBendSpringBetweenTheirFarCorners) {
    Scene scene = mesh_scene("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0.5\nf 1 2 3\nf 2 4 3\n");
    scene.shear.enabled = true;
    scene.bend.enabled = true;
    const Cloth cloth = build_mesh_cloth(scene);
    const std::set<SpringKey> expected_bend = {
        {0, 3, std::llround(std::sqrt(2.25) * 1e12)}};  // |(1, 1, 0.5)| = 1.5 m
    EXPECT_EQ(spring_set(cloth, SpringFamily::bend), expected_bend);
    EXPECT_EQ(spring_set(cloth, SpringFamily::structural).size(), 5u);
    EXPECT_TRUE(spring_set(cloth, SpringFamily::shear).empty());  // no quads, no shear
}

TEST(MeshBuilder, ATriangleBesideAQuadBendsAcrossTheQuadsSplitTriangle) {
    // Quad 1 2 3 4 (split 1-2-3, 1-3-4) and triangle 4 3 5 sharing side 3–4, which lies in
    // the split triangle 1-3-4: the bend spring joins 1 and 5.
    Scene scene =
        mesh_scene("v 0 0 0\nv 0 -1 0\nv 1 -1 0\nv 1 0 0\nv 2 -0.5 0\nf 1 2 3 4\nf 4 3 5\n");
    scene.bend.enabled = true;
    const Cloth cloth = build_mesh_cloth(scene);
    const std::set<SpringKey> expected = {{0, 4, std::llround(std::sqrt(4.25) * 1e12)}};
    EXPECT_EQ(spring_set(cloth, SpringFamily::bend), expected);
}

TEST(MeshBuilder, SpringsAreInCanonicalOrderBeforeColouring) {
    Scene scene = mesh_scene(grid_obj(5, 5, 0.1, true));
    scene.bend.enabled = true;
    const MeshTopology topology = derive_mesh_topology(*scene.cloth.mesh_data.obj);
    for (const auto* springs : {&topology.structural, &topology.bend})
        for (std::size_t k = 0; k < springs->size(); ++k) {
            EXPECT_LT((*springs)[k].i, (*springs)[k].j);
            if (k > 0) {
                EXPECT_LT(std::pair((*springs)[k - 1].i, (*springs)[k - 1].j),
                          std::pair((*springs)[k].i, (*springs)[k].j));
            }
        }
}

TEST(MeshBuilder, LumpedMassesSumToDensityTimesArea) {
    // A unit square fan of triangles around (0.3, 0.4) and a quad below it: 1 + 0.5 m².
    Scene scene = mesh_scene(
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.3 0.4 0\nv 0 -0.5 0\nv 1 -0.5 0\n"
        "f 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\nf 6 7 2 1\n");
    scene.cloth.density = 0.25;
    const Cloth cloth = build_mesh_cloth(scene);
    double total = 0.0;
    for (double m : cloth.topology().masses) total += m;
    EXPECT_NEAR(total, 0.25 * 1.5, 1e-15);
    EXPECT_NEAR(cloth.topology().masses[4], 0.25 * 1.0 / 3.0,
                1e-15);  // the centre: a third of each fan
}

TEST(MeshBuilder, PinsByVertexNumberOrGroup) {
    const std::string obj =
        "v 0 0 0\nv 1 0 0\nv 1 -1 0\nv 0 -1 0\ng cloth\nf 1 4 3 2\ng hem\np 1 2\n";
    Scene scene = mesh_scene(obj);
    scene.cloth.pin_preset = PinPreset::vertices;
    scene.cloth.pin_vertices = {4};
    EXPECT_EQ(build_mesh_cloth(scene).topology().pinned, (std::vector<std::uint32_t>{3}));
    scene.cloth.pin_preset = PinPreset::group;
    scene.cloth.pin_group = "hem";
    const Cloth pinned = build_mesh_cloth(scene);
    EXPECT_EQ(pinned.topology().pinned, (std::vector<std::uint32_t>{0, 1}));
    EXPECT_EQ(pinned.topology().inverse_masses[0], 0.0);
    EXPECT_GT(pinned.topology().inverse_masses[2], 0.0);

    scene.cloth.pin_group = "collar";
    const auto problem = mesh_pin_problem(scene.cloth, *scene.cloth.mesh_data.obj);
    ASSERT_TRUE(problem);
    EXPECT_NE(problem->find("'collar'"), std::string::npos) << *problem;
    EXPECT_NE(problem->find("'hem'"), std::string::npos) << *problem;  // says what there is
    EXPECT_THROW(build_mesh_cloth(scene), std::invalid_argument);
    scene.cloth.pin_preset = PinPreset::vertices;
    scene.cloth.pin_vertices = {2, 5};
    const auto out_of_range = mesh_pin_problem(scene.cloth, *scene.cloth.mesh_data.obj);
    ASSERT_TRUE(out_of_range);
    EXPECT_NE(out_of_range->find("pin 5"), std::string::npos) << *out_of_range;
}

// The topology errors, each at the line of the face (or vertex) that makes it.
void expect_refused(const std::string& obj, int line, const std::string& part) {
    const ObjMesh mesh = read_obj_text(obj, "test.obj");
    try {
        derive_mesh_topology(mesh);
        FAIL() << "built, but should have been refused:\n" << obj;
    } catch (const ObjError& error) {
        EXPECT_EQ(error.line(), line) << error.what();
        EXPECT_NE(error.reason().find(part), std::string::npos) << error.what();
    }
}

TEST(MeshBuilder, RefusesAnEdgeSharedByThreeTriangles) {
    expect_refused("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n", 8,
                   "edge 1–2 is shared by more than two faces (lines 6, 7 and 8)");
}

TEST(MeshBuilder, RefusesADegenerateTriangle) {
    expect_refused("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nf 1 2 3\nf 1 2 4\n", 6, "degenerate");
    // A quad whose second split triangle (1, 3, 4) has no area.
    expect_refused("v 0 0 0\nv 1 -1 0\nv 1 1 0\nv 0.5 0.5 0\nf 1 2 3 4\n", 5, "degenerate");
}

TEST(MeshBuilder, RefusesAVertexInNoFace) {
    expect_refused("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 5 5\nf 1 2 3\n", 4, "vertex 4 is in no face");
}

TEST(MeshBuilder, RefusesTheSameTriangleTwice) {
    expect_refused("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 3 2 1\n", 5, "fold onto each other");
    // The same, with the far corner duplicated: the bend spring would have no length.
    expect_refused("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 1 0\nf 1 2 3\nf 2 1 4\n", 6, "are at one point");
}

// A triangulated sheet of 8 × 8 vertices, 0.05 m apart, hung by its top corners.
Scene hanging_mesh_sheet(Integrator integrator) {
    Scene scene = mesh_scene(grid_obj(8, 8, 0.05, true));
    scene.cloth.pin_preset = PinPreset::vertices;
    scene.cloth.pin_vertices = {1, 8};
    scene.cloth.density = 0.2;
    scene.shear.enabled = true;
    scene.bend.enabled = true;
    scene.structural = {true, 50.0, 0.05};
    scene.bend = {true, 5.0, 0.01};
    scene.solver = {integrator, 0.0005};
    return scene;
}

class MeshCloth : public ::testing::TestWithParam<Integrator> {};

TEST_P(MeshCloth, StepsFiftyTimesWithoutDiverging) {
    Simulation simulation(hanging_mesh_sheet(GetParam()));
    for (int step = 0; step < 50; ++step) {
        const StepReport report = simulation.step();
        ASSERT_FALSE(report.diverged()) << "step " << step << ": " << *report.divergence;
    }
    const Cloth& cloth = simulation.cloth();
    EXPECT_EQ(cloth.positions[0], Vec3(0.0));     // pinned vertex 1 stays
    EXPECT_LT(cloth.positions[30].y, -0.05 * 3);  // the rest fell (y was -0.15)
}

INSTANTIATE_TEST_SUITE_P(EveryIntegrator, MeshCloth,
                         ::testing::Values(Integrator::explicit_euler, Integrator::symplectic_euler,
                                           Integrator::verlet, Integrator::velocity_verlet,
                                           Integrator::rk4, Integrator::implicit_euler),
                         [](const ::testing::TestParamInfo<Integrator>& param_info) {
                             std::string name = integrator_name(param_info.param);
                             for (char& c : name)
                                 if (c == '-') c = '_';
                             return name;
                         });

TEST(MeshCloth, HangingTriangulatedSheetStaysWholeAndFiniteUnderImplicitEuler) {
    Scene scene = hanging_mesh_sheet(Integrator::implicit_euler);
    scene.solver.dt = 0.005;  // ten times the explicit methods' step
    Simulation simulation(scene);
    const std::size_t particles = simulation.cloth().particle_count();
    const std::size_t springs = simulation.cloth().spring_count();
    for (int step = 0; step < 400; ++step) {  // 2 s: swings and settles
        const StepReport report = simulation.step();
        ASSERT_FALSE(report.diverged()) << "step " << step << ": " << *report.divergence;
    }
    const Cloth& cloth = simulation.cloth();
    EXPECT_EQ(cloth.particle_count(), particles);
    EXPECT_EQ(cloth.spring_count(), springs);
    for (std::size_t p = 0; p < cloth.particle_count(); ++p) {
        ASSERT_TRUE(std::isfinite(cloth.positions[p].x) && std::isfinite(cloth.positions[p].y) &&
                    std::isfinite(cloth.positions[p].z))
            << "particle " << p;
        // Hanging, not falling: within a few sheet lengths (0.35 m) of the pins.
        EXPECT_GT(cloth.positions[p].y, -1.0) << "particle " << p;
    }
}

}  // namespace
}  // namespace weft
