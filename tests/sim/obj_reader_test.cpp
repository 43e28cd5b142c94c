// The OBJ reader: the subset a cloth needs read exactly, everything wrong refused at its line
// with the offending token.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "sim/scene/obj_reader.h"
#include "sim/scene_io/scene_loader.h"

namespace weft {
namespace {

ObjMesh read(const std::string& text) {
    return read_obj_text(text, "mesh.obj");
}

TEST(ObjReader, ReadsVerticesFacesInEveryCornerFormAndSkipsTheLooks) {
    const ObjMesh mesh = read(
        "# a quad and a triangle\n"
        "mtllib cloth.mtl\n"
        "v 0 0 0\n"
        "v 1.5 0 0 1.0\n"  // w ignored
        "v 1.5 -1 +0.25\n"
        "\n"
        "v\t0 -1e0 0\r\n"  // tab, CRLF
        "vt 0 0\nvn 0 0 1\ns off\nusemtl red\nl 1 2\n"
        "f 1/1 4//1 3/1/1 2\n"
        "f -4 -3 -1  # relative: vertices 1, 2, 4\n");
    ASSERT_EQ(mesh.vertices.size(), 4u);
    EXPECT_EQ(mesh.vertices[1], Vec3(1.5, 0.0, 0.0));
    EXPECT_EQ(mesh.vertices[2], Vec3(1.5, -1.0, 0.25));
    EXPECT_EQ(mesh.vertices[3], Vec3(0.0, -1.0, 0.0));
    EXPECT_EQ(mesh.vertex_lines, (std::vector<int>{3, 4, 5, 7}));
    ASSERT_EQ(mesh.faces.size(), 2u);
    EXPECT_EQ(mesh.faces[0].count, 4);  // quads are kept whole: the builder splits them
    EXPECT_EQ(mesh.faces[0].vertices, (std::array<std::uint32_t, 4>{0, 3, 2, 1}));
    EXPECT_EQ(mesh.faces[0].line, 13);
    EXPECT_EQ(mesh.faces[1].count, 3);
    EXPECT_EQ(mesh.faces[1].vertices[0], 0u);
    EXPECT_EQ(mesh.faces[1].vertices[1], 1u);
    EXPECT_EQ(mesh.faces[1].vertices[2], 3u);
    EXPECT_TRUE(mesh.groups.empty());
}

TEST(ObjReader, GroupsHoldTheVerticesOfTheElementsAfterThem) {
    const ObjMesh mesh = read(
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\n"
        "o sheet\n"
        "f 1 2 3\n"
        "g top edge\n"  // two groups at once
        "f 1 3 4\n"
        "p 5 1\n"  // a point element: vertices without a face
        "g\n"      // back to no group
        "f 2 5 3\n"
        "g empty\n");
    ASSERT_EQ(mesh.groups.size(), 3u);  // "empty" got no vertices and is dropped
    EXPECT_EQ(mesh.groups[0].name, "sheet");
    EXPECT_EQ(mesh.groups[0].vertices, (std::vector<std::uint32_t>{0, 1, 2}));
    EXPECT_EQ(mesh.groups[1].name, "top");
    EXPECT_EQ(mesh.groups[1].vertices, (std::vector<std::uint32_t>{0, 2, 3, 4}));
    EXPECT_EQ(mesh.find_group("edge")->vertices, mesh.groups[1].vertices);
    EXPECT_EQ(mesh.find_group("empty"), nullptr);
}

struct BadObj {
    const char* name;
    const char* text;
    int line;           // where the error must point
    const char* quote;  // what the message must contain
};

class ObjReaderRefuses : public ::testing::TestWithParam<BadObj> {};

TEST_P(ObjReaderRefuses, NamingTheLineAndTheToken) {
    const BadObj& bad = GetParam();
    try {
        read(bad.text);
        FAIL() << "read, but should have been refused:\n" << bad.text;
    } catch (const ObjError& error) {
        EXPECT_EQ(error.path(), "mesh.obj");
        EXPECT_EQ(error.line(), bad.line) << error.what();
        EXPECT_NE(error.reason().find(bad.quote), std::string::npos) << error.what();
        EXPECT_EQ(std::string(error.what()).rfind("mesh.obj:" + std::to_string(bad.line) + ": ", 0),
                  0u)
            << error.what();
    }
}

constexpr const char* tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

INSTANTIATE_TEST_SUITE_P(
    BadInputs, ObjReaderRefuses,
    ::testing::Values(
        BadObj{"IndexPastTheVertices", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", 4, "'4'"},
        BadObj{"IndexZero", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", 4, "0"},
        BadObj{"RelativeIndexBeforeTheFirst", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n", 4, "'-4'"},
        BadObj{"IndexToAVertexDefinedLater", "v 0 0 0\nv 1 0 0\nf 1 2 3\nv 0 1 0\n", 3, "'3'"},
        BadObj{"CoordinateNotANumber", "v 0 0 0\nv 1 zero 0\n", 2, "'zero'"},
        BadObj{"CoordinateWithTrailingText", "v 0 0 0\nv 1 0 0x\n", 2, "'0x'"},
        BadObj{"CoordinateNotFinite", "v 0 0 0\nv 1 inf 0\n", 2, "'inf'"},
        BadObj{"CoordinateNaN", "v nan 0 0\n", 1, "'nan'"},
        BadObj{"CoordinateOverflows", "v 1e999 0 0\n", 1, "'1e999'"},
        BadObj{"VertexWithTwoCoordinates", "v 0 0 0\nv 1 0\n", 2, "three coordinates"},
        BadObj{"VertexWithFiveNumbers", "v 0 0 0 1 1\n", 1, "optional w"},
        BadObj{"FaceWithTwoVertices", "v 0 0 0\nv 1 0 0\nf 1 2\n", 3, "at least 3"},
        BadObj{"FaceWithFiveVertices", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 2 0\nf 1 2 3 4 5\n",
               6, "triangles"},
        BadObj{"FaceRepeatingAVertex", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -3\n", 4, "'-3'"},
        BadObj{"FaceIndexNotANumber", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 two 3\n", 4, "'two'"},
        BadObj{"FaceCornerWithBadTexture", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/x 2 3\n", 4, "'1/x'"},
        BadObj{"FaceCornerWithThreeSlashes", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1/1/1 2 3\n", 4,
               "'1/1/1/1'"},
        BadObj{"UnknownStatement", "v 0 0 0\ncurv 0 1 1 2\n", 2, "'curv'"},
        BadObj{"BinaryTokenIsEscaped", "v 0 0 \x01\xff\n", 1, "'\\x01\\xff'"},
        BadObj{"NoFaces", "v 0 0 0\nv 1 0 0\n# nothing else\n", 3, "no faces"},
        BadObj{"Empty", "", 1, "no faces"}),
    [](const ::testing::TestParamInfo<BadObj>& param_info) {
        return std::string(param_info.param.name);
    });

TEST(ObjReader, RefusesWhatIsNoRegularFileWithoutALine) {
    const std::string folder = ::testing::TempDir();
    try {
        read_obj_file(folder);
        FAIL() << "a folder was read as a mesh";
    } catch (const ObjError& error) {
        EXPECT_EQ(error.line(), 0);
        EXPECT_EQ(error.where(), folder);
        EXPECT_NE(error.reason().find("not a regular file"), std::string::npos) << error.what();
    }
    EXPECT_THROW(read_obj_file(folder + "/no-such-mesh.obj"), ObjError);
}

TEST(ObjReader, ReadsAFile) {
    const std::string path = ::testing::TempDir() + "/obj_reader_test_triangle.obj";
    std::ofstream(path) << tri << "f 1 2 3\n";
    const ObjMesh mesh = read_obj_file(path);
    EXPECT_EQ(mesh.path, path);
    EXPECT_EQ(mesh.faces.size(), 1u);
    std::filesystem::remove(path);
}

}  // namespace
}  // namespace weft
