// The Far oracle checked against values computed by hand from the rules (docs/loop-creases.md): Loop's
// original weights, the crease, corner and dart rules, uniform creasing, the two boundary options and
// a seamless UV channel. Exact octahedra keep the hand computations short: the base vertices are the
// unit axis vectors, so every neighbour sum is a few eighths.
#include <algorithm>
#include <stdexcept>

#include <gtest/gtest.h>

#include "osd_far.h"
#include "support/test_meshes.h"

namespace osdoracle {
namespace {

constexpr double exact = 1e-15;  // every expected value below is a short dyadic fraction

// v0 = +x, v1 = -x, v2 = +y, v3 = -y, v4 = +z, v5 = -z; faces counter-clockwise from outside.
FarInput octahedron() {
    FarInput in;
    in.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    in.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    return in;
}

// The four edges around the equator z = 0.
std::vector<SharpEdge> equator(double sharpness) {
    return {{0, 2, sharpness}, {2, 1, sharpness}, {1, 3, sharpness}, {3, 0, sharpness}};
}

// Follows a vertex through vertex children: its index at level `level`.
int descendant(const FarRefinement& r, int vertex, int level) {
    for (int k = 0; k < level; ++k) vertex = r.levels[k].vertex_child[vertex];
    return vertex;
}

// The vertex Far inserted on the edge {a, b} of level k, as an index of level k+1.
int edge_child(const FarRefinement& r, int k, int a, int b) {
    for (const FarEdge& e : r.levels[k].edges)
        if ((e.a == a && e.b == b) || (e.a == b && e.b == a)) return e.child;
    throw std::logic_error("no such edge");
}

double sharpness_of(const FarRefinement& r, int k, int a, int b) {
    for (const FarEdge& e : r.levels[k].edges)
        if ((e.a == a && e.b == b) || (e.a == b && e.b == a)) return e.sharpness;
    throw std::logic_error("no such edge");
}

void expect_near(const glm::dvec3& actual, const glm::dvec3& expected, double tolerance = exact) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

// Valence 4: beta = (5/8 - (3/8 + cos(pi/2)/4)^2) / 4 = 31/256, so the vertex keeps 1 - 4 beta = 33/64.
// Level 1: the neighbours of +x sum to zero, x = 33/64. Level 2: its four neighbours are the edge
// points 3/8 (x + y) etc., summing to (3/2, 0, 0): x = 33/64 * 33/64 + 31/256 * 3/2 = 1833/4096.
// Limit (spec §4.2): c = 8 alpha / (3 + 8 alpha) with alpha = 31/64 gives c = 31/55, x = 24/55.
TEST(OsdFarOracle, SmoothVertexFollowsLoopsOriginalWeights) {
    const FarRefinement r = refine_uniform(octahedron(), 2);
    expect_near(r.levels[1].positions[descendant(r, 0, 1)], {33.0 / 64.0, 0, 0});
    expect_near(r.levels[2].positions[descendant(r, 0, 2)], {1833.0 / 4096.0, 0, 0});
    expect_near(r.limit_positions[descendant(r, 0, 2)], {24.0 / 55.0, 0, 0});
    // Smooth edge point: 3/8 (x + y) + 1/8 (z - z).
    expect_near(r.levels[1].positions[edge_child(r, 0, 0, 2)], {3.0 / 8.0, 3.0 / 8.0, 0});
    EXPECT_EQ(r.levels[1].rules[descendant(r, 0, 1)], VertexRule::smooth);
}

TEST(OsdFarOracle, OriginsNameTheParentVertexOrEdge) {
    const FarRefinement r = refine_uniform(octahedron(), 2);
    ASSERT_EQ(r.levels.size(), 3u);
    for (int k = 0; k < 2; ++k) {
        const FarLevel& coarse = r.levels[k];
        const FarLevel& fine = r.levels[k + 1];
        EXPECT_EQ(fine.positions.size(), coarse.positions.size() + coarse.edges.size());
        EXPECT_EQ(fine.triangles.size(), 4 * coarse.triangles.size());
        for (std::size_t v = 0; v < coarse.positions.size(); ++v) {
            const VertexOrigin& o = fine.origins[coarse.vertex_child[v]];
            EXPECT_FALSE(o.on_edge);
            EXPECT_EQ(o.a, static_cast<int>(v));
        }
        for (const FarEdge& e : coarse.edges) {
            const VertexOrigin& o = fine.origins[e.child];
            EXPECT_TRUE(o.on_edge);
            EXPECT_EQ(std::minmax(o.a, o.b), std::minmax(e.a, e.b));
        }
    }
    EXPECT_TRUE(r.levels[0].origins.empty());
    EXPECT_TRUE(r.levels[2].vertex_child.empty());
}

// +x has the sharp neighbours +y and -y: level 1 3/4 x + 1/8 (y - y) = 3/4; its sharp edges end at the
// midpoints (1/2, +-1/2, 0), so level 2 gives 3/4 * 3/4 + 1/8 (1/2 + 1/2) = 11/16; the limit is the
// cubic B-spline's 2/3 x + 1/6 (y - y) = 2/3. The poles have no sharp edge and keep Loop's rule.
TEST(OsdFarOracle, CreaseVertexMovesAlongItsTwoSharpEdgesOnly) {
    FarInput in = octahedron();
    in.creases = equator(infinite_sharpness);
    const FarRefinement r = refine_uniform(in, 2);
    EXPECT_EQ(r.levels[0].rules[0], VertexRule::crease);
    EXPECT_EQ(r.levels[0].rules[4], VertexRule::smooth);
    expect_near(r.levels[1].positions[descendant(r, 0, 1)], {0.75, 0, 0});
    expect_near(r.levels[2].positions[descendant(r, 0, 2)], {11.0 / 16.0, 0, 0});
    expect_near(r.limit_positions[descendant(r, 0, 2)], {2.0 / 3.0, 0, 0});
    expect_near(r.levels[1].positions[edge_child(r, 0, 0, 2)], {0.5, 0.5, 0});       // crease edge: midpoint
    expect_near(r.levels[1].positions[edge_child(r, 0, 0, 4)], {3.0 / 8.0, 0, 3.0 / 8.0});  // smooth edge
    expect_near(r.levels[1].positions[descendant(r, 4, 1)], {0, 0, 33.0 / 64.0});
    // Children of a sharp edge are sharp, edges inside a face are smooth.
    const int x1 = descendant(r, 0, 1), m02 = edge_child(r, 0, 0, 2), m04 = edge_child(r, 0, 0, 4);
    EXPECT_EQ(sharpness_of(r, 1, x1, m02), infinite_sharpness);
    EXPECT_EQ(sharpness_of(r, 1, x1, m04), 0.0);
    EXPECT_EQ(sharpness_of(r, 1, m02, m04), 0.0);
}

TEST(OsdFarOracle, CornerTagAndThreeSharpEdgesKeepTheVertexInPlace) {
    FarInput in = octahedron();
    in.corners = {{0, infinite_sharpness}};
    in.creases = {{4, 0}, {4, 2}, {4, 1}};  // three sharp edges at the pole +z
    const FarRefinement r = refine_uniform(in, 3);
    EXPECT_EQ(r.levels[0].rules[0], VertexRule::corner);
    EXPECT_EQ(r.levels[0].rules[4], VertexRule::corner);
    for (int k = 0; k <= 3; ++k) {
        expect_near(r.levels[k].positions[descendant(r, 0, k)], {1, 0, 0});
        expect_near(r.levels[k].positions[descendant(r, 4, k)], {0, 0, 1});
    }
    expect_near(r.limit_positions[descendant(r, 0, 3)], {1, 0, 0});
    expect_near(r.limit_positions[descendant(r, 4, 3)], {0, 0, 1});
}

// One sharp edge (a dart at each end): both ends keep the smooth vertex rule, the edge point is the
// midpoint.
TEST(OsdFarOracle, DartKeepsTheSmoothVertexRuleWithAMidpointOnItsSharpEdge) {
    FarInput in = octahedron();
    in.creases = {{4, 0}};
    const FarRefinement r = refine_uniform(in, 1);
    EXPECT_EQ(r.levels[0].rules[4], VertexRule::dart);
    EXPECT_EQ(r.levels[0].rules[0], VertexRule::dart);
    expect_near(r.levels[1].positions[descendant(r, 4, 1)], {0, 0, 33.0 / 64.0});
    expect_near(r.levels[1].positions[descendant(r, 0, 1)], {33.0 / 64.0, 0, 0});
    expect_near(r.levels[1].positions[edge_child(r, 0, 4, 0)], {0.5, 0, 0.5});
    EXPECT_EQ(r.levels[1].rules[descendant(r, 4, 1)], VertexRule::dart);
}

// Sharpness 1: crease rules from level 0 to 1, smooth from level 1 on. Level 2 of +x: smooth rule over
// its level-1 ring, the crease midpoints (1/2, +-1/2, 0) and the smooth edge points (3/8, 0, +-3/8),
// which sum to (7/4, 0, 0): x = 33/64 * 3/4 + 31/256 * 7/4 = 613/1024.
TEST(OsdFarOracle, SemiSharpCreaseIsSharpForItsSharpnessInLevelsThenSmooth) {
    FarInput in = octahedron();
    in.creases = equator(1.0);
    const FarRefinement one = refine_uniform(in, 2);
    EXPECT_EQ(one.levels[0].rules[0], VertexRule::crease);
    EXPECT_EQ(one.levels[1].rules[descendant(one, 0, 1)], VertexRule::smooth);
    EXPECT_EQ(sharpness_of(one, 1, descendant(one, 0, 1), edge_child(one, 0, 0, 2)), 0.0);
    expect_near(one.levels[1].positions[descendant(one, 0, 1)], {0.75, 0, 0});
    expect_near(one.levels[2].positions[descendant(one, 0, 2)], {613.0 / 1024.0, 0, 0});

    in.creases = equator(2.0);
    const FarRefinement two = refine_uniform(in, 2);
    EXPECT_EQ(two.levels[1].rules[descendant(two, 0, 1)], VertexRule::crease);
    EXPECT_EQ(sharpness_of(two, 1, descendant(two, 0, 1), edge_child(two, 0, 0, 2)), 1.0);
    expect_near(two.levels[2].positions[descendant(two, 0, 2)], {11.0 / 16.0, 0, 0});
}

// Without the face (+x, -y, -z), +x is a boundary vertex between -y and -z: (1/8, 3/4, 1/8) gives
// (3/4, -1/8, -1/8), then with the boundary midpoints (1/2, -1/2, 0) and (1/2, 0, -1/2):
// (11/16, -5/32, -5/32), the values OpenMesh and CGAL give (docs/toolchain.md §4).
TEST(OsdFarOracle, BoundaryVertexUsesTheCreaseRuleAlongTheBoundary) {
    FarInput in = octahedron();
    in.triangles.pop_back();
    const FarRefinement r = refine_uniform(in, 2);
    EXPECT_EQ(r.levels[0].rules[0], VertexRule::crease);
    expect_near(r.levels[1].positions[descendant(r, 0, 1)], {0.75, -0.125, -0.125});
    expect_near(r.levels[2].positions[descendant(r, 0, 2)], {11.0 / 16.0, -5.0 / 32.0, -5.0 / 32.0});
}

// A vertex with one face: edge-only moves it by the boundary rule, edge-and-corner pins it.
TEST(OsdFarOracle, BoundaryOptionDecidesWhetherAOneFaceVertexMoves) {
    FarInput in;
    in.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    in.triangles = {{0, 1, 2}};
    const FarRefinement edge_only = refine_uniform(in, 1);
    EXPECT_EQ(edge_only.levels[0].rules[0], VertexRule::crease);
    EXPECT_EQ(edge_only.levels[0].vertex_sharpness[0], 0.0);
    expect_near(edge_only.levels[1].positions[descendant(edge_only, 0, 1)], {0.125, 0.125, 0});

    in.boundary = BoundaryInterpolation::edge_and_corner;
    const FarRefinement edge_and_corner = refine_uniform(in, 2);
    EXPECT_EQ(edge_and_corner.levels[0].rules[0], VertexRule::corner);
    EXPECT_EQ(edge_and_corner.levels[0].vertex_sharpness[0], infinite_sharpness);
    expect_near(edge_and_corner.levels[2].positions[descendant(edge_and_corner, 0, 2)], {0, 0, 0});
    expect_near(edge_and_corner.levels[1].positions[edge_child(edge_and_corner, 0, 0, 1)], {0.5, 0, 0});
}

// A flat mesh whose UVs are its x and y: with seamless UVs and no linear option, UVs follow exactly the
// positions' rules, so every UV is the x, y of its corner's position, at every level and in the limit.
// With "corners only" the two one-face corners of the grid keep their UV while their position moves.
TEST(OsdFarOracle, SeamlessUvsOnAFlatMeshFollowThePositions) {
    rgbtest::TestMesh grid = rgbtest::grid(3, 2);
    FarInput in;
    for (glm::dvec3 p : grid.positions) in.positions.push_back({p.x, p.y, 0.0});
    for (const auto& t : grid.triangles) in.triangles.push_back({int(t[0]), int(t[1]), int(t[2])});
    UvChannel uv;
    for (const glm::dvec3& p : in.positions) uv.values.push_back({p.x, p.y});
    uv.corners = in.triangles;
    uv.interpolation = UvInterpolation::none;
    in.uv = uv;
    const FarRefinement r = refine_uniform(in, 3);
    for (int k = 0; k <= 3; ++k)
        for (std::size_t t = 0; t < r.levels[k].triangles.size(); ++t)
            for (int c = 0; c < 3; ++c) {
                const glm::dvec3& p = r.levels[k].positions[r.levels[k].triangles[t][c]];
                EXPECT_NEAR(r.levels[k].uv[t][c].x, p.x, 1e-14);
                EXPECT_NEAR(r.levels[k].uv[t][c].y, p.y, 1e-14);
            }
    for (std::size_t t = 0; t < r.levels[3].triangles.size(); ++t)
        for (int c = 0; c < 3; ++c) {
            const glm::dvec3& p = r.limit_positions[r.levels[3].triangles[t][c]];
            EXPECT_NEAR(r.limit_uv[t][c].x, p.x, 1e-14);
            EXPECT_NEAR(r.limit_uv[t][c].y, p.y, 1e-14);
        }

    in.uv->interpolation = UvInterpolation::corners_only;
    const FarRefinement corners = refine_uniform(in, 2);
    for (int corner : {3, 8}) {  // (3, 0) and (0, 2): one face each
        const int v = descendant(corners, corner, 2);
        const FarLevel& level = corners.levels[2];
        EXPECT_NE(level.positions[v], in.positions[corner]);
        for (std::size_t t = 0; t < level.triangles.size(); ++t)
            for (int c = 0; c < 3; ++c) {
                if (level.triangles[t][c] == v) {
                    EXPECT_EQ(level.uv[t][c], in.uv->values[corner]);
                }
            }
    }
}

TEST(OsdFarOracle, RejectsInputItCannotRepresent) {
    FarInput in = octahedron();
    in.creases = {{0, 1}};  // +x and -x are not adjacent
    EXPECT_THROW(refine_uniform(in, 1), std::invalid_argument);
    in = octahedron();
    in.corners = {{6}};
    EXPECT_THROW(refine_uniform(in, 1), std::invalid_argument);
    in = octahedron();
    in.triangles.push_back({0, 2, 1});  // a third face on the edge 0-2, in the direction of face 0
    EXPECT_THROW(refine_uniform(in, 1), std::invalid_argument);
    in = octahedron();
    in.uv = UvChannel{{{0, 0}}, {{0, 0, 0}}, UvInterpolation::none};  // one corner triple for 8 faces
    EXPECT_THROW(refine_uniform(in, 1), std::invalid_argument);
    EXPECT_THROW(refine_uniform(octahedron(), 11), std::invalid_argument);
}

}  // namespace
}  // namespace osdoracle
