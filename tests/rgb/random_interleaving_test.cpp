// Random interleavings of refine_edge and remove_vertex (seeded; the seed is in every failure
// message). After every operation (every 20th under the sanitizers: see kInvariantCheckEvery): all
// invariants of spec §1.6; and every face the operation created (and every vertex of such a face)
// agrees with the uniform Loop oracle: green G_l faces are faces of Σl, displayed positions are the
// oracle's at the display level. Every few hundred operations the whole mesh is compared. At the end
// everything removable is removed, which must give back the base mesh bit for bit.
#include <algorithm>
#include <random>

#include <gtest/gtest.h>

#include "rgb/lod/refine.h"
#include "rgb/mesh/operators.h"
#include "support/oracle_checks.h"
#include "support/random_operations.h"

namespace rgbtest {
namespace {

struct RandomRun {
    TestMesh base;
    int max_level;
    int operations;
    std::uint32_t seed;
};

void PrintTo(const RandomRun& r, std::ostream* os) { *os << r.base.name << " seed " << r.seed; }

constexpr int kFullCheckEvery = 500;

// Under the sanitizers (test code at -O0 over an instrumented core) the whole-mesh invariant check
// after every operation made this suite the largest part of the sanitizer run; there it runs after
// every 20th operation and at the end, while the operators run the same sequence, which is what the
// sanitizers watch. The Release build checks after every operation.
#if defined(__SANITIZE_ADDRESS__)
constexpr int kInvariantCheckEvery = 20;
#else
constexpr int kInvariantCheckEvery = 1;
#endif

// One refine or remove chosen at random; returns a description of what was done, or "" if the
// random choice was not applicable (a red or too fine edge, a vertex that is not removable).
std::string random_operation(rgb::Mesh& mesh, std::mt19937& rng, int max_level) {
    if (rng() % 2 == 0) {
        const rgb::HalfedgeId h = rgb::Mesh::halfedge(random_live_face(mesh, rng), static_cast<int>(rng() % 3));
        const rgb::EdgeType type = mesh.edge_type(h);
        if (type.colour != rgb::Colour::Green || type.level >= max_level) return "";
        const rgb::VertexId a = mesh.from_vertex(h), b = mesh.to_vertex(h);
        const std::string what = "refine_edge(" + std::to_string(a.idx) + ", " + std::to_string(b.idx) + ")";
        EXPECT_TRUE(rgb::refine_edge(mesh, a, b)) << what << " split nothing";
        EXPECT_FALSE(mesh.find_edge(a, b).valid()) << what << " left the edge in place";
        return what;
    }
    const rgb::VertexId v = random_live_vertex(mesh, rng);
    if (!rgb::can_remove_vertex(mesh, v)) return "";
    const std::size_t before = mesh.num_vertices();
    rgb::remove_vertex(mesh, v);
    const std::string what = "remove_vertex(" + std::to_string(v.idx) + ")";
    EXPECT_EQ(mesh.num_vertices(), before - 1) << what;
    return what;
}

void run(const RandomRun& r) {
    SCOPED_TRACE(r.base.name + ", seed " + std::to_string(r.seed) + ", max level " + std::to_string(r.max_level));
    const UniformLoopOracle oracle(r.base.positions, r.base.triangles, r.max_level);
    rgb::Mesh mesh = make_rgb_mesh(r.base);
    IdentityTracker ids(mesh, oracle);
    ChangeRecorder changes(mesh);
    const OracleView view{mesh, ids, oracle_tolerance(r.base)};
    std::mt19937 rng(r.seed);
    int done = 0, removals = 0, deepest = 0;
    for (long attempt = 0; done < r.operations && attempt < 50L * r.operations; ++attempt) {
        changes.clear();
        const std::string what = random_operation(mesh, rng, r.max_level);
        if (what.empty()) continue;
        ++done;
        removals += what.starts_with("remove");
        deepest = std::max(deepest, mesh.max_vertex_level());
        SCOPED_TRACE("operation " + std::to_string(done) + ": " + what);
        ASSERT_FALSE(testing::Test::HasFailure());
        if (done % kInvariantCheckEvery == 0) {
            ASSERT_TRUE(invariants_hold(mesh));
        }
        for (rgb::FaceId f : changes.faces_added) {
            if (!mesh.is_live(f)) continue;
            ASSERT_TRUE(face_agrees(view, f));
            for (rgb::VertexId v : mesh.face_vertices(f)) ASSERT_TRUE(vertex_agrees(view, v));
        }
        if (done % kFullCheckEvery == 0) {
            ASSERT_TRUE(everything_agrees(view));
        }
    }
    ASSERT_EQ(done, r.operations) << "the random driver found too few applicable operations";
    // The run must exercise what it claims: both directions, down to the finest level.
    EXPECT_GE(removals, r.operations / 5);
    EXPECT_LE(removals, r.operations * 4 / 5);
    EXPECT_EQ(deepest, r.max_level);
    ASSERT_TRUE(everything_agrees(view));
    remove_everything_removable(mesh);
    ASSERT_TRUE(invariants_hold(mesh));
    EXPECT_TRUE(equals_base(mesh, r.base));
}

std::vector<RandomRun> runs() {
    // 16 small meshes x 6000 operations + the bunny's 4000: 100000 operations.
    std::vector<RandomRun> all;
    std::uint32_t seed = 1;
    for (const TestMesh& m : small_meshes()) {
        const bool deep = m.name == "octahedron" || m.name == "fan6" || m.name == "triangle";
        all.push_back({m, deep ? 5 : 4, 6000, seed++});
    }
    all.push_back({bunny(), 3, 4000, seed++});
    return all;
}

class RandomInterleaving : public testing::TestWithParam<RandomRun> {};

TEST_P(RandomInterleaving, KeepsInvariantsAndOracleAndCoarsensToBase) { run(GetParam()); }

INSTANTIATE_TEST_SUITE_P(Meshes, RandomInterleaving, testing::ValuesIn(runs()),
                         [](const testing::TestParamInfo<RandomRun>& info) { return info.param.base.name; });

}  // namespace
}  // namespace rgbtest
