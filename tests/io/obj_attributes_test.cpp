// What rides on the mesh: texture coordinates per corner (through triangulation, flips and
// compaction), vertex colours, and the usemtl/g/o/s labels of each face. Expected values are read
// off the OBJ text by hand.
#include <gtest/gtest.h>

#include "obj_test_support.h"

namespace rgbio {
namespace {

using Corners = std::vector<std::array<std::uint32_t, 3>>;
using test::has_warning;

TEST(ObjAttributes, QuadCornersKeepTheirTextureCoordinates) {
    // A convex quad: ear clipping cuts its first corner off, giving corners (4 1 2) and (2 3 4).
    const std::string text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n";
    const LoadedMesh mesh = read_obj_text(text, "quad.obj");
    EXPECT_EQ(mesh.triangles, (std::vector<rgb::Triangle>{{3, 0, 1}, {1, 2, 3}}));
    EXPECT_EQ(mesh.triangle_texcoords, (Corners{{3, 0, 1}, {1, 2, 3}}));
    EXPECT_EQ(mesh.texcoords, (std::vector<glm::dvec2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}));
}

TEST(ObjAttributes, FlippingATriangleFlipsItsTextureCoordinates) {
    // The octahedron's second face written backwards, with texture coordinates 1 2 3 on its
    // corners 2 3 5 and 4 5 6 on the first face. Re-orientation gives 3 2 5: corner data follows.
    std::string text = test::kOctahedron;
    text.replace(text.find("f 1 3 5"), 7, "f 1/4 3/5 5/6");
    text.replace(text.find("f 3 2 5"), 7, "f 2/1 3/2 5/3");
    text = "vt 0 0\nvt 1 0\nvt 0 1\nvt 0.5 0\nvt 0.5 0.5\nvt 0 0.5\n" + text;
    const LoadedMesh mesh = read_obj_text(text, "flipped.obj");
    EXPECT_TRUE(has_warning(mesh.warnings, "re-oriented 1 of 8 faces"));
    EXPECT_EQ(mesh.triangles[1], (rgb::Triangle{1, 4, 2}));  // vertices 2 5 3
    ASSERT_EQ(mesh.triangle_texcoords.size(), 8u);
    EXPECT_EQ(mesh.triangle_texcoords[1], (std::array<std::uint32_t, 3>{0, 2, 1}));  // still vertex 2 -> vt 1, 5 -> 3, 3 -> 2
    EXPECT_EQ(mesh.triangle_texcoords[0], (std::array<std::uint32_t, 3>{3, 4, 5}));
    EXPECT_EQ(mesh.triangle_texcoords[2], (std::array<std::uint32_t, 3>{kNoIndex, kNoIndex, kNoIndex}));
}

TEST(ObjAttributes, UnusedTextureCoordinatesAreDroppedAndTheRestRenumbered) {
    const std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 9 9\nvt 0 0\nvt 8 8\nvt 1 0\nvt 0 1\nf 1/2 2/4 3/-1\n";
    const LoadedMesh mesh = read_obj_text(text, "unused.obj");
    EXPECT_EQ(mesh.texcoords, (std::vector<glm::dvec2>{{0, 0}, {1, 0}, {0, 1}}));
    EXPECT_EQ(mesh.triangle_texcoords, (Corners{{0, 1, 2}}));
    EXPECT_TRUE(mesh.warnings.empty());
}

TEST(ObjAttributes, TextureCoordinateFormsAndTheirW) {
    // vt u (v = 0), vt u v w with w = 0 (kept quietly) and w = 0.5 (dropped, reported).
    const std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.25\nvt 0.5 0.75 0\nvt 1 1 0.5\nf 1/1/1 2/2/1 3/3/1\n";
    const LoadedMesh mesh = read_obj_text(text, "vt.obj");
    EXPECT_EQ(mesh.texcoords, (std::vector<glm::dvec2>{{0.25, 0}, {0.5, 0.75}, {1, 1}}));
    EXPECT_TRUE(has_warning(mesh.warnings, "dropped the third texture coordinate (w) of 1 vt lines (the first on line 6)"));
}

TEST(ObjAttributes, TextureCoordinateIndexErrorsNameTheirLine) {
    const std::string head = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\n";
    const ObjError range = test::load_error(head + "f 1/1 2/2 3/1\n");
    EXPECT_EQ(range.problem(), ObjProblem::FaceIndexOutOfRange);
    EXPECT_EQ(range.line(), 5u);
    EXPECT_NE(range.reason().find("texture coordinate index 2 is out of range (1 texture coordinates (vt) defined before this line)"),
              std::string::npos)
        << range.what();
    EXPECT_EQ(test::load_error(head + "f 1/0 2/1 3/1\n").problem(), ObjProblem::FaceIndexZero);
    EXPECT_EQ(test::load_error(head + "f 1/1/1/1 2 3\n").problem(), ObjProblem::Syntax);
    EXPECT_EQ(test::load_error(head + "f 1/x 2 3\n").problem(), ObjProblem::Syntax);
    EXPECT_EQ(test::load_error("vt\n").problem(), ObjProblem::Syntax);
    EXPECT_EQ(test::load_error("vt nan 0\n").problem(), ObjProblem::NonFiniteCoordinate);
}

TEST(ObjAttributes, VertexColoursAsMeshLabWritesThem) {
    const std::string text = "v 0 0 0 1 0 0\nv 1 0 0 0 0.5 0\nv 0 1 0 0 0 0.25\nv 5 5 5 1 1 1\nf 1 2 3\n";
    const LoadedMesh mesh = read_obj_text(text, "colours.obj");
    // The unused vertex goes, with its colour.
    EXPECT_EQ(mesh.colours, (std::vector<glm::dvec3>{{1, 0, 0}, {0, 0.5, 0}, {0, 0, 0.25}}));
}

TEST(ObjAttributes, ColoursAreDroppedWhenAUsedVertexHasNone) {
    // Vertex 4 (used) has none; vertex 5 (unused) does not count. A w value is not a colour.
    const std::string text = "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nv 1 1 0 1\nv 9 9 9\nf 1 2 3\nf 2 4 3\n";
    const LoadedMesh mesh = read_obj_text(text, "partial.obj");
    EXPECT_TRUE(mesh.colours.empty());
    EXPECT_TRUE(has_warning(mesh.warnings, "dropped the vertex colours: 1 of the 4 vertices used by faces have none (the first on "
                                           "line 4), and colours are kept only when every vertex has one"));
    EXPECT_EQ(test::load_error("v 0 0 0 1 inf 0\n").problem(), ObjProblem::NonFiniteCoordinate);
}

TEST(ObjAttributes, FacesCarryTheirMaterialGroupObjectAndSmoothingGroup) {
    // Faces before any usemtl/g/o have none; names are listed in order of first use by a face, so
    // the unused material "never" is not there; "s off" and "s 0" are group 0.
    const std::string text =
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 2 0 0\n"
        "f 1 2 3\n"
        "usemtl never\nusemtl  red \ng left arm\no body\ns 2\nf 2 4 3\n"
        "usemtl blue\ng\ns off\nf 2 5 4\n"
        "usemtl red\ng right\no\ns 0\nf 5 2 1\n";
    const LoadedMesh mesh = read_obj_text(text, "labels.obj");
    EXPECT_EQ(mesh.face_materials.names, (std::vector<std::string>{"red", "blue"}));
    EXPECT_EQ(mesh.face_materials.of_triangle, (std::vector<std::uint32_t>{kNoIndex, 0, 1, 0}));
    EXPECT_EQ(mesh.face_groups.names, (std::vector<std::string>{"left arm", "right"}));
    EXPECT_EQ(mesh.face_groups.of_triangle, (std::vector<std::uint32_t>{kNoIndex, 0, kNoIndex, 1}));
    EXPECT_EQ(mesh.face_objects.names, (std::vector<std::string>{"body"}));
    EXPECT_EQ(mesh.face_objects.of_triangle, (std::vector<std::uint32_t>{kNoIndex, 0, 0, kNoIndex}));
    EXPECT_EQ(mesh.face_smoothing_groups, (std::vector<std::uint32_t>{0, 2, 0, 0}));
    EXPECT_EQ(test::load_error("s on\n").problem(), ObjProblem::Syntax);
}

TEST(ObjAttributes, LabelsFollowTheTrianglesOfAPolygon) {
    const std::string text = "mtllib a.mtl b.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nf 1 2 5\nusemtl m\nf 1 2 3 4\n";
    const LoadedMesh mesh = read_obj_text(text, "polygon.obj");
    EXPECT_EQ(mesh.face_materials.of_triangle, (std::vector<std::uint32_t>{kNoIndex, 0, 0}));
    EXPECT_TRUE(mesh.face_groups.empty());
    EXPECT_TRUE(mesh.face_smoothing_groups.empty());
    EXPECT_TRUE(mesh.triangle_texcoords.empty());
    EXPECT_EQ(mesh.material_libraries, (std::vector<std::string>{"a.mtl", "b.mtl"}));
    EXPECT_TRUE(mesh.materials.empty());  // text in memory: no library is read
}

}  // namespace
}  // namespace rgbio
