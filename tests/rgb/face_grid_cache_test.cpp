// The grids the tolerance criterion reads its limit points from (rgb/values/face_grid_cache.h,
// FaceGridLimits::control_point) against HierarchyEvaluator's values, bit for bit: every vertex of Σ3
// of every base face, the faces interleaved in a scrambled order and each asked for at a scrambled
// level, through fewer grids than faces (so that grids give way and start again deeper), on a closed
// irregular mesh with crease, corner and semi-sharp tags and on an open one; and the displayed
// surface's error, which tolerance requests print, against the per-face measure through the evaluator.
#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "rgb/lod/refine.h"
#include "rgb/mesh/base_mesh.h"
#include "rgb/mesh/mesh.h"
#include "rgb/values/face_grid_cache.h"
#include "rgb/values/hierarchy_evaluator.h"
#include "rgb/values/surface_error.h"
#include "support/test_meshes.h"

namespace rgbtest {
namespace {

constexpr int kCacheTestLevel = 3;

void expect_exact(const glm::dvec3& got, const glm::dvec3& expected, const rgb::SurfacePoint& p, int k) {
    ASSERT_TRUE(got.x == expected.x && got.y == expected.y && got.z == expected.z)
        << "face " << p.face << " point " << p.a[0] << ',' << p.a[1] << ',' << p.a[2] << '/' << p.level << " at level " << k;
}

void expect_cache_gives_evaluators_values(const rgb::BaseMesh& base) {
    struct Ask {
        rgb::SurfacePoint point;
        int grid_level;
    };
    std::vector<Ask> asks;
    std::mt19937 random(7);
    const std::uint32_t n = 1u << kCacheTestLevel;
    for (std::uint32_t g = 0; g < base.num_faces(); ++g)
        for (std::uint32_t a1 = 0; a1 <= n; ++a1)
            for (std::uint32_t a2 = 0; a1 + a2 <= n; ++a2) {
                const rgb::SurfacePoint p = rgb::reduced(rgb::SurfacePoint{g, {n - a1 - a2, a1, a2}, kCacheTestLevel});
                // A grid as deep as the point, deeper, or too shallow for it (then the evaluator answers).
                asks.push_back({p, std::max(1, p.level + int(random() % 4) - 1)});
            }
    std::shuffle(asks.begin(), asks.end(), random);
    rgb::HierarchyEvaluator fallback(base), reference(base);
    rgb::FaceGridCache cache(base, fallback, 3);
    ASSERT_GT(base.num_faces(), 3u);
    for (const Ask& ask : asks) {
        rgb::FaceGridLimits& grid = cache.grid(ask.point.face, ask.grid_level);
        ASSERT_EQ(grid.face(), ask.point.face);
        ASSERT_GE(grid.level(), ask.grid_level);
        for (int k = ask.point.level; k <= rgb::FaceGridLimits::kMaxLevel + 1; ++k)
            expect_exact(grid.control_point(ask.point, k), reference.control_point(ask.point, k), ask.point, k);
        expect_exact(grid.limit_position(ask.point), reference.limit_position(ask.point), ask.point, -1);
    }
}

TEST(FaceGridCache, GivesTheEvaluatorsValuesWithCreasesCornersAndSemiSharpEdges) {
    expect_cache_gives_evaluators_values(tagged_bipyramid());
}

TEST(FaceGridCache, GivesTheEvaluatorsValuesOnAnOpenMesh) {
    const TestMesh m = grid(3, 2);
    expect_cache_gives_evaluators_values(rgb::BaseMesh(m.positions, m.triangles));
}

TEST(DisplayedSurfaceError, IsThePerFaceMeasureThroughTheEvaluator) {
    rgb::Mesh mesh = make_rgb_mesh(bipyramid(7));
    rgb::refine_uniform(mesh, 2);
    rgb::HierarchyEvaluator evaluator(mesh.base());
    rgb::SurfaceError expected;
    for (rgb::FaceId f : mesh.faces()) {
        const rgb::SurfaceError face = rgb::face_surface_error(mesh, evaluator, f);
        expected.samples += face.samples;
        if (face.max_error > expected.max_error) expected = {face.max_error, face.where, expected.samples};
    }
    const rgb::SurfaceError got = rgb::displayed_surface_error(mesh);
    EXPECT_GT(expected.max_error, 0.0);
    EXPECT_EQ(got.max_error, expected.max_error);
    EXPECT_EQ(got.where, expected.where);
    EXPECT_EQ(got.samples, expected.samples);
}

}  // namespace
}  // namespace rgbtest
