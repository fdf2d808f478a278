// What loads: exact coordinates, the OBJ dialects found in the wild, and the fixes the loader makes
// (re-orientation, unreferenced vertices, triangulation, ignored lines/points), each with a warning.
#include <charconv>
#include <map>
#include <random>
#include <set>

#include <gtest/gtest.h>

#include "obj_test_support.h"

namespace rgbio {
namespace {

// Every directed edge is used at most once: the orientation is consistent.
void expect_consistently_oriented(const LoadedMesh& mesh) {
    std::set<std::pair<std::uint32_t, std::uint32_t>> directed;
    for (const rgb::Triangle& t : mesh.triangles)
        for (int i = 0; i < 3; ++i) EXPECT_TRUE(directed.insert({t[i], t[(i + 1) % 3]}).second) << "edge used twice in one direction";
}

TEST(ObjLoadFixes, CleanMeshLoadsWithoutWarnings) {
    const LoadedMesh mesh = read_obj_text(test::kOctahedron, "octahedron.obj");
    EXPECT_EQ(mesh.positions.size(), 6u);
    ASSERT_EQ(mesh.triangles.size(), 8u);
    EXPECT_EQ(mesh.triangles[0], (rgb::Triangle{0, 2, 4}));
    EXPECT_TRUE(mesh.warnings.empty());
    EXPECT_FALSE(mesh.adaptive);
}

TEST(ObjLoadFixes, CoordinatesAreExactAtSeventeenDigits) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> coordinate(-1000.0, 1000.0);
    std::vector<glm::dvec3> written;
    std::string text;
    for (int i = 0; i < 3000; ++i) {
        glm::dvec3 p(coordinate(rng), coordinate(rng), coordinate(rng));
        written.push_back(p);
        char line[128];
        std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", p.x, p.y, p.z);
        text += line;
    }
    for (int i = 0; i + 2 < 3000; i += 3) text += "f " + std::to_string(i + 1) + " " + std::to_string(i + 2) + " " + std::to_string(i + 3) + "\n";
    const LoadedMesh mesh = read_obj_text(text, "random.obj");
    ASSERT_EQ(mesh.positions.size(), written.size());
    for (std::size_t i = 0; i < written.size(); ++i) ASSERT_EQ(mesh.positions[i], written[i]) << "vertex " << i;
}

TEST(ObjLoadFixes, DialectsFromTheWild) {
    // UTF-8 BOM, CRLF, tabs, a leading '+', w and colour values, v/vt/vn forms, negative
    // indices, other keywords, and no newline at the end. The normal and the one vertex colour are
    // dropped (with warnings).
    const std::string text =
        "\xef\xbb\xbfmtllib x.mtl\r\no thing\r\nv\t+1 0 0 1\r\nv 0 1 0 0.5 0.5 0.5\r\nv 0 0 1\r\nv 1. 1e0 .5\r\n"
        "vt 0 0\r\nvn 0 0 1\r\ng part\r\nusemtl m\r\ns off\r\nf 1/1/1 2//1 3\r\nf -1/1 -2/1 -3/1";
    const LoadedMesh mesh = read_obj_text(text, "dialects.obj");
    ASSERT_EQ(mesh.positions.size(), 4u);
    EXPECT_EQ(mesh.positions[0], glm::dvec3(1, 0, 0));
    EXPECT_EQ(mesh.positions[3], glm::dvec3(1, 1, 0.5));
    ASSERT_EQ(mesh.triangles.size(), 2u);
    EXPECT_EQ(mesh.triangles[1], (rgb::Triangle{3, 2, 1}));
    ASSERT_EQ(mesh.warnings.size(), 2u);
    EXPECT_EQ(mesh.warnings[0], "dropped 1 vertex normals (vn, the first on line 8): they cannot be subdivided meaningfully (a "
                                "refined surface bends between the input's vertices, so its normals follow from its shape, not "
                                "from the input's); --normals writes the exact normals of the limit surface instead");
    EXPECT_EQ(mesh.warnings[1], "dropped the vertex colours: 3 of the 4 vertices used by faces have none (the first on line 3), "
                                "and colours are kept only when every vertex has one");
    EXPECT_TRUE(mesh.colours.empty());
    // vt 1 at corner 1 of the first face; every corner of the second.
    EXPECT_EQ(mesh.texcoords, (std::vector<glm::dvec2>{{0, 0}}));
    EXPECT_EQ(mesh.triangle_texcoords,
              (std::vector<std::array<std::uint32_t, 3>>{{0, kNoIndex, kNoIndex}, {0, 0, 0}}));
    EXPECT_EQ(mesh.face_materials.names, (std::vector<std::string>{"m"}));
    EXPECT_EQ(mesh.face_materials.of_triangle, (std::vector<std::uint32_t>{0, 0}));
    EXPECT_EQ(mesh.face_groups.names, (std::vector<std::string>{"part"}));
    EXPECT_EQ(mesh.face_objects.names, (std::vector<std::string>{"thing"}));
    EXPECT_TRUE(mesh.face_smoothing_groups.empty());  // "s off" everywhere
    EXPECT_EQ(mesh.material_libraries, (std::vector<std::string>{"x.mtl"}));
}

TEST(ObjLoadFixes, FlippedFacesAreReorientedToTheMajority) {
    std::string text = test::kOctahedron;
    text.replace(text.find("f 3 2 5"), 7, "f 2 3 5");
    text.replace(text.find("f 4 2 6"), 7, "f 2 4 6");
    const LoadedMesh mesh = read_obj_text(text, "flipped.obj");
    expect_consistently_oriented(mesh);
    EXPECT_TRUE(test::has_warning(mesh.warnings, "re-oriented 2 of 8 faces")) << mesh.warnings.size();
    EXPECT_EQ(mesh.triangles[1], (rgb::Triangle{1, 4, 2}));  // 2 3 5 flipped back to outward (0-based)
    EXPECT_EQ(mesh.triangles[0], (rgb::Triangle{0, 2, 4}));  // majority faces untouched
}

// Whether triangle t is (a, b, c) up to rotation: the same face with the same winding.
bool same_winding(const rgb::Triangle& t, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    return (t[0] == a && t[1] == b && t[2] == c) || (t[0] == b && t[1] == c && t[2] == a) || (t[0] == c && t[1] == a && t[2] == b);
}

// Three separate parts, each decided on its own: an octahedron with 2 of 8 faces flipped (keeps
// outwards), a second one with 6 of 8 flipped (keeps inwards: the majority, not "outwards", wins),
// and a square of two triangles that disagree one to one (the tie goes to its first face).
TEST(ObjLoadFixes, EachConnectedPartKeepsItsOwnMajorityAndTiesKeepTheFirstFace) {
    // Outward octahedron faces, 0-based, as in test::kOctahedron.
    const std::vector<rgb::Triangle> outward{{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    const std::vector<glm::dvec3> corners{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    std::string text;
    for (int part = 0; part < 2; ++part)  // the second octahedron 10 units along x
        for (const glm::dvec3& c : corners)
            text += "v " + std::to_string(c.x + 10 * part) + " " + std::to_string(c.y) + " " + std::to_string(c.z) + "\n";
    const auto face = [&](int part, const rgb::Triangle& t, bool flip) {
        const auto index = [&](std::uint32_t i) { return std::to_string(6 * part + i + 1); };
        text += "f " + index(t[0]) + " " + (flip ? index(t[2]) + " " + index(t[1]) : index(t[1]) + " " + index(t[2])) + "\n";
    };
    for (std::size_t i = 0; i < 8; ++i) face(0, outward[i], i == 1 || i == 6);
    for (std::size_t i = 0; i < 8; ++i) face(1, outward[i], i != 0 && i != 4);
    text += "v 20 0 0\nv 21 0 0\nv 21 1 0\nv 20 1 0\nf 13 14 15\nf 16 15 13\n";

    const LoadedMesh mesh = read_obj_text(text, "parts.obj");
    ASSERT_EQ(mesh.triangles.size(), 18u);
    EXPECT_TRUE(test::has_warning(mesh.warnings, "re-oriented 5 of 18 faces")) << (mesh.warnings.empty() ? "" : mesh.warnings.front());
    ASSERT_EQ(mesh.positions.size(), 16u);
    for (std::size_t i = 0; i < 8; ++i) {
        const rgb::Triangle& t = outward[i];
        EXPECT_TRUE(same_winding(mesh.triangles[i], t[0], t[1], t[2])) << "first octahedron, face " << i;
        EXPECT_TRUE(same_winding(mesh.triangles[8 + i], 6 + t[0], 6 + t[2], 6 + t[1])) << "second octahedron, face " << i;
    }
    EXPECT_TRUE(same_winding(mesh.triangles[16], 12, 13, 14));
    EXPECT_TRUE(same_winding(mesh.triangles[17], 12, 14, 15)) << "flipped to agree with the first face";
    expect_consistently_oriented(mesh);
}

TEST(ObjLoadFixes, UnreferencedVerticesAreRemovedAndTheRestRenumbered) {
    const std::string text = "v 9 9 9\nv 0 0 0\nv 8 8 8\nv 1 0 0\nv 0 1 0\nv 7 7 7\nf 2 4 5\n";
    const LoadedMesh mesh = read_obj_text(text, "unreferenced.obj");
    ASSERT_EQ(mesh.positions.size(), 3u);
    EXPECT_EQ(mesh.positions[0], glm::dvec3(0, 0, 0));
    EXPECT_EQ(mesh.positions[2], glm::dvec3(0, 1, 0));
    EXPECT_EQ(mesh.triangles[0], (rgb::Triangle{0, 1, 2}));
    EXPECT_TRUE(test::has_warning(mesh.warnings, "removed 3 vertices used by no face (the first on line 1)"));
}

TEST(ObjLoadFixes, QuadsAndPolygonsAreTriangulatedAndCounted) {
    // A cube of 6 quads and a separate flat hexagon.
    const std::string text =
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
        "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n"
        "v 5 0 0\nv 6 0 0\nv 6.5 1 0\nv 6 2 0\nv 5 2 0\nv 4.5 1 0\nf -6 -5 -4 -3 -2 -1\n";
    const LoadedMesh mesh = read_obj_text(text, "polygons.obj");
    EXPECT_EQ(mesh.triangles.size(), 12u + 4u);
    EXPECT_TRUE(test::has_warning(mesh.warnings, "triangulated 6 quads and 1 polygons with more than 4 vertices into 16 triangles"));
    expect_consistently_oriented(mesh);
}

TEST(ObjLoadFixes, LinesAndPointsAreIgnoredWithANotice) {
    const LoadedMesh mesh = read_obj_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\np 1\nf 1 2 3\n", "mixed.obj");
    EXPECT_EQ(mesh.triangles.size(), 1u);
    EXPECT_TRUE(test::has_warning(mesh.warnings, "ignored 2 line elements (l) and 1 point elements (p)"));
}

}  // namespace
}  // namespace rgbio
