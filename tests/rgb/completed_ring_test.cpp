// limit_from_completed_ring (completed_ring.h) against the hierarchy evaluator, a second
// implementation that never looks at the mesh: on the meshes a budget run leaves after every few
// steps, each limit it gives must be the evaluator's bit for bit, and it must answer for the vertices
// it was written for (some faces around them coarser than their level), or the check says nothing.
#include <cstddef>

#include <gtest/gtest.h>

#include "rgb/lod/lod_driver.h"
#include "rgb/mesh/mesh.h"
#include "rgb/values/completed_ring.h"
#include "rgb/values/hierarchy_evaluator.h"
#include "support/test_meshes.h"

namespace rgbtest {
namespace {

// Whether a face around v is coarser than v: then its ring is not all in the mesh.
bool ring_has_gaps(const rgb::Mesh& mesh, rgb::VertexId v) {
    const rgb::HalfedgeId start = mesh.vertex_halfedge(v);
    rgb::HalfedgeId h = start;
    do {
        if (mesh.level(rgb::Mesh::face(h)) < mesh.level(v)) return true;
        h = mesh.ccw_rotated(h);
    } while (h.valid() && h != start);
    return false;
}

class CompletedRing : public testing::TestWithParam<TestMesh> {};

TEST_P(CompletedRing, GivesTheEvaluatorsLimitsDuringBudgetRuns) {
    const TestMesh& base = GetParam();
    rgb::Mesh mesh = make_rgb_mesh(base);
    rgb::LodSettings settings;
    settings.max_triangles = 60 * base.triangles.size();
    rgb::LodDriver driver(mesh, settings);
    std::size_t completed = 0;
    while (!driver.done()) {
        driver.run(base.triangles.size());
        rgb::HierarchyEvaluator evaluator(mesh.base());
        for (rgb::VertexId v : mesh.vertices()) {
            const auto limit = rgb::limit_from_completed_ring(mesh, v);
            if (!limit) continue;
            const glm::dvec3 expected = evaluator.limit_position(mesh.address(v));
            ASSERT_EQ(limit->x, expected.x) << "vertex " << v.idx;
            ASSERT_EQ(limit->y, expected.y) << "vertex " << v.idx;
            ASSERT_EQ(limit->z, expected.z) << "vertex " << v.idx;
            if (ring_has_gaps(mesh, v)) ++completed;
        }
    }
    EXPECT_GT(completed, base.triangles.size());
}

INSTANTIATE_TEST_SUITE_P(Meshes, CompletedRing,
                         testing::Values(icosahedron(), bipyramid(7), perforated_slab(7, 7, 3), grid_with_holes(8, 8, 3)),
                         [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace rgbtest
