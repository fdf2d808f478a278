// What a budget means (docs/requests.md "What a request means": a budget), pinned from outside the
// driver: an independent model of the key order as the definition states it (band of the edge's
// length in the uniform Loop mesh of its level, then the Morton order of its base-space midpoint, x
// highest, lowered to its endpoints' keys; ties by the midpoint), computed on the uniform Loop oracle,
// gives the same vertex set as the driver on random meshes and budgets. And the order has no ties left
// to storage: with coincident vertices (a UV seam stored as two vertex copies) the face order of the
// input does not change a budget's result.
#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <map>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "rgb/lod/lod_driver.h"
#include "rgb/lod/requests.h"
#include "rgb/mesh/invariants.h"
#include "rgb/mesh/mesh.h"
#include "support/budget_run.h"
#include "support/identity_tracker.h"
#include "support/request_oracle.h"
#include "support/same_mesh.h"
#include "support/test_meshes.h"
#include "support/triangle_keys.h"
#include "support/uniform_loop_oracle.h"
#include "support/set_level.h"

namespace rgbtest {
namespace {

// ---- the key order as the definition states it ------------------------------------------------

// The Morton code of a cell, bit by bit: from the highest bit down, x's bit, then y's, then z's.
std::uint64_t interleaved(const std::array<std::uint64_t, 3>& cell) {
    std::uint64_t code = 0;
    for (int bit = 15; bit >= 0; --bit)
        for (int axis = 0; axis < 3; ++axis) code = (code << 1) | ((cell[static_cast<std::size_t>(axis)] >> bit) & 1u);
    return code;
}

class BudgetByDefinition {
public:
    BudgetByDefinition(const UniformLoopOracle& oracle, const RequestOracle& meaning, int cap)
        : oracle_(oracle), meaning_(meaning), key_(oracle.num_identities(cap), ~std::uint64_t(0)) {
        const std::size_t base = oracle.num_identities(0);
        glm::dvec3 lo = oracle.position(0, 0), hi = lo;
        for (Identity i = 0; i < base; ++i) {
            lo = glm::min(lo, oracle.position(0, i));
            hi = glm::max(hi, oracle.position(0, i));
        }
        // The box onto 16 bits per axis, as canonical_order.h maps it.
        const glm::dvec3 scale = 65535.0 / glm::max(hi - lo, glm::dvec3(1e-300));
        // Identities come level by level, so both ends of a split are keyed before it.
        for (Identity v = static_cast<Identity>(base); v < key_.size(); ++v) {
            const auto [x, y] = meaning.parents(v);
            const int level = oracle.level(v) - 1;
            const double length = glm::distance(oracle.position(level, x), oracle.position(level, y));
            const auto band = static_cast<std::uint64_t>(std::floor(2.0 * std::log2(length)) + 32768.0);
            std::array<std::uint64_t, 3> cell{};
            for (int axis = 0; axis < 3; ++axis)
                cell[static_cast<std::size_t>(axis)] = static_cast<std::uint64_t>(
                    std::clamp((meaning.base_space(v)[axis] - lo[axis]) * scale[axis], 0.0, 65535.0));
            key_[v] = std::min({(band << 48) | interleaved(cell), key_[x], key_[y]});
            order_.push_back(v);
        }
        // Highest key first; equal keys by the greater base-space midpoint (x, then y, then z).
        std::sort(order_.begin(), order_.end(), [&](Identity a, Identity b) {
            const glm::dvec3 &ma = meaning.base_space(a), &mb = meaning.base_space(b);
            return std::tie(key_[a], ma.x, ma.y, ma.z) > std::tie(key_[b], mb.x, mb.y, mb.z);
        });
        // For the triangle count of a vertex set: the Euler characteristic and the boundary.
        std::set<std::pair<Identity, Identity>> edges;
        std::map<std::pair<Identity, Identity>, int> finest_edges;
        for (const IdentityTriangle& t : oracle.faces(0))
            for (int i = 0; i < 3; ++i) edges.insert(std::minmax(t[i], t[(i + 1) % 3]));
        euler_ = static_cast<long>(base) - static_cast<long>(edges.size()) + static_cast<long>(oracle.faces(0).size());
        for (const IdentityTriangle& t : oracle.faces(cap))
            for (int i = 0; i < 3; ++i) ++finest_edges[std::minmax(t[i], t[(i + 1) % 3])];
        for (const auto& [edge, faces] : finest_edges)
            if (faces == 1) boundary_.insert({edge.first, edge.second});
    }

    // Triangles of the RGB mesh of a vertex set: a triangulation of the surface, so F = 2V - Vb - 2χ
    // (Euler's formula with 3F = 2E - Eb and as many boundary edges as boundary vertices).
    long triangles(const std::set<Identity>& vertices) const {
        long on_boundary = 0;
        for (Identity v : vertices) on_boundary += boundary_.count(v) > 0 ? 1 : 0;
        return 2 * static_cast<long>(vertices.size()) - on_boundary - 2 * euler_;
    }

    // The mesh of the first n splits of the order, and what they need.
    std::set<Identity> first(std::size_t n) const {
        std::set<Identity> vertices = meaning_.base();
        vertices.insert(order_.begin(), order_.begin() + static_cast<std::ptrdiff_t>(n));
        return meaning_.closure(vertices);
    }

    // The longest prefix of the order whose mesh keeps at most `budget` triangles (the count only
    // grows along the order).
    std::set<Identity> result(std::size_t budget) const {
        std::size_t lo = 0, hi = order_.size();
        while (lo < hi) {
            const std::size_t mid = (lo + hi + 1) / 2;
            if (triangles(first(mid)) <= static_cast<long>(budget)) lo = mid;
            else hi = mid - 1;
        }
        return first(lo);
    }

private:
    const UniformLoopOracle& oracle_;
    const RequestOracle& meaning_;
    std::vector<std::uint64_t> key_;  // by identity; base vertices the largest key
    std::vector<Identity> order_;
    std::set<Identity> boundary_;
    long euler_ = 0;
};

TestMesh jittered(TestMesh m, std::mt19937& rng) {
    std::uniform_real_distribution<double> jitter(-0.08, 0.08);
    for (glm::dvec3& p : m.positions) p += glm::dvec3(jitter(rng), jitter(rng), jitter(rng));
    m.name += "-jittered";
    return m;
}

TEST(BudgetMeaning, TheDriverKeepsTheVerticesTheKeyOrderDefines) {
    constexpr int kCap = 3;
    std::mt19937 rng(31);
    for (const TestMesh& shape : {icosahedron(), grid(3, 2), fan(7), octahedron()})
        for (int trial = 0; trial < 2; ++trial) {
            const TestMesh base = jittered(shape, rng);
            const UniformLoopOracle oracle(base.positions, base.triangles, kCap);
            const RequestOracle meaning(oracle);
            const BudgetByDefinition model(oracle, meaning, kCap);
            const std::size_t most = oracle.faces(kCap).size();
            std::uniform_int_distribution<std::size_t> budgets(base.triangles.size(), most);
            for (int b = 0; b < 6; ++b) {
                const std::size_t budget = budgets(rng);
                rgb::Mesh mesh = make_rgb_mesh(base);
                IdentityTracker ids(mesh, oracle);
                run_budget(mesh, budget, kCap);
                const std::set<Identity> expected = model.result(budget);
                EXPECT_EQ(ids.live_identities(), expected) << base.name << ", budget " << budget;
                EXPECT_EQ(static_cast<long>(mesh.num_faces()), model.triangles(expected)) << base.name << ", budget " << budget;
            }
        }
}

// ---- coincident vertices ----------------------------------------------------------------------

// A torus cut open along one ring of its tube and stored with that ring twice (the seam of a UV
// layout): coincident vertices, whose edges along the seam have equal midpoints.
TestMesh seam_split_torus(int around, int tube) {
    TestMesh m = torus(around, tube);
    m.name = "seam-split " + m.name;
    const auto ring = [&](std::uint32_t v) { return static_cast<int>(v) / tube; };
    const auto copy_of = [&](std::uint32_t v) { return static_cast<std::uint32_t>(around * tube) + v; };
    for (int j = 0; j < tube; ++j) m.positions.push_back(m.positions[static_cast<std::size_t>(j)]);
    // The faces of the last segment meet ring 0 from the other side: they take the copies.
    for (rgb::Triangle& t : m.triangles)
        if (std::any_of(t.begin(), t.end(), [&](std::uint32_t v) { return ring(v) == around - 1; }))
            for (std::uint32_t& v : t)
                if (ring(v) == 0) v = copy_of(v);
    return m;
}

// The mesh as triangles of base-space corners (each rotated to start at its least corner): storage
// free, and it tells apart triangles on either side of the seam, whose third corners differ.
std::multiset<std::array<std::tuple<double, double, double>, 3>> triangles_in_base_space(const rgb::Mesh& mesh) {
    std::multiset<std::array<std::tuple<double, double, double>, 3>> triangles;
    for (rgb::FaceId f : mesh.faces()) {
        std::array<std::tuple<double, double, double>, 3> t;
        for (int i = 0; i < 3; ++i) {
            const glm::dvec3 p = mesh.base_space_position(mesh.face_vertices(f)[static_cast<std::size_t>(i)]);
            t[static_cast<std::size_t>(i)] = {p.x, p.y, p.z};
        }
        triangles.insert(canonical_rotation(t));
    }
    return triangles;
}

// Step by step, the splits come in the same order whatever the storage, so every budget (the mesh
// after some number of steps) gives the same result.
TEST(BudgetMeaning, CoincidentVerticesLeaveNoTieToTheFaceOrder) {
    const TestMesh torus = seam_split_torus(12, 6);
    TestMesh shuffled = with_shuffled_vertices(torus, 5);
    std::mt19937 rng(7);
    std::shuffle(shuffled.triangles.begin(), shuffled.triangles.end(), rng);
    for (const TestMesh& other : {with_reversed_faces(torus), with_rotated_corners(with_reversed_faces(torus)), shuffled}) {
        rgb::Mesh a = make_rgb_mesh(torus), b = make_rgb_mesh(other);
        rgb::LodSettings settings;
        settings.max_triangles = 6 * torus.triangles.size();
        settings.uniform_start = false;  // one split a step
        rgb::LodDriver run_a(a, settings), run_b(b, settings);
        for (std::size_t step = 0;; ++step) {
            const bool more = run_a.step();
            ASSERT_EQ(run_b.step(), more) << other.name << ", step " << step;
            if (!more) break;
            ASSERT_EQ(a.num_faces(), b.num_faces()) << other.name << ", step " << step;
            ASSERT_EQ(triangles_in_base_space(a), triangles_in_base_space(b)) << other.name << ", step " << step;
        }
    }
}

// The vertex set as base-space points: storage free.
// The triangles as sets of base-space corners, blind to orientation.
std::multiset<std::array<std::tuple<double, double, double>, 3>> unoriented_triangles(const rgb::Mesh& mesh) {
    std::multiset<std::array<std::tuple<double, double, double>, 3>> triangles;
    for (std::array<std::tuple<double, double, double>, 3> t : triangles_in_base_space(mesh)) {
        std::sort(t.begin(), t.end());
        triangles.insert(t);
    }
    return triangles;
}

// Whether the two triangulations of one vertex set differ only by quadrilaterals cut by the other
// diagonal: every triangle found in one alone pairs, across an edge, with another found there alone,
// and the quadrilateral the two make is cut the other way in the other triangulation.
testing::AssertionResult only_diagonals_differ(const std::multiset<std::array<std::tuple<double, double, double>, 3>>& a,
                                               const std::multiset<std::array<std::tuple<double, double, double>, 3>>& b) {
    using Corner = std::tuple<double, double, double>;
    using Triangle = std::array<Corner, 3>;
    std::set<Triangle> a_only, b_only, explained_a, explained_b;
    std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::inserter(a_only, a_only.end()));
    std::set_difference(b.begin(), b.end(), a.begin(), a.end(), std::inserter(b_only, b_only.end()));
    auto sorted = [](Triangle t) {
        std::sort(t.begin(), t.end());
        return t;
    };
    for (const Triangle& t : a_only)
        for (const Triangle& u : a_only)
            for (int i = 0; i < 3; ++i) {
                // t's edge (t[i], t[i+1]) shared with u, and the corners off that edge.
                const Corner p = t[i], q = t[(i + 1) % 3], r = t[(i + 2) % 3];
                if (&t == &u || std::count(u.begin(), u.end(), p) == 0 || std::count(u.begin(), u.end(), q) == 0) continue;
                const Corner s = *std::find_if(u.begin(), u.end(), [&](const Corner& c) { return c != p && c != q; });
                const Triangle x = sorted({r, s, p}), y = sorted({r, s, q});
                if (b_only.count(x) && b_only.count(y)) {
                    explained_a.insert({t, u});
                    explained_b.insert({x, y});
                }
            }
    if (explained_a != a_only || explained_b != b_only)
        return testing::AssertionFailure() << a_only.size() - explained_a.size() << " and " << b_only.size() - explained_b.size()
                                           << " triangles differ otherwise";
    return testing::AssertionSuccess() << a_only.size() << " triangles in other diagonals";
}

// docs/requests.md: reversing every face's orientation keeps the vertices of level requests and
// budgets, but the normal form's diagonal is chiral, so the triangulation can change (and does here):
// exactly by quadrilaterals cut by the other diagonal, the reversed result in the normal form too.
TEST(BudgetMeaning, ReversedOrientationKeepsTheVerticesNotAlwaysTheDiagonals) {
    const TestMesh base = icosahedron();
    TestMesh mirrored = base;
    for (rgb::Triangle& t : mirrored.triangles) std::swap(t[1], t[2]);
    std::size_t other_diagonals = 0;
    auto compare = [&](const rgb::Mesh& a, const rgb::Mesh& b, const std::string& what) {
        EXPECT_EQ(base_space_vertex_set(a), base_space_vertex_set(b)) << what;
        const auto ta = unoriented_triangles(a), tb = unoriented_triangles(b);
        EXPECT_TRUE(only_diagonals_differ(ta, tb)) << what;
        EXPECT_TRUE(rgb::check_normal_form(b).ok()) << what;
        other_diagonals += ta != tb;
    };
    for (std::size_t budget : {47, 130, 333, 700}) {
        rgb::Mesh a = make_rgb_mesh(base), b = make_rgb_mesh(mirrored);
        run_budget(a, budget, rgb::kMaxLevel);
        run_budget(b, budget, rgb::kMaxLevel);
        compare(a, b, "budget " + std::to_string(budget));
    }
    for (double radius : {0.3, 0.8}) {
        rgb::Mesh a = make_rgb_mesh(base), b = make_rgb_mesh(mirrored);
        rgbtest::set_level(a, 3, rgb::Sphere{base.positions[2], radius});
        rgbtest::set_level(b, 3, rgb::Sphere{base.positions[2], radius});
        compare(a, b, "level 3 in a ball of radius " + std::to_string(radius));
    }
    EXPECT_GT(other_diagonals, 0u) << "the normal form is chiral: some mirrored result must pick other diagonals";
}

}  // namespace
}  // namespace rgbtest
