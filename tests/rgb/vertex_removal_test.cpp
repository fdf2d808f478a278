// Vertex removal (spec §2.4): halves that no merge accepts (GGG, GBR) are normalised by a GG-swap or
// an RB-swap first; removability is exactly "no finer neighbour, not a base vertex".
#include <gtest/gtest.h>

#include "support/checked_operators.h"
#include "support/face_expectations.h"
#include "support/octahedron_edge.h"
#include "support/operator_printing.h"
#include "support/oracle_checks.h"

namespace rgbtest {
namespace {

class VertexRemoval : public OctahedronEdge, public testing::Test {};

TEST_F(VertexRemoval, GGGHalfIsGGSwappedThenMerged) {
    const rgb::VertexId v = split_checked(mesh, a, b, rgb::SplitKind::GG);
    const rgb::VertexId w = split_checked(mesh, a, x, rgb::SplitKind::RG);
    const rgb::VertexId u = split_checked(mesh, b, x, rgb::SplitKind::RG);
    // v's halves: its parent (a,b,x) fully split (GGG), the other parent only bisected (RR).
    EXPECT_EQ(rgb::merge_kind(mesh, v), std::nullopt);
    ASSERT_TRUE(rgb::can_remove_vertex(mesh, v));
    rgb::remove_vertex(mesh, v);
    EXPECT_FALSE(mesh.is_live(v));
    EXPECT_EQ(mesh.num_faces(), 12u);
    EXPECT_TRUE(has_faces(mesh, {green(0, b, a, y), green(1, w, u, x)}));
    EXPECT_EQ(colour_counts(mesh).blue, 1u);
    ASSERT_TRUE(invariants_hold(mesh));
    for (rgb::VertexId m : {u, w}) {
        ASSERT_TRUE(rgb::can_remove_vertex(mesh, m));
        rgb::remove_vertex(mesh, m);
        ASSERT_TRUE(invariants_hold(mesh));
    }
    EXPECT_TRUE(equals_base(mesh, base));
}

TEST_F(VertexRemoval, GBRHalfIsRBSwappedThenMerged) {
    const rgb::VertexId v = split_checked(mesh, a, b, rgb::SplitKind::GG);
    const std::vector<ExpectedFace> after_gg{red(0, a, v, x, v, x), red(0, v, b, x, v, x), red(0, b, v, y, v, y),
                                             red(0, v, a, y, v, y)};
    const rgb::VertexId w = split_checked(mesh, a, x, rgb::SplitKind::RG);
    rgb::rb_swap(mesh, mesh.find_edge(v, x));
    // w's half inside (a,b,x) is now G1(w,a,v), B0(v,b,w), R0(b,x,w): GBR, which no merge accepts.
    ASSERT_TRUE(has_faces(mesh, {green(1, w, a, v), blue(0, v, b, w, b, w), red(0, b, x, w, w, b)}));
    EXPECT_EQ(rgb::merge_kind(mesh, w), std::nullopt);
    ASSERT_TRUE(rgb::can_remove_vertex(mesh, w));
    rgb::remove_vertex(mesh, w);
    EXPECT_EQ(mesh.num_faces(), 10u);
    EXPECT_TRUE(has_faces(mesh, after_gg));
    ASSERT_TRUE(invariants_hold(mesh));
    rgb::remove_vertex(mesh, v);
    EXPECT_TRUE(equals_base(mesh, base));
}

TEST_F(VertexRemoval, BaseVerticesAndVerticesWithFinerNeighboursStay) {
    const rgb::VertexId v = split_checked(mesh, a, b, rgb::SplitKind::GG);
    const rgb::VertexId w = split_checked(mesh, a, x, rgb::SplitKind::RG);
    split_checked(mesh, b, x, rgb::SplitKind::RG);
    // v-w is a level-1 edge between two G1 of the completed parent.
    const rgb::VertexId finer = split_checked(mesh, v, w, rgb::SplitKind::GG);
    EXPECT_EQ(mesh.level(finer), 2);
    EXPECT_FALSE(rgb::can_remove_vertex(mesh, v));
    EXPECT_FALSE(rgb::can_remove_vertex(mesh, w));
    EXPECT_FALSE(rgb::can_remove_vertex(mesh, a));
    EXPECT_TRUE(rgb::can_remove_vertex(mesh, finer));
}

}  // namespace
}  // namespace rgbtest
