// Detail size (rgb/lod/lod_criteria.h with the edge length in the uniform mesh of each edge's level):
// results against the meaning computed independently on the uniform Loop oracle's identities, over
// the whole surface and in a ball, refine, coarsen and set; checked edge by edge; and the same mesh
// whatever the input's storage. On random lengths, what the documentation says and what it must not:
// green edges within L, diagonals of the displayed mesh beyond it.
#include <algorithm>
#include <limits>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <vector>

#include <glm/geometric.hpp>

#include <gtest/gtest.h>

#include "rgb/lod/lod_criteria.h"
#include "rgb/lod/requests.h"
#include "rgb/mesh/invariants.h"
#include "rgb/mesh/mesh.h"
#include "rgb/values/loop_geometry.h"
#include "support/clear_threshold.h"
#include "support/identity_tracker.h"
#include "support/request_oracle.h"
#include "support/same_mesh.h"
#include "support/test_meshes.h"
#include "support/set_level.h"

namespace rgbtest {
namespace {

constexpr int kCap = 4;

bool segment_meets(const glm::dvec3& p, const glm::dvec3& q, const OracleBall& ball) {
    // The nearest point of the segment, by projecting the centre on its line.
    const glm::dvec3 d = q - p;
    const double t = std::clamp(glm::dot(ball.centre - p, d) / glm::dot(d, d), 0.0, 1.0);
    return glm::length(p + t * d - ball.centre) <= ball.radius;
}

// The meaning of a request on identities (docs/requests.md "Detail by size, accuracy and view").
class DetailMeaning {
public:
    DetailMeaning(const UniformLoopOracle& oracle, double threshold)
        : oracle_(oracle), requests_(oracle), threshold_(threshold) {}

    // The smallest closed set holding `current` in which every edge of Σj (j < kCap) with both ends in
    // it that meets the region and is longer than the threshold has its midpoint.
    std::set<Identity> refined(std::set<Identity> current, const std::optional<OracleBall>& ball) const {
        for (;;) {
            std::set<Identity> wanted;
            for (int j = 0; j < kCap; ++j)
                for (const IdentityTriangle& t : oracle_.faces(j))
                    for (int i = 0; i < 3; ++i) {
                        const Identity x = t[i], y = t[(i + 1) % 3];
                        if (!current.count(x) || !current.count(y)) continue;
                        if (ball && !segment_meets(requests_.base_space(x), requests_.base_space(y), *ball)) continue;
                        const Identity m = *oracle_.midpoint(x, y);
                        if (oracle_edge_length(oracle_, x, y) > threshold_ && !current.count(m)) wanted.insert(m);
                    }
            if (wanted.empty()) return current;
            current.insert(wanted.begin(), wanted.end());
            current = requests_.closure(current);
        }
    }
    // Every vertex in the ball whose parent edge is not longer than the threshold goes, with all
    // that needs one of them.
    std::set<Identity> coarsened(const std::set<Identity>& current, const std::optional<OracleBall>& ball) const {
        std::set<Identity> doomed;
        for (Identity v : current) {
            if (oracle_.level(v) == 0) continue;
            if (ball && glm::length(requests_.base_space(v) - ball->centre) > ball->radius) continue;
            const auto [x, y] = requests_.parents(v);
            if (!(oracle_edge_length(oracle_, x, y) > threshold_)) doomed.insert(v);
        }
        return requests_.without(current, doomed);
    }
    std::set<Identity> base() const { return requests_.base(); }
    void set_threshold(double threshold) { threshold_ = threshold; }

private:
    const UniformLoopOracle& oracle_;
    RequestOracle requests_;
    double threshold_;
};

// With `from_mesh`, also the same values computed from the mesh (DetailRequest::mesh_value), which
// the script's and the command line's max-edge give the driver: it must reach the same vertices.
rgb::LodReport apply_max_edge(rgb::Mesh& mesh, rgb::RequestKind kind, double length, std::optional<rgb::Sphere> sphere,
                              bool from_mesh = false) {
    rgb::DetailRequest request;
    request.kind = kind;
    request.value = rgb::edge_length_value(mesh.shared_base());
    if (from_mesh) request.mesh_value = rgb::edge_length;
    request.threshold = length;
    request.sphere = sphere;
    request.max_level = kCap;
    return rgb::apply_detail_request(mesh, request);
}

class DetailSize : public testing::TestWithParam<TestMesh> {};

TEST_P(DetailSize, OverTheWholeSurfaceNoEdgeIsLongerThanAsked) {
    const TestMesh& base = GetParam();
    const UniformLoopOracle oracle(base.positions, base.triangles, kCap);
    for (double share : {0.4, 0.75, 0.9})
        for (bool from_mesh : {false, true}) {
            SCOPED_TRACE(from_mesh ? "values from the mesh" : "values from the hierarchy evaluator");
            const double length = clear_threshold(oracle, kCap, share);
            const DetailMeaning meaning(oracle, length);
            rgb::Mesh mesh = make_rgb_mesh(base);
            IdentityTracker ids(mesh, oracle);
            rgbtest::set_level(mesh, 1, rgb::Sphere{base.positions[1], 0.3 * bounding_box_diagonal(base.positions)});
            const rgb::LodReport report = apply_max_edge(mesh, rgb::RequestKind::Set, length, std::nullopt, from_mesh);
            EXPECT_FALSE(report.budget_bound);
            EXPECT_EQ(ids.live_identities(), meaning.refined(meaning.base(), std::nullopt)) << "share " << share;
            EXPECT_TRUE(rgb::check_invariants(mesh).ok());
            EXPECT_TRUE(rgb::check_normal_form(mesh).ok());
            // Edge by edge: every green edge is within the length in the uniform mesh of its level,
            // unless it is at the level cap.
            for (rgb::FaceId f : mesh.faces())
                for (int i = 0; i < 3; ++i) {
                    const rgb::HalfedgeId h = rgb::Mesh::halfedge(f, i);
                    const rgb::EdgeType t = mesh.edge_type(h);
                    if (t.colour != rgb::Colour::Green || t.level >= kCap) continue;
                    const Identity x = ids.identity(mesh.from_vertex(h)), y = ids.identity(mesh.to_vertex(h));
                    EXPECT_LE(oracle_edge_length(oracle, x, y), length) << "edge " << x << "-" << y << " of level " << t.level;
                }
        }
}

// What the documentation says of --max-edge L, pinned on random lengths: every edge of the result that
// is an edge of the uniform mesh of its level is at most L in that mesh, and the mesh is the meaning's
// (as coarse as that allows); "no edge longer than L" read on the displayed mesh would be false: the
// diagonals of red and blue triangles (edges of no uniform mesh) can be longer. Edges are classified,
// and the displayed positions modelled, from the oracle's identities alone (spec §4.6: a vertex shows
// p^k, k the largest of its own level and the least level of its edges; a diagonal from a vertex of
// level l+1 has level l), not from the core's edge types.
TEST(DetailSizeMeaning, RandomLengthsBoundGreenEdgesButNotDiagonals) {
    std::mt19937_64 random(31);
    int longer_diagonals = 0;
    for (const TestMesh& base : {icosahedron(), bipyramid(7), grid(4, 3)}) {
        const UniformLoopOracle oracle(base.positions, base.triangles, kCap);
        DetailMeaning meaning(oracle, 0.0);
        std::set<std::pair<Identity, Identity>> uniform_edges;  // of every Σj, j <= kCap
        double shortest = std::numeric_limits<double>::infinity(), longest = 0.0;
        for (int j = 0; j <= kCap; ++j)
            for (const IdentityTriangle& t : oracle.faces(j))
                for (int i = 0; i < 3; ++i) {
                    uniform_edges.insert(std::minmax(t[i], t[(i + 1) % 3]));
                    if (j == kCap) continue;
                    const double length = oracle_edge_length(oracle, t[i], t[(i + 1) % 3]);
                    shortest = std::min(shortest, length);
                    longest = std::max(longest, length);
                }
        for (int trial = 0; trial < 3; ++trial) {
            const double unit = static_cast<double>(random() >> 11) * 0x1.0p-53;
            const double length = shortest + unit * (longest - shortest);
            SCOPED_TRACE(base.name + ", L = " + std::to_string(length));
            rgb::Mesh mesh = make_rgb_mesh(base);
            IdentityTracker ids(mesh, oracle);
            apply_max_edge(mesh, rgb::RequestKind::Set, length, std::nullopt);
            meaning.set_threshold(length);
            EXPECT_EQ(ids.live_identities(), meaning.refined(meaning.base(), std::nullopt));
            // Each edge once, with its level: an edge of Σj has an end of level j (both of level 0 in
            // Σ0); a diagonal joins a vertex of level l+1 to the opposite corner and has level l.
            struct Edge {
                Identity x, y;
                bool uniform;
                int level;
            };
            std::vector<Edge> edges;
            std::map<Identity, int> least_edge_level;
            for (rgb::FaceId f : mesh.faces())
                for (int i = 0; i < 3; ++i) {
                    const rgb::HalfedgeId h = rgb::Mesh::halfedge(f, i);
                    const Identity x = ids.identity(mesh.from_vertex(h)), y = ids.identity(mesh.to_vertex(h));
                    const bool uniform = uniform_edges.count(std::minmax(x, y)) > 0;
                    const int level = std::max(oracle.level(x), oracle.level(y)) - (uniform ? 0 : 1);
                    for (Identity v : {x, y}) {
                        const auto [it, fresh] = least_edge_level.emplace(v, level);
                        if (!fresh) it->second = std::min(it->second, level);
                    }
                    if (mesh.is_boundary(h) || x < y) edges.push_back({x, y, uniform, level});
                }
            auto displayed = [&](Identity v) { return oracle.position(std::max(oracle.level(v), least_edge_level.at(v)), v); };
            // The model is the mesh's display (so the diagonals below are the displayed ones).
            for (rgb::VertexId v : mesh.vertices())
                EXPECT_LE(glm::distance(displayed(ids.identity(v)), rgb::displayed_position(mesh, v)), 1e-12) << "vertex " << ids.identity(v);
            for (const Edge& e : edges) {
                if (e.uniform && e.level < kCap) {
                    EXPECT_LE(oracle_edge_length(oracle, e.x, e.y), length) << "edge " << e.x << "-" << e.y;
                }
                if (!e.uniform && glm::distance(displayed(e.x), displayed(e.y)) > length) ++longer_diagonals;
            }
        }
    }
    // The same data refutes "no edge longer than L" on the displayed mesh.
    EXPECT_GT(longer_diagonals, 0);
}

TEST_P(DetailSize, RequestsInABallFollowTheirMeaning) {
    const TestMesh& base = GetParam();
    const UniformLoopOracle oracle(base.positions, base.triangles, kCap);
    const double diagonal = bounding_box_diagonal(base.positions);
    const double length = clear_threshold(oracle, kCap, 0.85);  // among the lengths of Σ2
    const DetailMeaning meaning(oracle, length);
    const rgb::Sphere ball{0.5 * (base.positions[0] + base.positions[2]), 0.35 * diagonal};
    const OracleBall oracle_ball{ball.centre, ball.radius};
    for (rgb::RequestKind kind : {rgb::RequestKind::Refine, rgb::RequestKind::Coarsen, rgb::RequestKind::Set}) {
        SCOPED_TRACE("request kind " + std::to_string(static_cast<int>(kind)));
        rgb::Mesh mesh = make_rgb_mesh(base);
        IdentityTracker ids(mesh, oracle);
        // Some detail to start from, partly in the ball.
        rgbtest::set_level(mesh, 3, rgb::Sphere{base.positions[0], 0.3 * diagonal});
        rgbtest::set_level(mesh, 1, rgb::Sphere{base.positions[3], 0.3 * diagonal});
        const std::set<Identity> before = ids.live_identities();
        apply_max_edge(mesh, kind, length, ball);
        std::set<Identity> expected = before;
        if (kind != rgb::RequestKind::Refine) expected = meaning.coarsened(expected, oracle_ball);
        if (kind != rgb::RequestKind::Coarsen) expected = meaning.refined(expected, oracle_ball);
        EXPECT_NE(expected, before) << "the request should change something";
        EXPECT_EQ(ids.live_identities(), expected);
        EXPECT_TRUE(rgb::check_invariants(mesh).ok());
        EXPECT_TRUE(rgb::check_normal_form(mesh).ok());
    }
}

TEST_P(DetailSize, TheResultIgnoresStorageAndHowTheRequestIsPut) {
    const TestMesh& base = GetParam();
    const UniformLoopOracle oracle(base.positions, base.triangles, kCap);
    const double length = clear_threshold(oracle, kCap, 0.7);
    const double diagonal = bounding_box_diagonal(base.positions);
    const rgb::Sphere ball{base.positions[0], 0.4 * diagonal};
    auto run = [&](const TestMesh& m) {
        rgb::Mesh mesh = make_rgb_mesh(m);
        apply_max_edge(mesh, rgb::RequestKind::Set, length, std::nullopt);
        apply_max_edge(mesh, rgb::RequestKind::Coarsen, 2.0 * length, ball);
        return mesh;
    };
    const rgb::Mesh fresh = run(base);
    for (const TestMesh& stored : {with_rotated_corners(base), with_reversed_faces(base), with_shuffled_vertices(base, 3)})
        EXPECT_TRUE(same_mesh(fresh, run(stored))) << stored.name;
    // A Set in a ball around everything is the Set over the whole surface.
    rgb::Mesh whole = make_rgb_mesh(base);
    apply_max_edge(whole, rgb::RequestKind::Set, length, std::nullopt);
    rgb::Mesh in_ball = make_rgb_mesh(base);
    rgbtest::set_level(in_ball, 2);
    apply_max_edge(in_ball, rgb::RequestKind::Set, length, rgb::Sphere{base.positions[0], 3.0 * diagonal});
    EXPECT_TRUE(same_mesh(whole, in_ball));
}

INSTANTIATE_TEST_SUITE_P(Meshes, DetailSize,
                         testing::Values(icosahedron(), bipyramid(7), grid(4, 3), perforated_slab(5, 5, 2)),
                         [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace rgbtest
