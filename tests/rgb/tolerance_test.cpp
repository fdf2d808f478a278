// The tolerance criterion (rgb/lod/limit_error.h): results checked against an independent evaluation of
// the limit surface on the uniform Loop oracle (support/oracle_surface.h), at the criterion's samples
// (the promise) and densely between them (the rise between samples that the README and --help state,
// kRiseBetweenSamples, on these meshes and on a plain torus, where it is largest); and the same mesh
// whatever the input's storage, the mesh's history, or how the request is put.
#include <cmath>

#include <gtest/gtest.h>

#include "rgb/lod/limit_error.h"
#include "rgb/lod/lod_criteria.h"
#include "rgb/lod/requests.h"
#include "rgb/mesh/invariants.h"
#include "rgb/mesh/mesh.h"
#include "rgb/values/surface_error.h"
#include "support/identity_tracker.h"
#include "support/oracle_surface.h"
#include "support/same_mesh.h"
#include "support/test_meshes.h"
#include "support/set_level.h"

namespace rgbtest {
namespace {

constexpr int kToleranceOracleLevels = 7;
constexpr int kDense = 4;  // points of Σ(l+4) in every face of level l: 16 times the samples' density
constexpr int kLevelCap = kToleranceOracleLevels - kDense;
// How far above the tolerance the error may rise between the samples, as a share of it: what the
// README, `refine --help`, `apply --help` and docs/requests.md state.
constexpr double kRiseBetweenSamples = 0.03;

rgb::LodReport apply_tolerance(rgb::Mesh& mesh, double tolerance, std::optional<rgb::Sphere> sphere = std::nullopt,
                               std::size_t budget = 1'000'000) {
    rgb::DetailRequest request;
    request.value = rgb::limit_error_value(mesh.shared_base(), tolerance);
    request.threshold = tolerance;
    request.sphere = sphere;
    request.max_triangles = budget;
    return rgb::apply_detail_request(mesh, request);
}

struct Case {
    TestMesh mesh;
    std::vector<double> shares;  // tolerances as shares of the bounding-box diagonal, reachable below kLevelCap
};
void PrintTo(const Case& c, std::ostream* os) { *os << c.mesh.name; }

class Tolerance : public testing::TestWithParam<Case> {};

// The tolerance's promise on one mesh: within it at every sample, and at most kRiseBetweenSamples of
// it above between them, at the points of Σ(l+dense) in each triangle of level l (no finer than cap).
void expect_within_tolerance(const TestMesh& base, const UniformLoopOracle& oracle, OracleSurface& surface, double share, int cap,
                             int dense) {
    SCOPED_TRACE(base.name + ", tolerance " + std::to_string(share) + " of the diagonal");
    const double tolerance = share * bounding_box_diagonal(base.positions);
    rgb::Mesh mesh = make_rgb_mesh(base);
    IdentityTracker ids(mesh, oracle);
    const rgb::LodReport report = apply_tolerance(mesh, tolerance);
    ASSERT_FALSE(report.level_cap_bound || report.budget_bound);
    ASSERT_LE(mesh.max_vertex_level(), cap);
    EXPECT_TRUE(rgb::check_invariants(mesh).ok());
    EXPECT_TRUE(rgb::check_normal_form(mesh).ok());
    // The promise, at the samples (corners, edge points and inner points of Σ(l+2)).
    const OracleError samples = surface.displayed_error(mesh, ids, 2);
    EXPECT_LE(samples.max_error, tolerance);
    // The core's own measure (what the CLI prints) is that measure.
    EXPECT_NEAR(rgb::displayed_surface_error(mesh).max_error, samples.max_error, 1e-12 * tolerance);
    // Between the samples the error can rise above their maximum by about how far the limit surface
    // bends within a cell of Σ(l+2), which the criterion keeps small against the tolerance.
    const OracleError between = surface.displayed_error(mesh, ids, dense);
    // (Σ(l+dense) has about 4^(dense-2) times the points of Σ(l+2); more than half as many here.)
    EXPECT_GT(between.points, (std::size_t(1) << (2 * (dense - 2))) / 2 * samples.points);
    EXPECT_LE(between.max_error, (1.0 + kRiseBetweenSamples) * tolerance);
}

// Checked at the 153 points of Σ(l+4) in each triangle.
TEST_P(Tolerance, TheResultIsWithinTheToleranceAtEverySampleAndBetween) {
    const TestMesh& base = GetParam().mesh;
    const UniformLoopOracle oracle(base.positions, base.triangles, kToleranceOracleLevels);
    OracleSurface surface(oracle);
    for (double share : GetParam().shares) expect_within_tolerance(base, oracle, surface, share, kLevelCap, kDense);
}

TEST_P(Tolerance, TheResultIgnoresStorageHistoryAndHowTheRequestIsPut) {
    const TestMesh& base = GetParam().mesh;
    const double tolerance = GetParam().shares.back() * bounding_box_diagonal(base.positions);
    rgb::Mesh fresh = make_rgb_mesh(base);
    apply_tolerance(fresh, tolerance);
    for (const TestMesh& stored : {with_rotated_corners(base), with_reversed_faces(base), with_shuffled_vertices(base, 7)}) {
        rgb::Mesh other = make_rgb_mesh(stored);
        apply_tolerance(other, tolerance);
        EXPECT_TRUE(same_mesh(fresh, other)) << stored.name;
    }
    rgb::Mesh refined = make_rgb_mesh(base);
    rgbtest::set_level(refined, 2, rgb::Sphere{base.positions[0], 0.5 * bounding_box_diagonal(base.positions)});
    apply_tolerance(refined, tolerance);
    EXPECT_TRUE(same_mesh(fresh, refined)) << "after refining part of the mesh first";
    // A Set in a ball holding the whole surface is the Set over the whole surface.
    rgb::Mesh in_ball = make_rgb_mesh(base);
    rgbtest::set_level(in_ball, 1);
    apply_tolerance(in_ball, tolerance, rgb::Sphere{base.positions[0], 3.0 * bounding_box_diagonal(base.positions)});
    EXPECT_TRUE(same_mesh(fresh, in_ball)) << "as a request in a ball around everything";
}

TEST_P(Tolerance, ABudgetStopsAtTheSameMeshWhateverTheStorage) {
    const TestMesh& base = GetParam().mesh;
    const double tolerance = GetParam().shares.back() * bounding_box_diagonal(base.positions);
    rgb::Mesh full = make_rgb_mesh(base);
    apply_tolerance(full, tolerance);
    const std::size_t budget = (full.num_faces() + base.triangles.size()) / 2;
    rgb::Mesh fresh = make_rgb_mesh(base);
    EXPECT_TRUE(apply_tolerance(fresh, tolerance, std::nullopt, budget).budget_bound);
    EXPECT_LE(fresh.num_faces(), budget);
    EXPECT_GT(fresh.num_faces(), base.triangles.size());
    for (const TestMesh& stored : {with_rotated_corners(base), with_reversed_faces(base)}) {
        rgb::Mesh other = make_rgb_mesh(stored);
        apply_tolerance(other, tolerance, std::nullopt, budget);
        EXPECT_TRUE(same_mesh(fresh, other)) << stored.name;
    }
}

INSTANTIATE_TEST_SUITE_P(Meshes, Tolerance,
                         testing::Values(Case{icosahedron(), {0.03, 0.003}}, Case{bipyramid(8), {0.03, 0.01}},
                                         Case{grid(4, 3), {0.03, 0.01, 0.003}}, Case{fan(7), {0.03, 0.01, 0.003}},
                                         Case{perforated_slab(3, 3, 2), {0.03, 0.01}}),
                         [](const auto& info) { return info.param.mesh.name; });

// A plain torus, smooth and curved both ways, where an outside check saw the error between samples
// rise most (2.4% above the tolerance): within the share the README states. Checked at the 45 points
// of Σ(l+3) in each triangle, to keep the oracle small.
TEST(Tolerance, OnAPlainTorusTheErrorBetweenSamplesRisesLittle) {
    constexpr int kTorusDense = 3, kTorusCap = 2;
    const TestMesh base = torus(8, 4);
    const UniformLoopOracle oracle(base.positions, base.triangles, kTorusCap + kTorusDense);
    OracleSurface surface(oracle);
    for (double share : {0.01, 0.006}) expect_within_tolerance(base, oracle, surface, share, kTorusCap, kTorusDense);
}

TEST(Tolerance, RefusesToleranceThatIsNotPositive) {
    rgb::Mesh mesh = make_rgb_mesh(icosahedron());
    EXPECT_THROW(apply_tolerance(mesh, 0.0), std::invalid_argument);
    EXPECT_THROW(apply_tolerance(mesh, -1.0), std::invalid_argument);
    EXPECT_THROW(apply_tolerance(mesh, std::nan("")), std::invalid_argument);
}

}  // namespace
}  // namespace rgbtest
