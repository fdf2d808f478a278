// The limit points of FaceGridLimits (rgb/values/face_grid_limits.h), which the measure of an LOD set
// reads, against HierarchyEvaluator's, bit for bit: every vertex of Σ4 in every base face, asked in a
// scrambled order (the grid fills itself on demand), on meshes with a boundary, irregular valences and
// crease, corner and semi-sharp tags, where the grid keeps the evaluator's points inside the face and
// must hand it those on the face's boundary; and points given unreduced, deeper than the grid or in
// another face.
#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "rgb/mesh/base_mesh.h"
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

void expect_evaluators_limits(const rgb::BaseMesh& base) {
    rgb::HierarchyEvaluator fallback(base), reference(base);
    rgb::FaceGridLimits grid(base, fallback);
    std::size_t inside = 0;
    for (std::uint32_t g = 0; g < base.num_faces(); ++g) {
        grid.start(g, kGridTestLevel);
        for (const rgb::SurfacePoint& p : face_points(g, kGridTestLevel, g)) {
            const glm::dvec3 expected = reference.limit_position(p), got = grid.limit_position(p);
            ASSERT_EQ(got.x, expected.x) << "face " << g << " point " << p.a[0] << ',' << p.a[1] << ',' << p.a[2] << '/' << p.level;
            ASSERT_EQ(got.y, expected.y);
            ASSERT_EQ(got.z, expected.z);
            inside += p.a[0] != 0 && p.a[1] != 0 && p.a[2] != 0;
        }
    }
    EXPECT_GT(inside, 0u);
}

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
