// The errors `rgbsub lods` prints for its levels (surface_errors_at over all levels at once,
// rgb/values/surface_error.h), with the levels' corners at their limit positions as the command writes
// them: against an independent evaluation on the uniform Loop oracle (support/oracle_surface.h) at the
// same samples, and against a brute-force maximum over a denser point set between them (the bound
// docs/cli.md states, kLodErrorRiseBetweenSamples); and the same result for each level as when it is
// measured alone, so that sharing one cache of limit points between the levels changes nothing.
#include <functional>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "rgb/lod/limit_error.h"
#include "rgb/lod/lod_criteria.h"
#include "rgb/lod/requests.h"
#include "rgb/mesh/mesh.h"
#include "rgb/values/loop_geometry.h"
#include "rgb/values/surface_error.h"
#include "support/identity_tracker.h"
#include "support/oracle_surface.h"
#include "support/test_meshes.h"
#include "support/set_level.h"

namespace rgbtest {
namespace {

constexpr int kLodErrorCap = 2;    // the finest level of the set
constexpr int kLodErrorDense = 3;  // the brute force: every point of Σ(l+3) in a face of level l, 45 per face
// How far above the printed error the error between its samples may rise, as a share of it: what
// docs/cli.md states for `rgbsub lods`.
constexpr double kLodErrorRiseBetweenSamples = 0.02;

struct TrackedLevel {
    std::unique_ptr<rgb::Mesh> mesh;
    std::unique_ptr<IdentityTracker> ids;
    std::vector<glm::dvec3> corners;  // the limit positions, by vertex slot
};

TrackedLevel tracked_level(const TestMesh& base, const UniformLoopOracle& oracle, const std::function<void(rgb::Mesh&)>& request) {
    TrackedLevel out;
    out.mesh = std::make_unique<rgb::Mesh>(make_rgb_mesh(base));
    out.ids = std::make_unique<IdentityTracker>(*out.mesh, oracle);
    request(*out.mesh);
    out.corners.resize(out.mesh->vertex_capacity());
    for (rgb::VertexId v : out.mesh->vertices()) out.corners[v.idx] = rgb::limit_position(*out.mesh, v);
    return out;
}

TEST(LodSetError, IsTheOraclesAtTheSamplesAndBoundsTheErrorBetweenThem) {
    const TestMesh base = torus(8, 4);
    const UniformLoopOracle oracle(base.positions, base.triangles, kLodErrorCap + kLodErrorDense);
    OracleSurface surface(oracle);
    const double size = bounding_box_diagonal(base.positions);
    // Levels 2, 1 and 0 (nested), and an adaptive level by tolerance that is no subset of level 2's.
    std::vector<TrackedLevel> levels;
    for (int level = kLodErrorCap; level >= 0; --level)
        levels.push_back(tracked_level(base, oracle, [&](rgb::Mesh& mesh) { rgbtest::set_level(mesh, level); }));
    levels.push_back(tracked_level(base, oracle, [&](rgb::Mesh& mesh) {
        rgb::DetailRequest request;
        request.value = rgb::limit_error_value(mesh.shared_base(), 0.01 * size);
        request.threshold = 0.01 * size;
        request.max_triangles = 1'000'000;
        rgb::apply_detail_request(mesh, request);
    }));
    ASSERT_EQ(levels.back().mesh->max_vertex_level(), kLodErrorCap);
    ASSERT_LT(levels.back().mesh->num_faces(), levels.front().mesh->num_faces());

    std::vector<const rgb::Mesh*> meshes;
    std::vector<std::vector<glm::dvec3>> corners;
    for (const TrackedLevel& level : levels) {
        meshes.push_back(level.mesh.get());
        corners.push_back(level.corners);
    }
    const std::vector<rgb::SurfaceError> errors = rgb::surface_errors_at(meshes, corners);
    ASSERT_EQ(errors.size(), levels.size());
    for (std::size_t i = 0; i < levels.size(); ++i) {
        SCOPED_TRACE("level " + std::to_string(i));
        const rgb::Mesh& mesh = *levels[i].mesh;
        // At the samples (the points of Σ(l+2) in each face of level l), the oracle's distances.
        const OracleError samples = surface.displayed_error(mesh, *levels[i].ids, 2, OracleSurface::Corners::Limit);
        EXPECT_EQ(errors[i].samples, samples.points);
        EXPECT_GT(errors[i].max_error, 0.0);
        EXPECT_NEAR(errors[i].max_error, samples.max_error, 1e-12 * size);
        // Between them, by brute force over 16/5 times the points.
        const OracleError between = surface.displayed_error(mesh, *levels[i].ids, kLodErrorDense, OracleSurface::Corners::Limit);
        EXPECT_GE(between.max_error, samples.max_error);
        EXPECT_LE(between.max_error, (1.0 + kLodErrorRiseBetweenSamples) * errors[i].max_error);
        // Measured alone: the same bits.
        const rgb::SurfaceError alone = rgb::surface_error_at(mesh, levels[i].corners);
        EXPECT_EQ(alone.max_error, errors[i].max_error);
        EXPECT_EQ(alone.where, errors[i].where);
        EXPECT_EQ(alone.samples, errors[i].samples);
    }
    // Coarser levels are farther from the surface.
    EXPECT_LT(errors[0].max_error, errors[1].max_error);
    EXPECT_LT(errors[1].max_error, errors[2].max_error);
}

}  // namespace
}  // namespace rgbtest
