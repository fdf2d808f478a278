// Non-manifold input is cut into a manifold the core accepts: bow-ties split into one vertex per
// fan, non-manifold edges cut apart, by rules that look only at file order (manifold_repair.h).
// Expected meshes are worked out by hand from those rules.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "obj_test_support.h"

namespace rgbio {
namespace {

using test::has_warning;

// The core accepts only oriented 2-manifolds; constructing one is the independent check.
void expect_core_accepts(const LoadedMesh& mesh) { EXPECT_NO_THROW(rgb::Mesh(mesh.positions, mesh.triangles)); }

TEST(ObjRepair, BowTieIsSplitIntoOneVertexPerFan) {
    // Two triangles touching only at vertex 1 (line 1), with colours and texture coordinates.
    const std::string text =
        "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 1 1 0 0 0 1\nv -1 0 0 1 1 0\nv -1 -1 0 0 1 1\n"
        "vt 0.5 0.5\nvt 1 0\nvt 1 1\nvt 0 0\nvt 0 1\n"
        "f 1/1 2/2 3/3\nf 1/1 4/4 5/5\n";
    const LoadedMesh mesh = read_obj_text(text, "bowtie.obj");
    // The first fan (the face on line 11) keeps vertex 1; the second gets a copy, after the others.
    ASSERT_EQ(mesh.positions.size(), 6u);
    EXPECT_EQ(mesh.positions[5], glm::dvec3(0, 0, 0));
    EXPECT_EQ(mesh.triangles, (std::vector<rgb::Triangle>{{0, 1, 2}, {5, 3, 4}}));
    EXPECT_EQ(mesh.colours[5], glm::dvec3(1, 0, 0));  // the copy keeps the vertex's colour
    EXPECT_EQ(mesh.triangle_texcoords, (std::vector<std::array<std::uint32_t, 3>>{{0, 1, 2}, {0, 3, 4}}));
    EXPECT_EQ(mesh.warnings, (std::vector<std::string>{
                                 "split 1 non-manifold vertex (bow-ties: fans of faces that touch only at the vertex) into one "
                                 "vertex per fan (1 vertex added), the first is vertex 1 on line 1"}));
    expect_core_accepts(mesh);
}

TEST(ObjRepair, ThreeFansAtOneVertexGiveTwoCopiesInFileOrder) {
    // Three triangles around vertex 4, touching only there; the third fan's copy comes second.
    const std::string text = "v 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 0\nv -1 0 0\nv -1 -1 0\nv 0 -1 0\n"
                             "f 4 1 2\nf 4 3 5\nf 4 6 7\n";
    const LoadedMesh mesh = read_obj_text(text, "three.obj");
    EXPECT_EQ(mesh.triangles, (std::vector<rgb::Triangle>{{3, 0, 1}, {7, 2, 4}, {8, 5, 6}}));
    EXPECT_TRUE(has_warning(mesh.warnings, "split 1 non-manifold vertex (bow-ties: fans of faces that touch only at the vertex) "
                                           "into one vertex per fan (2 vertices added), the first is vertex 4 on line 4"));
    expect_core_accepts(mesh);
}

TEST(ObjRepair, EdgeOfThreeFacesKeepsTheFirstOppositePairAndCutsTheThird) {
    // Edge 1-2 has the faces on lines 6 (1->2), 7 (2->1) and 8 (1->2): 6 and 7 stay joined.
    const std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n";
    const LoadedMesh mesh = read_obj_text(text, "fin.obj");
    ASSERT_EQ(mesh.positions.size(), 7u);
    EXPECT_EQ(mesh.positions[5], glm::dvec3(0, 0, 0));  // copies of vertices 1 and 2, in corner order
    EXPECT_EQ(mesh.positions[6], glm::dvec3(1, 0, 0));
    EXPECT_EQ(mesh.triangles, (std::vector<rgb::Triangle>{{0, 1, 2}, {1, 0, 3}, {5, 6, 4}}));
    EXPECT_EQ(mesh.warnings,
              (std::vector<std::string>{"cut 1 non-manifold edge (shared by more than two faces) apart, the first at the face on "
                                        "line 8: at each edge the first face in file order stays joined to the first one running "
                                        "the other way, and the other faces got their own copies of the edge's vertices (2 "
                                        "vertices added)"}));
    expect_core_accepts(mesh);
}

// docs/requests.md: non-manifold repair goes by file order, so there the face order changes the base
// mesh itself. The three faces of the test above, the last first: now the face with apex 4 (running
// 2->1) is first and the face with apex 5 is the first later one running 1->2, so those two stay joined
// and the face with apex 3 is cut off.
TEST(ObjRepair, FaceOrderDecidesWhichFacesOfANonManifoldEdgeStayJoined) {
    // Whether the faces with apexes (positions) p and q share an edge after the repair.
    auto joined = [](const LoadedMesh& mesh, const glm::dvec3& p, const glm::dvec3& q) {
        auto face_with = [&](const glm::dvec3& apex) {
            for (const rgb::Triangle& t : mesh.triangles)
                for (std::uint32_t v : t)
                    if (mesh.positions[v] == apex) return t;
            ADD_FAILURE() << "no face with that apex";
            return rgb::Triangle{};
        };
        const rgb::Triangle a = face_with(p), b = face_with(q);
        int shared = 0;
        for (std::uint32_t v : a) shared += static_cast<int>(std::count(b.begin(), b.end(), v));
        return shared == 2;
    };
    const glm::dvec3 apex3(0, 1, 0), apex4(0, -1, 0), apex5(0, 0, 1);
    const std::string vertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\n";
    const LoadedMesh first = read_obj_text(vertices + "f 1 2 3\nf 2 1 4\nf 1 2 5\n", "first.obj");
    const LoadedMesh last = read_obj_text(vertices + "f 2 1 4\nf 1 2 5\nf 1 2 3\n", "last.obj");
    EXPECT_TRUE(joined(first, apex3, apex4));
    EXPECT_FALSE(joined(first, apex5, apex4));
    EXPECT_TRUE(joined(last, apex5, apex4));
    EXPECT_FALSE(joined(last, apex3, apex4));
    expect_core_accepts(first);
    expect_core_accepts(last);
}

TEST(ObjRepair, FinOnAClosedSurfaceIsCutOffAndTheSurfaceStaysClosed) {
    // The octahedron's edge 1-3 (faces on lines 7 and 11) gains a fin on line 16.
    const std::string text = test::kOctahedron + "v 2 2 0\nf 1 3 7\n";
    const LoadedMesh mesh = read_obj_text(text, "octahedron_fin.obj");
    ASSERT_EQ(mesh.triangles.size(), 9u);
    for (int t = 0; t < 8; ++t)  // the octahedron itself is untouched
        for (int i = 0; i < 3; ++i) EXPECT_LT(mesh.triangles[t][i], 6u);
    EXPECT_EQ(mesh.triangles[8], (rgb::Triangle{7, 8, 6}));
    EXPECT_EQ(mesh.positions[7], glm::dvec3(1, 0, 0));
    EXPECT_EQ(mesh.positions[8], glm::dvec3(0, 1, 0));
    EXPECT_TRUE(has_warning(mesh.warnings, "cut 1 non-manifold edge (shared by more than two faces) apart, the first at the face on line 16"));
    const rgb::Mesh core(mesh.positions, mesh.triangles);
    EXPECT_EQ(core.num_vertices(), 9u);
}

TEST(ObjRepair, CutFaceWhoseFansWrapAroundGetsItsOwnVertex) {
    // A tetrahedron a b c e (vertices 1 2 3 4) with a fin 2 1 5 on its edge 1-2. In file order the
    // faces on lines 6 (1->2) and 7, the fin (2->1), stay joined, so the tetrahedron's face on
    // line 8 is cut off the edge; but its fans at 1 and 2 reach the kept faces around the
    // tetrahedron, so splitting fans separates nothing, and it takes a copy of vertex 1.
    const std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 1 1 1\nf 1 2 3\nf 2 1 5\nf 1 4 2\nf 2 4 3\nf 3 4 1\n";
    const LoadedMesh mesh = read_obj_text(text, "tetrahedron_fin.obj");
    ASSERT_EQ(mesh.positions.size(), 6u);
    EXPECT_EQ(mesh.positions[5], glm::dvec3(0, 0, 0));
    EXPECT_EQ(mesh.triangles, (std::vector<rgb::Triangle>{{0, 1, 2}, {1, 0, 4}, {5, 3, 1}, {1, 3, 2}, {2, 3, 0}}));
    EXPECT_TRUE(has_warning(mesh.warnings, "the first at the face on line 8"));
    EXPECT_TRUE(has_warning(mesh.warnings, "(1 vertex added)"));
    expect_core_accepts(mesh);
}

TEST(ObjRepair, TenThousandFacesOnOneEdgeAreCutIntoSeparateTriangles) {
    std::string text = "v 0 0 0\nv 1 0 0\n";
    constexpr int kFaces = 10000;
    for (int i = 0; i < kFaces; ++i) text += "v 0.5 " + std::to_string(std::cos(i * 0.001)) + " " + std::to_string(std::sin(i * 0.001)) + "\n";
    for (int i = 0; i < kFaces; ++i) text += "f 1 2 " + std::to_string(i + 3) + "\n";
    const LoadedMesh mesh = read_obj_text(text, "book.obj");
    // All faces run 1->2, so the first two stay joined; every other one gets copies of 1 and 2.
    EXPECT_EQ(mesh.positions.size(), std::size_t(2 + kFaces + 2 * (kFaces - 2)));
    EXPECT_TRUE(has_warning(mesh.warnings, "(19996 vertices added)"));
    expect_core_accepts(mesh);
}

TEST(ObjRepair, RepairIsTheSameEveryTime) {
    const std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv -1 0 0\nv -1 -1 0\n"
                             "f 1 2 3\nf 2 1 4\nf 1 2 5\nf 1 6 7\n";
    const LoadedMesh first = read_obj_text(text, "a.obj");
    const LoadedMesh second = read_obj_text(text, "b.obj");
    EXPECT_EQ(first.positions, second.positions);
    EXPECT_EQ(first.triangles, second.triangles);
    EXPECT_EQ(first.warnings, second.warnings);
    expect_core_accepts(first);
}

}  // namespace
}  // namespace rgbio
