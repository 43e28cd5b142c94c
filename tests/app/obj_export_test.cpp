// The cloth as OBJ (--obj): weft's own reader reads it back to the particles' exact positions
// in the dump's order and to the intact triangles, across a cut; and loads as a mesh cloth.
#include <gtest/gtest.h>

#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <tuple>

#include "app/obj_export.h"
#include "sim/core/simulation.h"
#include "sim/scene/obj_reader.h"

namespace weft::app {
namespace {

ObjMesh written_and_read(const Cloth& cloth, const std::string& name) {
    std::ostringstream out;
    write_cloth_obj(cloth, name, out);
    return read_obj_text(out.str(), "cloth.obj");
}

// Every particle's position, bit for bit, as vertex p + 1; every intact triangle as a face
// with the same corners in the same order, and no other face.
void expect_same_mesh(const Cloth& cloth, const ObjMesh& mesh) {
    ASSERT_EQ(mesh.vertices.size(), cloth.particle_count());
    for (std::size_t p = 0; p < cloth.particle_count(); ++p) {
        EXPECT_EQ(mesh.vertices[p].x, cloth.positions[p].x) << "particle " << p;
        EXPECT_EQ(mesh.vertices[p].y, cloth.positions[p].y) << "particle " << p;
        EXPECT_EQ(mesh.vertices[p].z, cloth.positions[p].z) << "particle " << p;
    }
    const auto& triangles = cloth.topology().triangles;
    ASSERT_EQ(mesh.faces.size(), triangles.size());
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        EXPECT_EQ(mesh.faces[t].count, 3);
        EXPECT_EQ(std::tie(mesh.faces[t].vertices[0], mesh.faces[t].vertices[1],
                           mesh.faces[t].vertices[2]),
                  std::tie(triangles[t].a, triangles[t].b, triangles[t].c))
            << "triangle " << t;
    }
}

Scene swinging_sheet() {
    Scene scene;
    scene.cloth.rows = 8;
    scene.cloth.cols = 10;
    scene.shear.enabled = true;
    return scene;
}

TEST(ObjExport, ReadsBackAsTheParticlesAndTrianglesOfAMovingSheet) {
    Simulation simulation(swinging_sheet());
    for (int s = 0; s < 300; ++s) ASSERT_FALSE(simulation.step().diverged());
    const ObjMesh mesh = written_and_read(simulation.cloth(), "Hanging sheet");
    expect_same_mesh(simulation.cloth(), mesh);
    EXPECT_EQ(mesh.faces.size(), 2u * 7u * 9u);  // two a cell
}

// A cut down the middle removes the triangles along it: the faces read back fall into two
// pieces that share no vertex, and every particle is still a vertex in the dump's numbering.
TEST(ObjExport, ACutSheetComesOutInTwoPiecesWithItsNumberingKept) {
    Simulation simulation(swinging_sheet());
    for (int s = 0; s < 100; ++s) ASSERT_FALSE(simulation.step().diverged());
    const std::uint32_t cols = 10;
    const std::size_t cut = simulation.cut_springs([&](const Spring& spring) {
        const std::uint32_t a = spring.i % cols, b = spring.j % cols;
        return (a <= 4 && b >= 5) || (b <= 4 && a >= 5);  // every spring across columns 4|5
    });
    ASSERT_GT(cut, 0u);
    for (int s = 0; s < 100; ++s) ASSERT_FALSE(simulation.step().diverged());
    const ObjMesh mesh = written_and_read(simulation.cloth(), "cut");
    expect_same_mesh(simulation.cloth(), mesh);
    EXPECT_EQ(mesh.faces.size(), 2u * 7u * 8u);  // the cells between columns 4 and 5 are gone
    std::set<std::uint32_t> left, right;
    for (const ObjFace& face : mesh.faces)
        for (int c = 0; c < 3; ++c)
            (face.vertices[0] % cols <= 4 ? left : right).insert(face.vertices[c]);
    for (const std::uint32_t v : left) EXPECT_EQ(right.count(v), 0u) << "vertex " << v;
}

// A deformed sheet, written out, is a mesh weft can load as a cloth: the mesh cloth built
// from it has the sheet's particles where they were and its triangles, and writes the same
// file again.
TEST(ObjExport, ADeformedSheetLoadsBackAsAMeshCloth) {
    Simulation simulation(swinging_sheet());
    for (int s = 0; s < 300; ++s) ASSERT_FALSE(simulation.step().diverged());
    std::ostringstream written;
    write_cloth_obj(simulation.cloth(), "sheet", written);
    Scene scene;
    scene.cloth.mesh = "sheet.obj";
    scene.cloth.mesh_data.obj =
        std::make_shared<ObjMesh>(read_obj_text(written.str(), "sheet.obj"));
    scene.cloth.pin_preset = PinPreset::none;
    const Simulation mesh_cloth(scene);
    expect_same_mesh(simulation.cloth(), written_and_read(mesh_cloth.cloth(), "sheet"));
    std::ostringstream again;
    write_cloth_obj(mesh_cloth.cloth(), "sheet", again);
    EXPECT_EQ(again.str(), written.str());
}

// The object's name is one token whatever the scene is called.
TEST(ObjExport, TheSceneNameBecomesOneToken) {
    Simulation simulation(swinging_sheet());
    std::ostringstream out;
    write_cloth_obj(simulation.cloth(), "Two words\nand a line", out);
    EXPECT_NE(out.str().find("\no Two_words_and_a_line\n"), std::string::npos);
    std::ostringstream unnamed;
    write_cloth_obj(simulation.cloth(), "", unnamed);
    EXPECT_NE(unnamed.str().find("\no cloth\n"), std::string::npos);
}

}  // namespace
}  // namespace weft::app
