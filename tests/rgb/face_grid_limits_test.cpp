// The limit points of FaceGridLimits (rgb/values/face_grid_limits.h), which the measure of an LOD set
// reads, against HierarchyEvaluator's, bit for bit: every vertex of Σ4 in every base face, asked in a
// scrambled order (the grid fills itself on demand), on meshes with a boundary, irregular valences and
// crease, corner and semi-sharp tags, where the grid keeps the evaluator's points inside the face and
// must hand it those on the face's boundary; and points given unreduced, deeper than the grid or in
// another face. The points on untagged interior base edges and the neighbouring faces' points beside
// them are the grid's own (the "diamond" of the two faces): the meshes below put such edges beside
// crease, semi-sharp, boundary and corner-tagged ones, next to vertices of valence 3 to 8, with the
// neighbour's corners in every rotation; and the control points at every finer level are compared
// too, as the tolerance criterion reads them.
#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "rgb/mesh/base_mesh.h"
#include "rgb/rules/sharp_features.h"
#include "rgb/values/face_grid_limits.h"
#include "rgb/values/hierarchy_evaluator.h"
#include "support/test_meshes.h"

namespace rgbtest {
namespace {

constexpr int kGridTestLevel = 4;

// Every vertex of Σk in base face g, reduced, in an order shuffled by `seed`.
std::vector<rgb::SurfacePoint> face_points(std::uint32_t g, int k, std::uint32_t seed) {
    std::vector<rgb::SurfacePoint> out;
    const std::uint32_t n = 1u << k;
    for (std::uint32_t a1 = 0; a1 <= n; ++a1)
        for (std::uint32_t a2 = 0; a1 + a2 <= n; ++a2) out.push_back(rgb::reduced(rgb::SurfacePoint{g, {n - a1 - a2, a1, a2}, k}));
    std::mt19937 random(seed);
    std::shuffle(out.begin(), out.end(), random);
    return out;
}

// Every vertex of Σlevel of every face, its limit and its control points at each level from its own
// to the grid's deepest, in a shuffled order.
// With `fill`, the grid computes every point first (FaceGridLimits::fill).
void expect_evaluators_values(const rgb::BaseMesh& base, int level = kGridTestLevel, bool fill = false) {
    rgb::HierarchyEvaluator fallback(base), reference(base);
    rgb::FaceGridLimits grid(base, fallback);
    std::size_t inside = 0;
    const auto expect_same = [](const glm::dvec3& got, const glm::dvec3& expected, const rgb::SurfacePoint& p, int k) {
        ASSERT_TRUE(got.x == expected.x && got.y == expected.y && got.z == expected.z)
            << "face " << p.face << " point " << p.a[0] << ',' << p.a[1] << ',' << p.a[2] << '/' << p.level << " at level " << k;
    };
    for (std::uint32_t g = 0; g < base.num_faces(); ++g) {
        grid.start(g, level);
        if (fill) grid.fill();
        for (const rgb::SurfacePoint& p : face_points(g, level, g)) {
            ASSERT_NO_FATAL_FAILURE(expect_same(grid.limit_position(p), reference.limit_position(p), p, -1));
            for (int k = p.level; k <= rgb::FaceGridLimits::kMaxLevel; ++k)
                ASSERT_NO_FATAL_FAILURE(expect_same(grid.control_point(p, k), reference.control_point(p, k), p, k));
            inside += p.a[0] != 0 && p.a[1] != 0 && p.a[2] != 0;
        }
    }
    EXPECT_GT(inside, 0u);
}

void expect_evaluators_limits(const rgb::BaseMesh& base) { expect_evaluators_values(base); }

TEST(FaceGridLimits, AreTheEvaluatorsOnAClosedIrregularMesh) {
    const TestMesh m = bipyramid(7);
    expect_evaluators_limits(rgb::BaseMesh(m.positions, m.triangles));
}

TEST(FaceGridLimits, AreTheEvaluatorsOnAnOpenMesh) {
    const TestMesh m = grid(3, 2);
    expect_evaluators_limits(rgb::BaseMesh(m.positions, m.triangles));
}

TEST(FaceGridLimits, AreTheEvaluatorsWithCreasesCornersAndSemiSharpEdges) {
    expect_evaluators_limits(tagged_bipyramid());
}

TEST(FaceGridLimits, AreTheEvaluatorsBesideValenceThreeCornersAndDeeper) {
    const TestMesh m = tetrahedron();
    expect_evaluators_values(rgb::BaseMesh(m.positions, m.triangles), 6);
}

TEST(FaceGridLimits, AreTheEvaluatorsWithTheNeighboursCornersInEveryRotation) {
    TestMesh m = torus(5, 4);
    for (std::size_t f = 0; f < m.triangles.size(); ++f)
        for (std::size_t turn = 0; turn < f % 3; ++turn) m.triangles[f] = {m.triangles[f][1], m.triangles[f][2], m.triangles[f][0]};
    expect_evaluators_values(rgb::BaseMesh(m.positions, m.triangles));
}

TEST(FaceGridLimits, AreTheEvaluatorsOnAnOpenMeshWithHoles) {
    const TestMesh m = grid_with_holes(4, 4, 3);
    expect_evaluators_values(rgb::BaseMesh(m.positions, m.triangles));
}

// Untagged edges between faces across a crease, a semi-sharp edge of sharpness 2 (sharp for two
// levels, then untagged rules at each of its points), a corner tag and corner-tagged boundary
// vertices with a single face.
TEST(FaceGridLimits, AreTheEvaluatorsBesideCreasesSemiSharpEdgesAndCornersOfAnOpenMesh) {
    const TestMesh m = grid(3, 3);
    rgb::SharpFeatures features;
    features.edges = {{5, 6, rgb::kInfiniteSharpness}, {6, 10, rgb::kInfiniteSharpness}, {9, 10, 2}};
    features.corners = {{5, rgb::kInfiniteSharpness}};
    features.boundary = rgb::BoundaryInterpolation::EdgeAndCorner;
    expect_evaluators_values(rgb::BaseMesh(m.positions, m.triangles, features));
}

TEST(FaceGridLimits, FilledAreTheEvaluatorsOnClosedOpenAndTaggedMeshes) {
    const TestMesh closed = bipyramid(7), open = grid_with_holes(4, 4, 3);
    expect_evaluators_values(rgb::BaseMesh(closed.positions, closed.triangles), kGridTestLevel, true);
    expect_evaluators_values(rgb::BaseMesh(open.positions, open.triangles), kGridTestLevel, true);
    expect_evaluators_values(tagged_bipyramid(), 5, true);
}

TEST(FaceGridLimits, AnswerForUnreducedPointsDeeperThanTheGridAndOfOtherFaces) {
    const TestMesh m = torus(4, 3);
    const rgb::BaseMesh base(m.positions, m.triangles);
    rgb::HierarchyEvaluator fallback(base), reference(base);
    rgb::FaceGridLimits grid(base, fallback);
    grid.start(0, 2);
    const rgb::SurfacePoint deeper{0, {5, 6, 5}, 4}, elsewhere{1, {1, 1, 2}, 2};
    EXPECT_EQ(grid.limit_position(deeper), reference.limit_position(deeper));
    EXPECT_EQ(grid.limit_position(elsewhere), reference.limit_position(elsewhere));
    grid.start(0, 4);
    const rgb::SurfacePoint unreduced{0, {4, 8, 4}, 4}, edge{0, {0, 12, 4}, 4};
    EXPECT_EQ(grid.limit_position(unreduced), reference.limit_position(rgb::reduced(unreduced)));
    EXPECT_EQ(grid.limit_position(edge), reference.limit_position(rgb::reduced(edge)));
}

}  // namespace
}  // namespace rgbtest
