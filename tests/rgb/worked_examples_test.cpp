// The worked examples of spec §9.2 (one triangle, three boundary splits and back) and §9.3
// (tetrahedron to level 2): the operator chosen before each split, the exact triangles or the
// per-step triangle and colour counts. An automatic BB-swap shows in the counts: without it the two
// blues of a completed parent would remain.
#include <algorithm>
#include <map>

#include <gtest/gtest.h>

#include "rgb/lod/refine.h"
#include "rgb/mesh/operators.h"
#include "rgb/values/loop_split.h"
#include "support/checked_operators.h"
#include "support/face_expectations.h"
#include "support/identity_tracker.h"
#include "support/operator_printing.h"
#include "support/test_meshes.h"

namespace rgbtest {
namespace {

TEST(WorkedExampleA, OneTriangleThreeBoundarySplitsAndBack) {
    rgb::Mesh mesh = make_rgb_mesh(single_triangle());
    const rgb::VertexId A(0), B(1), C(2);

    const rgb::VertexId M = split_checked(mesh, A, B, rgb::SplitKind::BoundaryG);
    const std::vector<ExpectedFace> step1{red(0, A, M, C, M, C), red(0, M, B, C, C, M)};
    ASSERT_TRUE(faces_are(mesh, step1));

    // Spec §9.2 lists the variant with red edge M-C; the normal form of spec §3.5 takes the other
    // diagonal: the split edges AB and BC share corner B, the edge leaving B counter-clockwise is
    // B->C, so the red edge runs from its midpoint N to the far corner A (and enters N, the red's top).
    const rgb::VertexId N = split_checked(mesh, B, C, rgb::SplitKind::BoundaryR);
    ASSERT_TRUE(faces_are(mesh, {green(1, B, N, M), red(0, N, C, A, A, N), blue(0, N, A, M, N, A)}));
    const rgb::VertexId P = split_checked(mesh, C, A, rgb::SplitKind::BoundaryR);
    // The blues B0(N,C,M) and B0(C,P,M) shared the red edge M-C and were BB-swapped.
    ASSERT_TRUE(faces_are(mesh, {green(1, B, N, M), green(1, P, A, M), green(1, M, N, P), green(1, N, C, P)}));
    for (rgb::VertexId v : {M, N, P}) EXPECT_EQ(mesh.level(v), 1);

    // Coarsening back: P's star is one GGG half, which needs a GG-swap before any merge applies. The
    // swap may pair the centre with either corner (spec §2.4 leaves the choice open), so the parent is
    // left in one of the two variants of the two-split-edges state: G1(B,N,M) plus a blue and a red.
    EXPECT_EQ(rgb::merge_kind(mesh, P), std::nullopt);
    ASSERT_TRUE(rgb::can_remove_vertex(mesh, P));
    rgb::remove_vertex(mesh, P);
    ASSERT_TRUE(has_faces(mesh, {green(1, B, N, M)}));
    EXPECT_EQ(colour_counts(mesh), (ColourCounts{1, 1, 1}));
    ASSERT_TRUE(rgb::can_remove_vertex(mesh, N));
    rgb::remove_vertex(mesh, N);
    ASSERT_TRUE(faces_are(mesh, step1));
    EXPECT_EQ(rgb::merge_kind(mesh, M), rgb::MergeKind::BoundaryR2);
    rgb::remove_vertex(mesh, M);
    EXPECT_TRUE(faces_are(mesh, {green(0, A, B, C)}));
}

struct TetrahedronStep {
    std::uint32_t a, b;
    rgb::SplitKind kind;
    std::size_t triangles;
    ColourCounts colours;
};

TEST(WorkedExampleB, TetrahedronToLevel1InLexicographicOrder) {
    // Spec §9.3's table, in the normal form of spec §3.5. Step 4 splits 0-3 between faces 031 and 023,
    // each bisected once with its red edge drawn to v3: both reds reach v3, the "same" case. That
    // leaves 031 with split edges 0->3 and 1->0 at corner 0; the normal form's red edge runs from the
    // midpoint of 0->3 (the edge leaving 0 counter-clockwise) to v1. So at step 5 (edge 1-3) the red
    // of 031 reaches v1 while the red of 132 (bisected at 1-2, red edge to v3) reaches v3: the
    // "opposite" case. Then 132 has split edges 1->3 and 2->1 at corner 1 (red edge from the midpoint
    // of 1->3 to v2) and 023 has 0->2 and 3->0 at corner 0 (red edge from the midpoint of 0->2 to v3):
    // at step 6 (edge 2-3) they reach v2 and v3, "opposite" again. Colour counts follow spec §1.3.
    const std::vector<TetrahedronStep> steps{
        {0, 1, rgb::SplitKind::GG, 6, {2, 4, 0}},           {0, 2, rgb::SplitKind::RG, 8, {2, 5, 1}},
        {1, 2, rgb::SplitKind::RG, 10, {4, 6, 0}},          {0, 3, rgb::SplitKind::RR_Same, 12, {6, 4, 2}},
        {1, 3, rgb::SplitKind::RR_Opposite, 14, {10, 2, 2}}, {2, 3, rgb::SplitKind::RR_Opposite, 16, {16, 0, 0}}};
    rgb::Mesh mesh = make_rgb_mesh(tetrahedron());
    EXPECT_EQ(colour_counts(mesh), (ColourCounts{4, 0, 0}));
    for (const TetrahedronStep& s : steps) {
        SCOPED_TRACE("split v" + std::to_string(s.a) + "v" + std::to_string(s.b));
        split_checked(mesh, rgb::VertexId(s.a), rgb::VertexId(s.b), s.kind);
        EXPECT_EQ(mesh.num_faces(), s.triangles);
        EXPECT_EQ(colour_counts(mesh), s.colours);
    }
    EXPECT_EQ(mesh.num_vertices(), 10u);
}

TEST(WorkedExampleB, TetrahedronLevel1To2SplitsAndSwapsPerParent) {
    // Which split applies depends only on how many edges of the two level-1 parents of the edge are
    // already split: a parent with none is a green side, any other is a red side. The tiles of a
    // parent follow from the same count (spec §1.3): 0 -> G1; 1 -> two R1; 2 -> G2, B1, R1;
    // 3 -> four G2 (the BB-swap completed it). Predict both independently of the core.
    const TestMesh tet = tetrahedron();
    const UniformLoopOracle oracle(tet.positions, tet.triangles, 2);
    rgb::Mesh mesh = make_rgb_mesh(tet);
    IdentityTracker ids(mesh, oracle);
    rgb::refine_uniform(mesh, 1);

    std::vector<std::pair<Identity, Identity>> edges;
    for (const IdentityTriangle& f : oracle.faces(1))
        for (int i = 0; i < 3; ++i) edges.emplace_back(std::min(f[i], f[(i + 1) % 3]), std::max(f[i], f[(i + 1) % 3]));
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    ASSERT_EQ(edges.size(), 24u);

    std::map<IdentityTriangle, int> splits_in_parent;
    std::map<rgb::SplitKind, int> kinds;
    auto predicted_colours = [&] {
        ColourCounts c;
        for (const IdentityTriangle& p : oracle.faces(1)) {
            const int splits = splits_in_parent[p];
            c.green += splits == 0 ? 1 : splits == 2 ? 1 : splits == 3 ? 4 : 0;
            c.red += splits == 1 ? 2 : splits == 2 ? 1 : 0;
            c.blue += splits == 2 ? 1 : 0;
        }
        return c;
    };
    for (const auto& [x, y] : edges) {
        std::vector<IdentityTriangle> parents;
        for (const IdentityTriangle& f : oracle.faces(1))
            if (std::count(f.begin(), f.end(), x) + std::count(f.begin(), f.end(), y) == 2) parents.push_back(f);
        ASSERT_EQ(parents.size(), 2u);
        const int green_sides = (splits_in_parent[parents[0]] == 0) + (splits_in_parent[parents[1]] == 0);
        for (const IdentityTriangle& p : parents) ++splits_in_parent[p];

        const rgb::HalfedgeId h = mesh.find_edge(ids.vertex_of(x), ids.vertex_of(y));
        const std::optional<rgb::SplitKind> kind = rgb::split_kind(mesh, h);
        ASSERT_TRUE(kind.has_value()) << "edge " << x << "-" << y;
        const bool rr = *kind == rgb::SplitKind::RR_Same || *kind == rgb::SplitKind::RR_Opposite;
        EXPECT_EQ(green_sides == 2, *kind == rgb::SplitKind::GG) << "edge " << x << "-" << y;
        EXPECT_EQ(green_sides == 1, *kind == rgb::SplitKind::RG) << "edge " << x << "-" << y;
        EXPECT_EQ(green_sides == 0, rr) << "edge " << x << "-" << y;
        ++kinds[*kind];
        rgb::split_edge(mesh, h);
        EXPECT_EQ(colour_counts(mesh), predicted_colours()) << "after splitting edge " << x << "-" << y;
    }
    EXPECT_EQ(mesh.num_faces(), 64u);
    EXPECT_EQ(mesh.num_vertices(), 34u);
    EXPECT_EQ(colour_counts(mesh), (ColourCounts{64, 0, 0}));
    EXPECT_EQ(kinds[rgb::SplitKind::GG] + kinds[rgb::SplitKind::RG] + kinds[rgb::SplitKind::RR_Same] +
                  kinds[rgb::SplitKind::RR_Opposite],
              24);
}

}  // namespace
}  // namespace rgbtest
