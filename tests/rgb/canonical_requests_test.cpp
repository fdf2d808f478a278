// What a request means (docs/requests.md "What a request means", spec §3.5), checked as a property over many
// random request sets on closed, open and high-genus meshes: the vertex set equals the one an
// independent model of the meaning computes on the uniform Loop oracle, requests of one kind give the
// identical mesh in every order, the input's storage and the history do not matter, and small regions
// reach their level. Every result also passes the invariants, the normal form and the Loop oracle.
#include <algorithm>
#include <numeric>
#include <random>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "rgb/lod/dab.h"
#include "rgb/lod/requests.h"
#include "rgb/mesh/invariants.h"
#include "rgb/values/restore_state.h"
#include "support/identity_tracker.h"
#include "support/oracle_checks.h"
#include "support/request_oracle.h"
#include "support/same_mesh.h"
#include "support/test_meshes.h"
#include "support/set_level.h"

namespace rgbtest {
namespace {

constexpr int kOracleLevels = 4;

struct Request {
    rgb::RequestKind kind;
    int level;
    rgb::Sphere ball;
};

rgb::LevelRequest as_request(const Request& r) {
    rgb::LevelRequest request;
    request.kind = r.kind;
    request.level = r.level;
    request.sphere = r.ball;
    return request;
}

void apply_all(rgb::Mesh& mesh, const std::vector<Request>& requests, const std::vector<std::size_t>& order) {
    for (std::size_t i : order) rgb::apply_request(mesh, as_request(requests[i]));
}

// A mesh with its identity tracker, so its vertex set can be compared with the oracle's.
struct Tracked {
    Tracked(const TestMesh& base, const UniformLoopOracle& oracle) : mesh(make_rgb_mesh(base)), ids(mesh, oracle) {}
    rgb::Mesh mesh;
    IdentityTracker ids;
};

// Balls centred near the surface (a jittered base vertex), of radii from a tenth of an edge to a few
// edges, so that they overlap each other and cross base edges and vertices.
std::vector<Request> random_requests(const TestMesh& base, std::mt19937& rng, int count, rgb::RequestKind kind, int fixed_level) {
    double edge = 0.0;
    for (const rgb::Triangle& t : base.triangles) edge += glm::distance(base.positions[t[0]], base.positions[t[1]]);
    edge /= static_cast<double>(base.triangles.size());
    auto uniform = [&] { return static_cast<double>(rng()) / 4294967296.0; };
    const glm::dvec3 anchor = base.positions[rng() % base.positions.size()];
    std::vector<Request> requests;
    for (int i = 0; i < count; ++i) {
        const glm::dvec3 centre = anchor + edge * glm::dvec3(uniform() - 0.5, uniform() - 0.5, uniform() - 0.5);
        const int level = fixed_level >= 0 ? fixed_level : 1 + static_cast<int>(rng() % 3);
        requests.push_back({kind, level, {centre, edge * (0.1 + 1.5 * uniform())}});
    }
    return requests;
}

testing::AssertionResult healthy(const Tracked& t, const TestMesh& base) {
    if (auto r = rgb::check_invariants(t.mesh); !r.ok()) return testing::AssertionFailure() << r.violations.front();
    if (auto r = rgb::check_normal_form(t.mesh); !r.ok()) return testing::AssertionFailure() << r.violations.front();
    return everything_agrees({t.mesh, t.ids, oracle_tolerance(base)});
}

std::vector<TestMesh> request_meshes() {
    return {icosahedron(), bipyramid(5), fan(7), grid(3, 2), perforated_slab(7, 7, 3), grid_with_holes(6, 6, 3)};
}

class CanonicalRequests : public testing::TestWithParam<TestMesh> {
protected:
    const TestMesh& base = GetParam();
    const UniformLoopOracle oracle{base.positions, base.triangles, kOracleLevels};
    const RequestOracle meaning{oracle};
};

TEST_P(CanonicalRequests, RefiningGivesExactlyTheRequestedClosure) {
    std::mt19937 rng(11);
    for (int trial = 0; trial < 6; ++trial) {
        const std::vector<Request> requests = random_requests(base, rng, 3, rgb::RequestKind::Refine, -1);
        Tracked t(base, oracle);
        std::set<Identity> expected = meaning.base();
        for (const Request& r : requests) {
            rgb::apply_request(t.mesh, as_request(r));
            expected = meaning.refined(expected, r.level, {r.ball.centre, r.ball.radius});
            ASSERT_EQ(t.ids.live_identities(), expected) << "trial " << trial;
        }
        ASSERT_TRUE(healthy(t, base)) << "trial " << trial;
    }
}

TEST_P(CanonicalRequests, CoarseningRemovesExactlyWhatTheMeaningRemoves) {
    std::mt19937 rng(12);
    for (int trial = 0; trial < 4; ++trial) {
        Tracked t(base, oracle);
        rgbtest::set_level(t.mesh, 3);
        std::set<Identity> expected = t.ids.live_identities();
        for (const Request& r : random_requests(base, rng, 3, rgb::RequestKind::Coarsen, -1)) {
            rgb::apply_request(t.mesh, as_request(r));
            expected = meaning.coarsened(expected, r.level, {r.ball.centre, r.ball.radius});
            ASSERT_EQ(t.ids.live_identities(), expected) << "trial " << trial;
        }
        ASSERT_TRUE(healthy(t, base)) << "trial " << trial;
    }
}

// A set to N (`level N` in a ball) is a coarsen to N and then a refine to N in the same ball, by the
// meaning's own rules, from any start: here the base, and the mesh at level 3 everywhere.
TEST_P(CanonicalRequests, SettingGivesExactlyWhatTheMeaningGives) {
    std::mt19937 rng(16);
    for (int trial = 0; trial < 4; ++trial) {
        Tracked t(base, oracle);
        if (trial % 2 == 1) rgbtest::set_level(t.mesh, 3);
        std::set<Identity> expected = t.ids.live_identities();
        for (const Request& r : random_requests(base, rng, 3, rgb::RequestKind::Set, -1)) {
            rgb::apply_request(t.mesh, as_request(r));
            const OracleBall ball{r.ball.centre, r.ball.radius};
            expected = meaning.refined(meaning.coarsened(expected, r.level, ball), r.level, ball);
            ASSERT_EQ(t.ids.live_identities(), expected) << "trial " << trial;
        }
        ASSERT_TRUE(healthy(t, base)) << "trial " << trial;
    }
}

// Requests of one kind commute: refine-only, coarsen-only, and `level N` with one N.
TEST_P(CanonicalRequests, EveryOrderOfOverlappingRequestsGivesTheIdenticalMesh) {
    std::mt19937 rng(13);
    const struct {
        rgb::RequestKind kind;
        int level;
        bool start_refined;
    } cases[] = {{rgb::RequestKind::Refine, -1, false}, {rgb::RequestKind::Set, 2, false}, {rgb::RequestKind::Coarsen, -1, true}};
    for (const auto& c : cases) {
        for (int trial = 0; trial < 2; ++trial) {
            const std::vector<Request> requests = random_requests(base, rng, 4, c.kind, c.level);
            std::vector<std::size_t> order(requests.size());
            std::iota(order.begin(), order.end(), 0);
            rgb::Mesh first = make_rgb_mesh(base);
            if (c.start_refined) rgbtest::set_level(first, 3);
            const rgb::Mesh start = first;
            apply_all(first, requests, order);
            EXPECT_TRUE(rgb::check_normal_form(first).ok());
            while (std::next_permutation(order.begin(), order.end())) {
                rgb::Mesh other = start;
                apply_all(other, requests, order);
                ASSERT_TRUE(same_mesh(first, other)) << "kind " << static_cast<int>(c.kind) << " trial " << trial;
            }
        }
    }
}

TEST_P(CanonicalRequests, DisjointRequestsOfAnyKindCommute) {
    // Two balls at opposite ends of the mesh, far apart compared with their size and the base edges.
    auto extreme = [&](bool high) {
        return *std::max_element(base.positions.begin(), base.positions.end(), [&](const glm::dvec3& a, const glm::dvec3& b) {
            return high ? a.x + a.y < b.x + b.y : a.x + a.y > b.x + b.y;
        });
    };
    const double diagonal = bounding_box_diagonal(base.positions);
    const Request a{rgb::RequestKind::Set, 3, {extreme(true), 0.15 * diagonal}};
    const Request b{rgb::RequestKind::Set, 1, {extreme(false), 0.15 * diagonal}};
    rgb::Mesh ab = make_rgb_mesh(base), ba = make_rgb_mesh(base);
    rgbtest::set_level(ab, 2);
    rgbtest::set_level(ba, 2);
    apply_all(ab, {a, b}, {0, 1});
    apply_all(ba, {a, b}, {1, 0});
    EXPECT_TRUE(same_mesh(ab, ba));
}

TEST_P(CanonicalRequests, StorageOfTheInputDoesNotMatter) {
    std::mt19937 rng(14);
    const std::vector<Request> requests = random_requests(base, rng, 3, rgb::RequestKind::Set, 2);
    std::vector<std::size_t> order{0, 1, 2};
    rgb::Mesh reference = make_rgb_mesh(base);
    apply_all(reference, requests, order);
    for (const TestMesh& stored : {with_rotated_corners(base), with_reversed_faces(base), with_shuffled_vertices(base, 7)}) {
        rgb::Mesh mesh = make_rgb_mesh(stored);
        apply_all(mesh, requests, order);
        EXPECT_TRUE(same_mesh(reference, mesh)) << stored.name;
    }
}

TEST_P(CanonicalRequests, HistoryDoesNotMatter) {
    std::mt19937 rng(15);
    const std::vector<Request> x = random_requests(base, rng, 3, rgb::RequestKind::Set, 2);
    const std::vector<std::size_t> order{0, 1, 2};
    rgb::Mesh once = make_rgb_mesh(base);
    apply_all(once, x, order);
    // X; level 0; X
    rgb::Mesh twice = make_rgb_mesh(base);
    apply_all(twice, x, order);
    rgbtest::set_level(twice, 0);
    EXPECT_TRUE(same_mesh(twice, make_rgb_mesh(base)));
    apply_all(twice, x, order);
    EXPECT_TRUE(same_mesh(once, twice));
    // Saving and restoring between the requests.
    rgb::Mesh resumed = make_rgb_mesh(base);
    for (std::size_t i : order) {
        resumed = rgb::restore_state(rgb::capture_state(resumed));
        rgb::apply_request(resumed, as_request(x[i]));
    }
    EXPECT_TRUE(same_mesh(once, resumed));
}

INSTANTIATE_TEST_SUITE_P(Meshes, CanonicalRequests, testing::ValuesIn(request_meshes()),
                         [](const testing::TestParamInfo<TestMesh>& info) { return info.param.name; });

// A ball far smaller than a face, inside one, asking for a deep level: every face whose triangle
// meets it gets exactly that level, at a face's interior point, at a base vertex and on a base edge.
TEST(SmallRegions, ReachTheirLevel) {
    const TestMesh base = icosahedron();
    const rgb::Triangle& t = base.triangles[0];
    const glm::dvec3 a = base.positions[t[0]], b = base.positions[t[1]], c = base.positions[t[2]];
    const double edge = glm::distance(a, b);
    for (const glm::dvec3& centre : {(a + b + c) / 3.0, a, 0.5 * (a + b), 0.7 * a + 0.2 * b + 0.1 * c}) {
        for (int level : {5, 8}) {
            rgb::Mesh mesh = make_rgb_mesh(base);
            const rgb::Sphere ball{centre, 1e-3 * edge};
            rgbtest::set_level(mesh, level, ball);
            std::size_t meeting = 0;
            for (rgb::FaceId f : mesh.faces()) {
                std::array<glm::dvec3, 3> corners;
                for (int i = 0; i < 3; ++i) corners[i] = mesh.base_space_position(mesh.face_vertices(f)[i]);
                if (oracle_distance_to_triangle(ball.centre, corners[0], corners[1], corners[2]) > ball.radius) continue;
                ++meeting;
                EXPECT_EQ(mesh.level(f), level);
            }
            EXPECT_GT(meeting, 0u);
            EXPECT_TRUE(rgb::check_invariants(mesh).ok());
            EXPECT_TRUE(rgb::check_normal_form(mesh).ok());
            // Locally: a deep request stays small (far fewer triangles than the level everywhere).
            EXPECT_LT(mesh.num_faces(), base.triangles.size() + 60u * static_cast<std::size_t>(level));
        }
    }
}

// A dab smaller than a face reaches its level under its centre too.
TEST(SmallRegions, ADabSmallerThanAFacePaintsIt) {
    const TestMesh base = icosahedron();
    rgb::Mesh mesh = make_rgb_mesh(base);
    const rgb::Triangle& t = base.triangles[3];
    rgb::Dab dab;
    dab.level = 6;
    dab.centre = (base.positions[t[0]] + base.positions[t[1]] + base.positions[t[2]]) / 3.0;
    dab.radius = 1e-2 * glm::distance(base.positions[t[0]], base.positions[t[1]]);
    dab.view = -dab.centre;  // looking at the face from outside
    EXPECT_GT(rgb::apply_dab(mesh, dab).splits, 0u);
    int finest = 0;
    for (rgb::FaceId f : mesh.faces()) finest = std::max(finest, mesh.level(f));
    EXPECT_EQ(finest, 6);
}

}  // namespace
}  // namespace rgbtest
