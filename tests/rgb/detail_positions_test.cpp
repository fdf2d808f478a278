// Detail positions (rgb/mesh/detail_positions.h): a cage's vertices shown at sampled points, a
// function of the address alone. Checked against closed forms: the number of points of Σk, an
// affine function (which the piecewise-linear lookup beyond the sampled level must reproduce), and
// the sampled values themselves at every address of every grid point; then through the mesh: every
// displayed vertex of random adaptive meshes, in any request order and after a save and restore.
#include <cmath>
#include <memory>
#include <random>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "rgb/lod/requests.h"
#include "rgb/mesh/detail_positions.h"
#include "rgb/mesh/mesh.h"
#include "rgb/mesh/state.h"
#include "rgb/values/loop_geometry.h"
#include "rgb/values/restore_state.h"
#include "support/test_meshes.h"

namespace {

using rgb::DetailPositions;
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
        const glm::dvec3 expected = affine(rgb::base_space_position(base, rgb::reduced(p)));
        const glm::dvec3 got = detail->position(base, p);
        const double scale = 1.0 + glm::length(expected);
        EXPECT_NEAR(got.x, expected.x, 1e-12 * scale);
        EXPECT_NEAR(got.y, expected.y, 1e-12 * scale);
        EXPECT_NEAR(got.z, expected.z, 1e-12 * scale);
        // Any face of a point on a base edge gives the same bits.
        for (std::uint32_t g = 0; g < base.num_faces(); ++g) {
            if (const auto q = rgb::in_face(base, rgb::reduced(p), g)) {
                ASSERT_EQ(detail->position(base, *q), got);
            }
        }
    }
}

// The meshes of random requests display every vertex at the sample of its address (level <= 3,
// sampled) or at the interpolation (finer): in any request order, and after a save and restore.
TEST_P(DetailOnMeshes, DisplayedVerticesAreTheirAddressesSamples) {
    const rgbtest::TestMesh& m = GetParam();
    const rgb::BaseMesh plain(m.positions, m.triangles);
    const auto detail = sampled(plain, 3, wavy);
    auto base = std::make_shared<const rgb::BaseMesh>(m.positions, m.triangles, rgb::SharpFeatures{}, detail);
    std::mt19937 rng(11);
    std::vector<std::pair<int, rgb::Sphere>> requests;
    const double diagonal = rgbtest::bounding_box_diagonal(m.positions);
    for (int i = 0; i < 6; ++i) {
        const glm::dvec3 centre = m.positions[rng() % m.positions.size()];
        requests.push_back({1 + static_cast<int>(rng() % 5), rgb::Sphere{centre, diagonal * (0.1 + 0.05 * (rng() % 5))}});
    }
    rgb::Mesh forward(base), backward(base);
    for (const auto& [level, sphere] : requests) rgb::set_level(forward, level, sphere);
    for (auto it = requests.rbegin(); it != requests.rend(); ++it) rgb::set_level(backward, it->first, it->second);
    for (const rgb::Mesh* mesh : {&forward, &backward})
        for (rgb::VertexId v : mesh->vertices()) {
            const glm::dvec3 shown = rgb::displayed_position(*mesh, v);
            ASSERT_EQ(shown, detail->position(*base, mesh->address(v)));
            if (mesh->level(v) <= 3) {
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

INSTANTIATE_TEST_SUITE_P(Meshes, DetailOnMeshes,
                         ::testing::Values(rgbtest::tetrahedron(), rgbtest::icosahedron(), rgbtest::grid(4, 3),
                                           rgbtest::grid_with_holes(6, 6, 3)));

TEST(DetailPositions, RefusesAWrongCountOrLevel) {
    const rgbtest::TestMesh m = rgbtest::octahedron();
    const rgb::BaseMesh base(m.positions, m.triangles);
    const std::vector<glm::dvec3> too_few(3);
    EXPECT_THROW(DetailPositions(base, 1, too_few), std::invalid_argument);
    EXPECT_THROW(DetailPositions::grid_points(base, DetailPositions::kMaxLevel + 1), std::invalid_argument);
    EXPECT_THROW(DetailPositions::grid_points(base, -1), std::invalid_argument);
    const rgbtest::TestMesh other = rgbtest::tetrahedron();
    const rgb::BaseMesh other_base(other.positions, other.triangles);
    const auto detail = sampled(other_base, 1, wavy);
    EXPECT_THROW(rgb::BaseMesh(m.positions, m.triangles, {}, detail), std::invalid_argument);
}

}  // namespace
