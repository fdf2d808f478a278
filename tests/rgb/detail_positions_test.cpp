// Detail positions (rgb/mesh/detail_positions.h): a cage's vertices shown at sampled points, a
// function of the address alone. Checked against closed forms: the number of points of Σk, an
// affine function (which the piecewise-linear lookup beyond the sampled level must reproduce), and
// the sampled values themselves at every address of every grid point; with levels per face, the
// stored points against the definition of the sampled ones (support/detail_sampling.h), every
// address of every point of Σ5 alike from every face, and edge points between their samples; then
// through the mesh: every displayed vertex of random adaptive meshes, in any request order and after
// a save and restore.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <set>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "rgb/lod/requests.h"
#include "rgb/mesh/detail_positions.h"
#include "rgb/mesh/mesh.h"
#include "rgb/mesh/state.h"
#include "rgb/values/loop_geometry.h"
#include "rgb/values/restore_state.h"
#include "support/detail_sampling.h"
#include "support/test_meshes.h"
#include "support/set_level.h"

namespace {

using rgb::DetailPositions;
using rgbtest::sampled_by_definition;
using rgb::SurfacePoint;

// A smooth, non-affine stand-in for a dense surface: each base-space point moved by a wave.
glm::dvec3 wavy(const glm::dvec3& p) { return p + 0.05 * glm::dvec3(std::sin(7 * p.y), std::cos(5 * p.z), std::sin(3 * p.x + p.y)); }
// An affine map, which piecewise-linear interpolation reproduces up to rounding.
glm::dvec3 affine(const glm::dvec3& p) { return {2 * p.x - p.y + 0.5, p.y + 3 * p.z - 1.0, -p.x + 0.25 * p.z + 2.0}; }

template <class F>
std::shared_ptr<const DetailPositions> sampled(const rgb::BaseMesh& base, int level, F f) {
    std::vector<glm::dvec3> values;
    for (const SurfacePoint& p : DetailPositions::grid_points(base, level)) values.push_back(f(rgb::base_space_position(base, p)));
    return std::make_shared<const DetailPositions>(base, level, values);
}

template <class F>
std::shared_ptr<const DetailPositions> sampled(const rgb::BaseMesh& base, const std::vector<std::uint8_t>& levels, F f) {
    std::vector<glm::dvec3> values;
    for (const SurfacePoint& p : DetailPositions::grid_points(base, levels)) values.push_back(f(rgb::base_space_position(base, p)));
    return std::make_shared<const DetailPositions>(base, levels, values);
}

// Levels 1..4 mixed over the faces, so that edges join faces of equal and of different levels.
std::vector<std::uint8_t> mixed_levels(const rgb::BaseMesh& base) {
    std::vector<std::uint8_t> levels(base.num_faces());
    for (std::size_t f = 0; f < levels.size(); ++f) levels[f] = static_cast<std::uint8_t>(1 + (f * 7 + f / 3) % 4);
    return levels;
}

// Every point of Σ_level of every face, unreduced, in that face.
// Whether the detail of `affine` gives at p the affine function's value at p's base-space position,
// within 1e-12 relative (interpolation reproduces an affine function).
::testing::AssertionResult reproduces_affine(const DetailPositions& detail, const rgb::BaseMesh& base, const SurfacePoint& p) {
    const glm::dvec3 expected = affine(rgb::base_space_position(base, rgb::reduced(p)));
    const glm::dvec3 got = detail.position(base, p);
    if (glm::distance(got, expected) <= 1e-12 * (1.0 + glm::length(expected))) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "face " << p.face << " level " << p.level << ": got (" << got.x << ", " << got.y << ", "
                                         << got.z << "), expected (" << expected.x << ", " << expected.y << ", " << expected.z << ")";
}

std::vector<SurfacePoint> every_address(const rgb::BaseMesh& base, int level) {
    std::vector<SurfacePoint> points;
    const std::uint32_t n = 1u << level;
    for (std::uint32_t f = 0; f < base.num_faces(); ++f)
        for (std::uint32_t a2 = 0; a2 <= n; ++a2)
            for (std::uint32_t a1 = 0; a1 + a2 <= n; ++a1) points.push_back(SurfacePoint{f, {n - a1 - a2, a1, a2}, level});
    return points;
}

std::size_t edge_count(const rgb::BaseMesh& base) {
    std::size_t halfedges = 0, boundary = 0;
    for (std::uint32_t h = 0; h < 3 * base.num_faces(); ++h) {
        ++halfedges;
        boundary += base.opposite(h) == rgb::BaseMesh::kNone;
    }
    return (halfedges + boundary) / 2;
}

class DetailOnMeshes : public ::testing::TestWithParam<rgbtest::TestMesh> {};

TEST_P(DetailOnMeshes, GridHasEveryPointOfTheLevelOnce) {
    const rgbtest::TestMesh& m = GetParam();
    const rgb::BaseMesh base(m.positions, m.triangles);
    for (int level : {0, 1, 2, 3}) {
        const std::vector<SurfacePoint> points = DetailPositions::grid_points(base, level);
        // V + E (2^k - 1) + F (2^k - 1)(2^k - 2) / 2: the vertices of Σk.
        const std::size_t n = std::size_t(1) << level;
        EXPECT_EQ(points.size(), base.num_vertices() + edge_count(base) * (n - 1) + base.num_faces() * (n - 1) * (n - 2) / 2)
            << "level " << level;
        std::set<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t, std::uint32_t, int>> seen;
        for (const SurfacePoint& p : points) {
            EXPECT_EQ(rgb::canonical(base, p), p);
            EXPECT_TRUE(seen.insert({p.face, p.a[0], p.a[1], p.a[2], p.level}).second);
        }
    }
}

TEST_P(DetailOnMeshes, EveryAddressOfAGridPointGivesItsSample) {
    const rgbtest::TestMesh& m = GetParam();
    const rgb::BaseMesh base(m.positions, m.triangles);
    const int level = 2;
    const auto detail = sampled(base, level, wavy);
    const std::uint32_t n = 1u << level;
    for (std::uint32_t f = 0; f < base.num_faces(); ++f)
        for (std::uint32_t a2 = 0; a2 <= n; ++a2)
            for (std::uint32_t a1 = 0; a1 + a2 <= n; ++a1) {
                SurfacePoint p;
                p.face = f;
                p.level = level;
                p.a = {n - a1 - a2, a1, a2};
                const glm::dvec3 expected = wavy(rgb::base_space_position(base, rgb::reduced(p)));
                const glm::dvec3 got = detail->position(base, p);  // unreduced, in this face
                ASSERT_EQ(got, expected) << "face " << f << " (" << a1 << ", " << a2 << ")";
            }
}

TEST_P(DetailOnMeshes, FinerPointsInterpolateTheGridLinearly) {
    const rgbtest::TestMesh& m = GetParam();
    const rgb::BaseMesh base(m.positions, m.triangles);
    const auto detail = sampled(base, 1, affine);
    std::mt19937 rng(7);
    for (int trial = 0; trial < 2000; ++trial) {
        SurfacePoint p;
        p.face = static_cast<std::uint32_t>(rng() % base.num_faces());
        p.level = 2 + static_cast<int>(rng() % 6);
        const std::uint32_t n = 1u << p.level;
        const std::uint32_t a1 = rng() % (n + 1), a2 = rng() % (n + 1 - a1);
        p.a = {n - a1 - a2, a1, a2};
        EXPECT_TRUE(reproduces_affine(*detail, base, p));
        const glm::dvec3 got = detail->position(base, p);
        // Any face of a point on a base edge gives the same bits.
        for (std::uint32_t g = 0; g < base.num_faces(); ++g) {
            if (const auto q = rgb::in_face(base, rgb::reduced(p), g)) {
                ASSERT_EQ(detail->position(base, *q), got);
            }
        }
    }
}

// The meshes of random requests display every vertex at the sample of its address (sampled: within
// its face's or edge's level of the mixed levels) or at the interpolation (finer): in any request
// order, and after a save and restore.
TEST_P(DetailOnMeshes, DisplayedVerticesAreTheirAddressesSamples) {
    const rgbtest::TestMesh& m = GetParam();
    const rgb::BaseMesh plain(m.positions, m.triangles);
    const std::vector<std::uint8_t> levels = mixed_levels(plain);
    const auto detail = sampled(plain, levels, wavy);
    auto base = std::make_shared<const rgb::BaseMesh>(m.positions, m.triangles, rgb::SharpFeatures{}, detail);
    std::mt19937 rng(11);
    std::vector<std::pair<int, rgb::Sphere>> requests;
    const double diagonal = rgbtest::bounding_box_diagonal(m.positions);
    for (int i = 0; i < 6; ++i) {
        const glm::dvec3 centre = m.positions[rng() % m.positions.size()];
        requests.push_back({1 + static_cast<int>(rng() % 5), rgb::Sphere{centre, diagonal * (0.1 + 0.05 * (rng() % 5))}});
    }
    rgb::Mesh forward(base), backward(base);
    for (const auto& [level, sphere] : requests) rgbtest::set_level(forward, level, sphere);
    for (auto it = requests.rbegin(); it != requests.rend(); ++it) rgbtest::set_level(backward, it->first, it->second);
    for (const rgb::Mesh* mesh : {&forward, &backward})
        for (rgb::VertexId v : mesh->vertices()) {
            const glm::dvec3 shown = rgb::displayed_position(*mesh, v);
            ASSERT_EQ(shown, detail->position(*base, mesh->address(v)));
            if (sampled_by_definition(plain, levels, mesh->address(v))) {
                ASSERT_EQ(shown, wavy(mesh->base_space_position(v)));
            }
        }
    rgb::RestoredPositions positions;
    const rgb::Mesh restored = rgb::restore_state(rgb::capture_state(forward), {}, nullptr, &positions);
    ASSERT_NE(restored.base().detail(), nullptr);
    std::size_t i = 0;
    for (rgb::VertexId v : restored.vertices()) {
        ASSERT_EQ(rgb::displayed_position(restored, v), detail->position(*base, restored.address(v)));
        ASSERT_EQ(positions.values[i++], rgb::displayed_position(restored, v));
    }
    // Retagging keeps the detail: the positions are the surface's, not Loop's.
    const rgb::Mesh retagged = rgb::with_sharp_features(forward, rgb::SharpFeatures{});
    for (rgb::VertexId v : retagged.vertices()) ASSERT_EQ(rgb::displayed_position(retagged, v), rgb::displayed_position(forward, v));
}

// Levels per face: the stored points are the sampled ones of the definition, each once; every
// address of a sampled point gives its sample, bit for bit, whichever face (of whatever level) it is
// given in; and every other point gives the same bits from every address.
TEST_P(DetailOnMeshes, MixedLevelsStoreEverySampledPointOnceAndAnswerAlikeFromEveryFace) {
    const rgbtest::TestMesh& m = GetParam();
    const rgb::BaseMesh base(m.positions, m.triangles);
    const std::vector<std::uint8_t> levels = mixed_levels(base);
    std::set<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t, std::uint32_t, int>> expected;
    for (const SurfacePoint& p : every_address(base, 4))
        if (sampled_by_definition(base, levels, p)) {
            const SurfacePoint c = rgb::canonical(base, rgb::reduced(p));
            expected.insert({c.face, c.a[0], c.a[1], c.a[2], c.level});
        }
    const std::vector<SurfacePoint> points = DetailPositions::grid_points(base, levels);
    EXPECT_EQ(points.size(), expected.size());
    EXPECT_EQ(DetailPositions::num_points(base, levels), expected.size());
    std::set<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t, std::uint32_t, int>> stored;
    for (const SurfacePoint& p : points) {
        const SurfacePoint c = rgb::canonical(base, p);
        EXPECT_TRUE(stored.insert({c.face, c.a[0], c.a[1], c.a[2], c.level}).second) << "a point stored twice";
    }
    EXPECT_EQ(stored, expected);

    const auto detail = sampled(base, levels, wavy);
    EXPECT_EQ(detail->coarsest_level(), 1);
    EXPECT_EQ(detail->finest_level(), 4);
    std::size_t sampled_points = 0, interpolated = 0, edge_points_between = 0;
    for (const SurfacePoint& p : every_address(base, 5)) {
        const glm::dvec3 got = detail->position(base, p);
        const SurfacePoint r = rgb::reduced(p);
        const bool is_sampled = sampled_by_definition(base, levels, p);
        ASSERT_EQ(detail->is_sampled(base, p), is_sampled);
        if (is_sampled) {
            ASSERT_EQ(got, wavy(rgb::base_space_position(base, r))) << "face " << p.face << " level " << r.level;
            ++sampled_points;
        } else {
            ++interpolated;
        }
        // An edge point finer than one of its faces and within the other's level: the edge has the
        // coarser level, so it is interpolated along the edge.
        if (const auto h = rgb::base_edge_of(r); h && base.opposite(*h) != rgb::BaseMesh::kNone) {
            const int here = levels[p.face], there = levels[base.opposite(*h) / 3];
            if (r.level > std::min(here, there) && r.level <= std::max(here, there)) {
                ASSERT_FALSE(is_sampled);
                ++edge_points_between;
            }
        }
        for (std::uint32_t g = 0; g < base.num_faces(); ++g)
            if (const auto q = rgb::in_face(base, r, g)) {
                ASSERT_EQ(detail->position(base, *q), got) << "face " << g;
            }
    }
    EXPECT_GT(sampled_points, 0u);
    EXPECT_GT(interpolated, 0u);
    EXPECT_GT(edge_points_between, 0u);
    // Saved and given back (samples, in grid_points' order): the same detail, bit for bit.
    const DetailPositions again(base, levels, detail->samples(base));
    for (const SurfacePoint& p : every_address(base, 6)) ASSERT_EQ(again.position(base, p), detail->position(base, p));
}

// Beyond the levels the samples are interpolated linearly, inside a face in its grid triangle and on
// a base edge between its two neighbouring samples: an affine function is reproduced everywhere.
TEST_P(DetailOnMeshes, MixedLevelsInterpolateLinearlyInFacesAndAlongEdges) {
    const rgbtest::TestMesh& m = GetParam();
    const rgb::BaseMesh base(m.positions, m.triangles);
    const std::vector<std::uint8_t> levels = mixed_levels(base);
    const auto detail = sampled(base, levels, affine);
    const auto wavy_detail = sampled(base, levels, wavy);
    for (const SurfacePoint& p : every_address(base, 6)) {
        ASSERT_TRUE(reproduces_affine(*detail, base, p));
        // An edge point one level finer than its edge lies halfway between its neighbours on the edge.
        const SurfacePoint r = rgb::reduced(p);
        const auto h = rgb::base_edge_of(r);
        if (!h) continue;
        const int edge = base.opposite(*h) == rgb::BaseMesh::kNone ? levels[r.face]
                                                                   : std::min<int>(levels[r.face], levels[base.opposite(*h) / 3]);
        if (r.level != edge + 1) continue;
        SurfacePoint a = r, b = r;
        for (int i = 0; i < 3; ++i)
            if (r.a[i] % 2 == 1) {
                a.a[i] -= 1;
                b.a[i] += 1;
                break;
            }
        for (int i = 2; i >= 0; --i)
            if (r.a[i] % 2 == 1) {
                a.a[i] += 1;
                b.a[i] -= 1;
                break;
            }
        const glm::dvec3 halfway = 0.5 * (wavy_detail->position(base, a) + wavy_detail->position(base, b));
        const glm::dvec3 between = wavy_detail->position(base, r);
        ASSERT_NEAR(glm::length(between - halfway), 0.0, 1e-14 * (1.0 + glm::length(halfway)));
    }
}

// The positions are a continuous function of the address: next to a base edge between faces of
// different levels, a point inside either face and its neighbour on the edge draw together as the
// level grows (a step between them would stay, and budgets would split there without end).
TEST_P(DetailOnMeshes, MixedLevelsAreContinuousAcrossBaseEdges) {
    const rgbtest::TestMesh& m = GetParam();
    const rgb::BaseMesh base(m.positions, m.triangles);
    const auto detail = sampled(base, mixed_levels(base), wavy);
    // The largest difference between a point on a base edge and its neighbour inside a face at `level`.
    auto largest_step = [&](int level) {
        const std::uint32_t n = std::uint32_t(1) << level;
        double step = 0.0;
        for (std::uint32_t f = 0; f < base.num_faces(); ++f)
            for (std::uint32_t a1 = 1; a1 + 1 < n; a1 += 7) {
                // On the edge a2 = 0, and one step inside.
                const SurfacePoint on_edge{f, {n - a1, a1, 0}, level}, inside{f, {n - a1 - 1, a1, 1}, level};
                step = std::max(step, glm::distance(detail->position(base, on_edge), detail->position(base, inside)));
            }
        return step;
    };
    const double coarse = largest_step(8), fine = largest_step(12);
    EXPECT_LT(fine, coarse / 8) << "steps " << coarse << " at level 8, " << fine << " at level 12";
}

INSTANTIATE_TEST_SUITE_P(Meshes, DetailOnMeshes,
                         ::testing::Values(rgbtest::tetrahedron(), rgbtest::icosahedron(), rgbtest::grid(4, 3),
                                           rgbtest::grid_with_holes(6, 6, 3)));

TEST(DetailPositions, RefusesAWrongCountOrLevel) {
    const rgbtest::TestMesh m = rgbtest::octahedron();
    const rgb::BaseMesh base(m.positions, m.triangles);
    const std::vector<glm::dvec3> too_few(3);
    EXPECT_THROW(DetailPositions(base, 1, too_few), std::invalid_argument);
    // Levels: one per face, each at most kMaxLevel, and as many values as they need.
    const std::vector<glm::dvec3> level_one(DetailPositions::num_points(base, DetailPositions::uniform_levels(base, 1)));
    EXPECT_NO_THROW(DetailPositions(base, DetailPositions::uniform_levels(base, 1), level_one));
    EXPECT_THROW(DetailPositions(base, std::vector<std::uint8_t>(base.num_faces() - 1, 1), level_one), std::invalid_argument);
    std::vector<std::uint8_t> one_finer = DetailPositions::uniform_levels(base, 1);
    one_finer[3] = 2;
    EXPECT_THROW(DetailPositions(base, one_finer, level_one), std::invalid_argument);
    one_finer[3] = DetailPositions::kMaxLevel + 1;
    EXPECT_THROW(DetailPositions::num_points(base, one_finer), std::invalid_argument);
    // A face at the finest level with a count of values that would need terabytes is refused
    // without allocating them.
    EXPECT_THROW(DetailPositions(base, std::vector<std::uint8_t>(base.num_faces(), DetailPositions::kMaxLevel), level_one),
                 std::invalid_argument);
    EXPECT_THROW(DetailPositions::grid_points(base, DetailPositions::kMaxLevel + 1), std::invalid_argument);
    EXPECT_THROW(DetailPositions::grid_points(base, -1), std::invalid_argument);
    const rgbtest::TestMesh other = rgbtest::tetrahedron();
    const rgb::BaseMesh other_base(other.positions, other.triangles);
    const auto detail = sampled(other_base, 1, wavy);
    EXPECT_THROW(rgb::BaseMesh(m.positions, m.triangles, {}, detail), std::invalid_argument);
}

}  // namespace
