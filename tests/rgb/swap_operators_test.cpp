// The swaps of spec §2.5 called directly: GG-swap and BB-swap undo each other inside a fully split
// parent, and the RB-swap moves the red diagonal of a two-split-edges parent and is its own inverse.
#include <gtest/gtest.h>

#include "support/checked_operators.h"
#include "support/face_expectations.h"
#include "support/octahedron_edge.h"
#include "support/oracle_checks.h"

namespace rgbtest {
namespace {

class SwapOperators : public OctahedronEdge, public testing::Test {};

TEST_F(SwapOperators, GGSwapTurnsCentreAndCornerIntoTwoBluesAndBBSwapUndoesIt) {
    const rgb::VertexId v = split_checked(mesh, a, b, rgb::SplitKind::GG);
    const rgb::VertexId w = split_checked(mesh, a, x, rgb::SplitKind::RG);
    const rgb::VertexId u = split_checked(mesh, b, x, rgb::SplitKind::RG);
    const std::vector<ExpectedFace> complete{green(1, a, v, w), green(1, v, b, u), green(1, w, u, x), green(1, v, u, w)};
    ASSERT_TRUE(has_faces(mesh, complete));

    // Centre (v,u,w) and corner (u,v,b) share v-u; the flip draws the red level-0 edge w-b.
    ASSERT_TRUE(rgb::can_gg_swap(mesh, mesh.find_edge(v, u)));
    EXPECT_FALSE(rgb::can_gg_swap(mesh, mesh.find_edge(a, v))) << "a-v has a green level-0 neighbour";
    rgb::gg_swap(mesh, mesh.find_edge(v, u));
    EXPECT_TRUE(has_faces(mesh, {blue(0, v, b, w, b, w), blue(0, b, u, w, w, b)}));

    ASSERT_TRUE(rgb::can_bb_swap(mesh, mesh.find_edge(b, w)));
    rgb::bb_swap(mesh, mesh.find_edge(b, w));
    EXPECT_TRUE(has_faces(mesh, complete));
    EXPECT_TRUE(invariants_hold(mesh));
}

TEST_F(SwapOperators, RBSwapMovesTheRedDiagonalAndIsItsOwnInverse) {
    const rgb::VertexId v = split_checked(mesh, a, b, rgb::SplitKind::GG);
    const rgb::VertexId w = split_checked(mesh, a, x, rgb::SplitKind::RG);
    // Parent (a,b,x) has a-b and a-x split; its red diagonal is v-x, between R0(v,b,x) and B0(x,w,v).
    const std::vector<ExpectedFace> variant1{green(1, w, a, v), blue(0, x, w, v, v, x), red(0, v, b, x, v, x)};
    ASSERT_TRUE(has_faces(mesh, variant1));
    ASSERT_TRUE(rgb::can_rb_swap(mesh, mesh.find_edge(v, x)));
    EXPECT_FALSE(rgb::can_rb_swap(mesh, mesh.find_edge(w, v))) << "w-v is green";
    rgb::rb_swap(mesh, mesh.find_edge(v, x));
    // The other diagonal, b-w: the blue now has its low vertex at b, the red its top at w.
    EXPECT_TRUE(has_faces(mesh, {green(1, w, a, v), blue(0, v, b, w, b, w), red(0, b, x, w, w, b)}));
    EXPECT_TRUE(invariants_hold(mesh));

    ASSERT_TRUE(rgb::can_rb_swap(mesh, mesh.find_edge(b, w)));
    rgb::rb_swap(mesh, mesh.find_edge(b, w));
    EXPECT_TRUE(has_faces(mesh, variant1));
    EXPECT_TRUE(invariants_hold(mesh));
}

}  // namespace
}  // namespace rgbtest
