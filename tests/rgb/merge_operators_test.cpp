// Each merge of spec §2.3, recognised by merge_kind and applied by merge_vertex, undoes exactly the
// split that created the vertex: the configuration before that split comes back.
#include <gtest/gtest.h>

#include "support/checked_operators.h"
#include "support/face_expectations.h"
#include "support/octahedron_edge.h"
#include "support/operator_printing.h"
#include "support/oracle_checks.h"

namespace rgbtest {
namespace {

class MergeOperators : public OctahedronEdge, public testing::Test {};

TEST_F(MergeOperators, R4MergeUndoesTheGGSplit) {
    const rgb::VertexId v = split_checked(mesh, a, b, rgb::SplitKind::GG);
    ASSERT_EQ(rgb::merge_kind(mesh, v), rgb::MergeKind::R4);
    rgb::merge_vertex(mesh, v);
    EXPECT_TRUE(equals_base(mesh, base));
}

TEST_F(MergeOperators, R2GBMergeUndoesTheRGSplit) {
    const rgb::VertexId v = split_checked(mesh, a, b, rgb::SplitKind::GG);
    const std::vector<ExpectedFace> after_gg{red(0, a, v, x, v, x), red(0, v, b, x, v, x), red(0, b, v, y, v, y),
                                             red(0, v, a, y, v, y)};
    const rgb::VertexId w = split_checked(mesh, a, x, rgb::SplitKind::RG);
    EXPECT_EQ(rgb::merge_kind(mesh, v), std::nullopt) << "v has a finer neighbour";
    ASSERT_EQ(rgb::merge_kind(mesh, w), rgb::MergeKind::R2GB);
    rgb::merge_vertex(mesh, w);
    EXPECT_EQ(mesh.num_faces(), 10u);
    EXPECT_TRUE(has_faces(mesh, after_gg));
    EXPECT_TRUE(invariants_hold(mesh));
}

TEST_F(MergeOperators, GBGBMergeUndoesTheOppositeRRSplit) {
    const auto [m1, m2] = make_both_sides_red(false);
    const rgb::VertexId v = split_checked(mesh, a, b, rgb::SplitKind::RR_Opposite);
    ASSERT_EQ(rgb::merge_kind(mesh, v), rgb::MergeKind::GBGB);
    rgb::merge_vertex(mesh, v);
    EXPECT_EQ(mesh.num_faces(), 12u);
    EXPECT_TRUE(has_faces(mesh, {red(0, b, m1, a, m1, a), red(0, a, m2, b, m2, b)}));
    EXPECT_TRUE(invariants_hold(mesh));
}

TEST_F(MergeOperators, G2B2MergeUndoesTheSameRRSplit) {
    const auto [m1, m2] = make_both_sides_red(true);
    const rgb::VertexId v = split_checked(mesh, a, b, rgb::SplitKind::RR_Same);
    // The split keeps the normal form (red edge v-y on the side of y); the raw RR-split of spec
    // §2.2.3 leaves the other diagonal m2-a, the G,B,B,G star this merge undoes. One RB-swap gets there.
    ASSERT_EQ(rgb::merge_kind(mesh, v), std::nullopt);
    rgb::rb_swap(mesh, mesh.find_edge(v, y));
    ASSERT_TRUE(has_faces(mesh, {blue(0, a, v, m1, m1, a), green(1, v, b, m1), green(1, b, v, m2), blue(0, v, a, m2, a, m2)}));
    ASSERT_EQ(rgb::merge_kind(mesh, v), rgb::MergeKind::G2B2);
    rgb::merge_vertex(mesh, v);
    EXPECT_EQ(mesh.num_faces(), 12u);
    EXPECT_TRUE(has_faces(mesh, {red(0, b, m1, a, m1, a), red(0, m2, b, a, m2, a)}));
    EXPECT_TRUE(invariants_hold(mesh));
}

TEST(BoundaryMerges, GBAndR2MergesUndoTheBoundaryBisections) {
    const TestMesh triangle = single_triangle();
    rgb::Mesh mesh = make_rgb_mesh(triangle);
    const rgb::VertexId A(0), B(1), C(2);
    const rgb::VertexId M = split_checked(mesh, A, B, rgb::SplitKind::BoundaryG);
    const rgb::VertexId N = split_checked(mesh, B, C, rgb::SplitKind::BoundaryR);
    // The split leaves the normal form, red edge N-A (spec §3.5); the boundary GB-merge undoes the
    // raw bisection's diagonal M-C, one RB-swap away.
    ASSERT_EQ(rgb::merge_kind(mesh, N), std::nullopt);
    rgb::rb_swap(mesh, mesh.find_edge(N, A));
    ASSERT_EQ(rgb::merge_kind(mesh, N), rgb::MergeKind::BoundaryGB);
    rgb::merge_vertex(mesh, N);
    EXPECT_TRUE(faces_are(mesh, {red(0, A, M, C, M, C), red(0, M, B, C, C, M)}));
    ASSERT_EQ(rgb::merge_kind(mesh, M), rgb::MergeKind::BoundaryR2);
    rgb::merge_vertex(mesh, M);
    EXPECT_TRUE(equals_base(mesh, triangle));
}

}  // namespace
}  // namespace rgbtest
