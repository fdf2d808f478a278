// Which requests commute (docs/requests.md "What a request means"): requests in balls far apart, of
// any kind (level or criterion; refine, coarsen or set), give the identical mesh in both orders, each
// changing vertices only inside the base faces around the corners of the faces its ball meets; and
// criterion requests in overlapping balls need not (the definition itself depends on the edges the
// mesh holds), nor level requests of different kinds in one ball. "Far apart" and the faces a
// request may change are computed here from the base mesh alone; level requests of one kind in
// overlapping balls are checked in canonical_requests_test.cpp.
#include <algorithm>
#include <array>
#include <iterator>
#include <random>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "rgb/lod/lod_criteria.h"
#include "rgb/lod/requests.h"
#include "rgb/mesh/invariants.h"
#include "support/request_oracle.h"
#include "support/same_mesh.h"
#include "support/test_meshes.h"

namespace rgbtest {
namespace {

constexpr int kCommuteCap = 4;  // no request goes finer, so the oracle covers every vertex

// One request of any kind in a ball.
struct AnyRequest {
    bool criterion = false;  // max-edge (length) rather than a level
    rgb::RequestKind kind = rgb::RequestKind::Set;
    int level = 0;
    double length = 0.0;
    rgb::Sphere ball;
};

void apply_any(rgb::Mesh& mesh, const AnyRequest& r) {
    if (r.criterion) {
        rgb::DetailRequest request;
        request.kind = r.kind;
        request.value = rgb::edge_length_value(mesh.shared_base());
        request.threshold = r.length;
        request.sphere = r.ball;
        request.max_level = kCommuteCap;
        rgb::apply_detail_request(mesh, request);
    } else {
        rgb::LevelRequest request;
        request.kind = r.kind;
        request.level = r.level;
        request.sphere = r.ball;
        rgb::apply_request(mesh, request);
    }
}

// The base faces a request in `ball` may change: those with a corner on a base face the ball meets.
std::set<std::size_t> reach_of(const TestMesh& base, const rgb::Sphere& ball) {
    std::set<std::uint32_t> corners;
    for (const rgb::Triangle& t : base.triangles)
        if (oracle_distance_to_triangle(ball.centre, base.positions[t[0]], base.positions[t[1]], base.positions[t[2]]) <= ball.radius)
            corners.insert(t.begin(), t.end());
    std::set<std::size_t> faces;
    for (std::size_t f = 0; f < base.triangles.size(); ++f)
        for (std::uint32_t v : base.triangles[f])
            if (corners.count(v)) faces.insert(f);
    return faces;
}

// Whether two sets of base faces share a face or an edge (a vertex alone does not count: base
// vertices never change).
bool share_an_edge(const TestMesh& base, const std::set<std::size_t>& a, const std::set<std::size_t>& b) {
    std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (std::size_t f : a)
        for (int i = 0; i < 3; ++i) edges.insert(std::minmax(base.triangles[f][i], base.triangles[f][(i + 1) % 3]));
    for (std::size_t f : b)
        for (int i = 0; i < 3; ++i)
            if (edges.count(std::minmax(base.triangles[f][i], base.triangles[f][(i + 1) % 3]))) return true;
    return false;
}

// Whether a base-space point lies on one of the faces (closed, within rounding).
bool on_faces(const TestMesh& base, const std::set<std::size_t>& faces, const glm::dvec3& p) {
    const double scale = bounding_box_diagonal(base.positions);
    for (std::size_t f : faces) {
        const rgb::Triangle& t = base.triangles[f];
        if (oracle_distance_to_triangle(p, base.positions[t[0]], base.positions[t[1]], base.positions[t[2]]) <= 1e-12 * scale) return true;
    }
    return false;
}

double mean_edge(const TestMesh& base) {
    double sum = 0.0;
    for (const rgb::Triangle& t : base.triangles) sum += glm::distance(base.positions[t[0]], base.positions[t[1]]);
    return sum / static_cast<double>(base.triangles.size());
}

double unit_random(std::mt19937_64& random) { return static_cast<double>(random() >> 11) * 0x1.0p-53; }

// A ball around a random point of a random base face, up to about an edge across, with a random
// request of any kind.
AnyRequest random_any_request(const TestMesh& base, std::mt19937_64& random) {
    const rgb::Triangle& t = base.triangles[random() % base.triangles.size()];
    double a = unit_random(random), b = unit_random(random);
    if (a + b > 1.0) {
        a = 1.0 - a;
        b = 1.0 - b;
    }
    AnyRequest r;
    r.ball = {base.positions[t[0]] + a * (base.positions[t[1]] - base.positions[t[0]]) + b * (base.positions[t[2]] - base.positions[t[0]]),
              mean_edge(base) * (0.05 + 0.6 * unit_random(random))};
    r.criterion = random() % 2 == 0;
    r.kind = std::array{rgb::RequestKind::Refine, rgb::RequestKind::Coarsen, rgb::RequestKind::Set}[random() % 3];
    r.level = static_cast<int>(random() % (kCommuteCap + 1));
    r.length = mean_edge(base) * (0.08 + 0.5 * unit_random(random));
    return r;
}

// Some detail to start from: level 1 everywhere and level 3 over part of the mesh.
rgb::Mesh commute_start(const TestMesh& base) {
    rgb::Mesh mesh = make_rgb_mesh(base);
    rgb::LevelRequest request;
    request.level = 1;
    rgb::apply_request(mesh, request);
    request.level = 3;
    request.sphere = rgb::Sphere{base.positions[0], 2.0 * mean_edge(base)};
    rgb::apply_request(mesh, request);
    return mesh;
}

class CommutingRequests : public testing::TestWithParam<TestMesh> {};

TEST_P(CommutingRequests, RequestsFarApartCommuteWhateverTheirKind) {
    const TestMesh& base = GetParam();
    std::mt19937_64 random(47);
    const rgb::Mesh start = commute_start(base);
    int pairs = 0, changed = 0;
    for (int attempt = 0; attempt < 200 && pairs < 8; ++attempt) {
        const AnyRequest a = random_any_request(base, random), b = random_any_request(base, random);
        const std::set<std::size_t> reach_a = reach_of(base, a.ball), reach_b = reach_of(base, b.ball);
        if (share_an_edge(base, reach_a, reach_b)) continue;
        ++pairs;
        SCOPED_TRACE("pair " + std::to_string(pairs));
        rgb::Mesh ab = start, ba = start;
        // Each request changes vertices only on the faces of its reach.
        for (const AnyRequest* r : {&a, &b}) {
            const std::set<BaseSpacePoint> before = base_space_vertex_set(ab);
            apply_any(ab, *r);
            const std::set<BaseSpacePoint> after = base_space_vertex_set(ab);
            std::set<BaseSpacePoint> difference;
            std::set_symmetric_difference(before.begin(), before.end(), after.begin(), after.end(),
                                          std::inserter(difference, difference.end()));
            changed += !difference.empty();
            for (const BaseSpacePoint& p : difference)
                EXPECT_TRUE(on_faces(base, r == &a ? reach_a : reach_b, {std::get<0>(p), std::get<1>(p), std::get<2>(p)}));
        }
        apply_any(ba, b);
        apply_any(ba, a);
        EXPECT_TRUE(same_mesh(ab, ba));
        EXPECT_TRUE(rgb::check_normal_form(ab).ok());
    }
    EXPECT_EQ(pairs, 8);
    EXPECT_GE(changed, 8);  // most requests did something
}

// By the definition itself: a criterion request splits only edges the mesh holds, so where two balls
// overlap, the first request's splits (and what they need) give the second edges to judge. Found
// among random pairs of max-edge refine requests on the base mesh (about one pair in ten differs).
TEST_P(CommutingRequests, CriterionRequestsInOverlappingBallsNeedNot) {
    const TestMesh& base = GetParam();
    std::mt19937_64 random(53);
    const rgb::Mesh start = make_rgb_mesh(base);
    int differing = 0;
    for (int attempt = 0; attempt < 100 && differing == 0; ++attempt) {
        AnyRequest a = random_any_request(base, random), b = random_any_request(base, random);
        a.criterion = b.criterion = true;
        a.kind = b.kind = rgb::RequestKind::Refine;
        b.ball.centre = a.ball.centre + 0.5 * a.ball.radius * glm::dvec3(unit_random(random), unit_random(random), 0.0);
        rgb::Mesh ab = start, ba = start;
        apply_any(ab, a);
        apply_any(ab, b);
        apply_any(ba, b);
        apply_any(ba, a);
        differing += !same_mesh(ab, ba);
    }
    EXPECT_GT(differing, 0);
}

// Level requests of different kinds in one ball: whichever comes last decides.
TEST_P(CommutingRequests, LevelRequestsOfDifferentKindsInOneBallNeedNot) {
    const TestMesh& base = GetParam();
    AnyRequest refine, coarsen;
    refine.kind = rgb::RequestKind::Refine;
    refine.level = 3;
    coarsen.kind = rgb::RequestKind::Coarsen;
    coarsen.level = 1;
    refine.ball = coarsen.ball = {base.positions[0], mean_edge(base)};
    rgb::Mesh first = make_rgb_mesh(base), second = make_rgb_mesh(base);
    apply_any(first, refine);
    apply_any(first, coarsen);
    apply_any(second, coarsen);
    apply_any(second, refine);
    EXPECT_FALSE(same_mesh(first, second));
}

INSTANTIATE_TEST_SUITE_P(Meshes, CommutingRequests, testing::Values(grid(6, 5), perforated_slab(5, 5, 2)),
                         [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace rgbtest
