// Each split operator's exact result (spec §2.1 side rule, §2.2) on an octahedron edge a-b with
// faces (a,b,x) and (b,a,y): which triangles appear, their colour, level and red edge. The boundary
// bisections are covered by worked example A (worked_examples_test.cpp).
#include <gtest/gtest.h>

#include "rgb/mesh/invariants.h"

#include "support/checked_operators.h"
#include "support/face_expectations.h"
#include "support/octahedron_edge.h"
#include "support/oracle_checks.h"

namespace rgbtest {
namespace {

class SplitOperators : public OctahedronEdge, public testing::Test {};

TEST_F(SplitOperators, GGSplitMakesFourRedsWithRedEdgesToTheOppositeCorners) {
    const rgb::VertexId v = split_checked(mesh, a, b, rgb::SplitKind::GG);
    EXPECT_EQ(mesh.level(v), 1);
    EXPECT_EQ(mesh.num_faces(), 10u);
    EXPECT_TRUE(has_faces(mesh, {red(0, a, v, x, v, x), red(0, v, b, x, v, x), red(0, b, v, y, v, y), red(0, v, a, y, v, y)}));
    EXPECT_TRUE(invariants_hold(mesh));
}

TEST_F(SplitOperators, RGSplitBisectsTheGreenSideAndCutsACornerOffTheRedSide) {
    const rgb::VertexId v = split_checked(mesh, a, b, rgb::SplitKind::GG);
    // The red (a,v,x) has a-x as its level-0 edge; across a-x lies a green (a,x,z).
    const rgb::VertexId z = mesh.opposite_vertex(mesh.find_halfedge(a, x));
    const rgb::VertexId w = split_checked(mesh, a, x, rgb::SplitKind::RG);
    EXPECT_EQ(mesh.num_faces(), 12u);
    // Red side (x,a,v) with its red edge at x: the blue keeps v-x, the corner at a is a G1.
    EXPECT_TRUE(has_faces(mesh, {red(0, a, w, z, w, z), red(0, w, x, z, w, z), blue(0, x, w, v, v, x), green(1, w, a, v),
                                 red(0, v, b, x, v, x)}));
    EXPECT_TRUE(invariants_hold(mesh));
}

TEST_F(SplitOperators, ThirdSplitOfAParentBBSwapsItIntoFourGreens) {
    const rgb::VertexId v = split_checked(mesh, a, b, rgb::SplitKind::GG);
    const rgb::VertexId w = split_checked(mesh, a, x, rgb::SplitKind::RG);
    const rgb::VertexId u = split_checked(mesh, b, x, rgb::SplitKind::RG);
    EXPECT_EQ(mesh.num_faces(), 14u);
    // Spec §1.3, all three edges of (a,b,x) split.
    EXPECT_TRUE(has_faces(mesh, {green(1, a, v, w), green(1, v, b, u), green(1, w, u, x), green(1, v, u, w)}));
    EXPECT_TRUE(invariants_hold(mesh));
}

TEST_F(SplitOperators, RRSplitOppositeGivesGreenBlueGreenBlue) {
    const auto [m1, m2] = make_both_sides_red(false);
    ASSERT_TRUE(has_faces(mesh, {red(0, b, m1, a, m1, a), red(0, a, m2, b, m2, b)}));
    const rgb::VertexId v = split_checked(mesh, a, b, rgb::SplitKind::RR_Opposite);
    EXPECT_TRUE(has_faces(mesh, {blue(0, a, v, m1, m1, a), green(1, v, b, m1), blue(0, b, v, m2, m2, b), green(1, v, a, m2)}));
    EXPECT_TRUE(invariants_hold(mesh));
}

TEST_F(SplitOperators, RRSplitSameKeepsTheNormalForm) {
    const auto [m1, m2] = make_both_sides_red(true);
    ASSERT_TRUE(has_faces(mesh, {red(0, b, m1, a, m1, a), red(0, m2, b, a, m2, a)}));
    const rgb::VertexId v = split_checked(mesh, a, b, rgb::SplitKind::RR_Same);
    // Side (a,b,x): split edges b->x and a->b meet at b, and b->x leaves b counter-clockwise, so the
    // red edge stays m1-a (spec §3.5). Side (b,a,y): split edges b->a and y->b meet at b, b->a leaves
    // it, so the red edge becomes v-y instead of the raw operator's m2-a (spec §2.2.3's G,B,B,G star).
    EXPECT_TRUE(has_faces(mesh, {green(1, v, b, m1), blue(0, a, v, m1, m1, a), red(0, m1, x, a, a, m1), green(1, b, v, m2),
                                 red(0, v, a, y, y, v), blue(0, v, y, m2, v, y)}));
    EXPECT_TRUE(invariants_hold(mesh));
    EXPECT_TRUE(rgb::check_normal_form(mesh).ok());
}

TEST_F(SplitOperators, RedEdgesAndCoarserSidesAreNotSplittable) {
    const rgb::VertexId v = split_checked(mesh, a, b, rgb::SplitKind::GG);
    EXPECT_EQ(rgb::split_kind(mesh, mesh.find_edge(v, x)), std::nullopt) << "red edge";
    // a-v is a level-1 green edge inside the level-0 red (a,v,x): not splittable before a-x is.
    EXPECT_EQ(rgb::split_kind(mesh, mesh.find_edge(a, v)), std::nullopt) << "edge of a coarser red";
}

}  // namespace
}  // namespace rgbtest
