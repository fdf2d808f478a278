// Order independence (spec §4.7): whatever sequence of operations reaches a set of vertices, each
// vertex gets bit-identical positions. Σ3 is reached by refine_uniform, by refine_edge over each
// level's edges in shuffled orders, after random refine/remove detours, and after a full coarsening
// and refinement again; positions are compared with ==, not with a tolerance.
#include <algorithm>
#include <random>
#include <utility>

#include <gtest/gtest.h>

#include "rgb/lod/refine.h"
#include "rgb/mesh/operators.h"
#include "rgb/values/loop_geometry.h"
#include "support/oracle_checks.h"
#include "support/random_operations.h"

namespace rgbtest {
namespace {

constexpr int kLevel = 3;

// A mesh and its identity tracker, built together so the tracker sees every change.
struct TrackedMesh {
    TrackedMesh(const TestMesh& base, const UniformLoopOracle& oracle) : mesh(make_rgb_mesh(base)), ids(mesh, oracle) {}
    rgb::Mesh mesh;
    IdentityTracker ids;
};

testing::AssertionResult same_positions_bitwise(const TrackedMesh& x, const TrackedMesh& y) {
    if (x.mesh.num_vertices() != y.mesh.num_vertices())
        return testing::AssertionFailure() << x.mesh.num_vertices() << " vs " << y.mesh.num_vertices() << " vertices";
    std::vector<rgb::VertexId> y_of_identity(y.ids.oracle().num_identities(kLevel));
    for (rgb::VertexId w : y.mesh.vertices()) y_of_identity.at(y.ids.identity(w)) = w;
    for (rgb::VertexId v : x.mesh.vertices()) {
        const Identity id = x.ids.identity(v);
        const rgb::VertexId w = y_of_identity.at(id);
        if (!w.valid()) return testing::AssertionFailure() << "identity " << id << " missing from the second mesh";
        if (x.mesh.insertion_position(v) != y.mesh.insertion_position(w) ||
            rgb::displayed_position(x.mesh, v) != rgb::displayed_position(y.mesh, w))
            return testing::AssertionFailure() << "identity " << id << " (vertices " << v.idx << ", " << w.idx
                                               << ") differs in the last bits";
    }
    return testing::AssertionSuccess();
}

void refine_levels_in_shuffled_order(rgb::Mesh& mesh, std::mt19937& rng) {
    for (int level = 0; level < kLevel; ++level) {
        std::vector<std::pair<rgb::VertexId, rgb::VertexId>> edges;
        for (rgb::FaceId f : mesh.faces())
            for (int i = 0; i < 3; ++i) {
                const rgb::HalfedgeId h = rgb::Mesh::halfedge(f, i);
                const rgb::VertexId a = mesh.from_vertex(h), b = mesh.to_vertex(h);
                if (a < b || mesh.is_boundary(h)) edges.emplace_back(a, b);
            }
        std::shuffle(edges.begin(), edges.end(), rng);
        for (const auto& [a, b] : edges)
            if (mesh.find_edge(a, b).valid()) rgb::refine_edge(mesh, a, b);
    }
}

class OrderIndependence : public testing::TestWithParam<TestMesh> {
protected:
    const TestMesh& base = GetParam();
    const UniformLoopOracle oracle{base.positions, base.triangles, kLevel};
    TrackedMesh uniform{base, oracle};
    void SetUp() override { rgb::refine_uniform(uniform.mesh, kLevel); }
};

TEST_P(OrderIndependence, ShuffledEdgeOrdersGiveIdenticalPositions) {
    for (std::uint32_t seed = 1; seed <= 3; ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        TrackedMesh shuffled(base, oracle);
        std::mt19937 rng(seed);
        refine_levels_in_shuffled_order(shuffled.mesh, rng);
        ASSERT_TRUE(equals_uniform({shuffled.mesh, shuffled.ids, oracle_tolerance(base)}, kLevel));
        EXPECT_TRUE(same_positions_bitwise(uniform, shuffled));
    }
}

TEST_P(OrderIndependence, RandomDetoursThenUniformGiveIdenticalPositions) {
    const std::uint32_t seed = 17;
    SCOPED_TRACE("seed " + std::to_string(seed));
    TrackedMesh detour(base, oracle);
    std::mt19937 rng(seed);
    for (int i = 0; i < 400; ++i) {
        if (rng() % 2 == 0) {
            const rgb::HalfedgeId h = rgb::Mesh::halfedge(random_live_face(detour.mesh, rng), static_cast<int>(rng() % 3));
            const rgb::EdgeType type = detour.mesh.edge_type(h);
            if (type.colour == rgb::Colour::Green && type.level < kLevel)
                rgb::refine_edge(detour.mesh, detour.mesh.from_vertex(h), detour.mesh.to_vertex(h));
        } else {
            const rgb::VertexId v = random_live_vertex(detour.mesh, rng);
            if (rgb::can_remove_vertex(detour.mesh, v)) rgb::remove_vertex(detour.mesh, v);
        }
    }
    rgb::refine_uniform(detour.mesh, kLevel);
    EXPECT_TRUE(same_positions_bitwise(uniform, detour));
}

TEST_P(OrderIndependence, CoarseningAndRefiningAgainGivesIdenticalPositions) {
    TrackedMesh again(base, oracle);
    rgb::refine_uniform(again.mesh, kLevel);
    remove_everything_removable(again.mesh);
    ASSERT_TRUE(equals_base(again.mesh, base));
    rgb::refine_uniform(again.mesh, kLevel);
    EXPECT_TRUE(same_positions_bitwise(uniform, again));
}

INSTANTIATE_TEST_SUITE_P(SmallMeshes, OrderIndependence, testing::ValuesIn(small_meshes()),
                         [](const testing::TestParamInfo<TestMesh>& info) { return info.param.name; });

}  // namespace
}  // namespace rgbtest
