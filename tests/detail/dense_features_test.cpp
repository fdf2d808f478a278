// A dense mesh's sharp features (src/detail/dense_features.h) on meshes whose features are known by
// construction: a cube tessellated on an integer grid (its twelve edges, eight corners) and a double
// cone (one closed ridge, no corner).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <set>
#include <vector>

#include <glm/geometric.hpp>

#include "detail/cage.h"
#include "detail/dense_features.h"
#include "rgb/mesh/base_mesh.h"
#include "rgb/mesh/surface_point.h"

namespace {

using rgb::Triangle;
using rgbdetail::FeatureGraph;

struct FeatureTestMesh {
    std::vector<glm::dvec3> positions;
    std::vector<Triangle> triangles;
};

// The cube [0, n]^3, each face an n x n grid of squares split in two, outward oriented. Integer
// coordinates, so that coplanar triangles have exactly parallel normals.
FeatureTestMesh tessellated_cube(int n) {
    struct Side {
        glm::ivec3 origin, u, v;  // u x v points outwards
    };
    const Side sides[] = {{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}}, {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},
                          {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}}, {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}},
                          {{0, 0, 0}, {0, 0, 1}, {0, 1, 0}}, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    FeatureTestMesh s;
    std::map<std::array<int, 3>, std::uint32_t> index;
    auto vertex = [&](const glm::ivec3& p) {
        const std::array<int, 3> key{p.x, p.y, p.z};
        auto [it, added] = index.emplace(key, static_cast<std::uint32_t>(s.positions.size()));
        if (added) s.positions.emplace_back(p.x, p.y, p.z);
        return it->second;
    };
    for (const Side& side : sides)
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                auto at = [&](int a, int b) { return vertex(side.origin * n + side.u * a + side.v * b); };
                const std::uint32_t p00 = at(i, j), p10 = at(i + 1, j), p11 = at(i + 1, j + 1), p01 = at(i, j + 1);
                s.triangles.push_back({p00, p10, p11});
                s.triangles.push_back({p00, p11, p01});
            }
    return s;
}

// Two cones of height 1 on a ring of m points of radius 1: the ring's edges turn by 90 degrees, the
// cones' own edges by 2 asin(sin(pi/m) / sqrt(2)) (under 11 degrees for m = 24).
FeatureTestMesh double_cone(int m) {
    FeatureTestMesh s;
    for (int i = 0; i < m; ++i) {
        const double angle = 2.0 * std::numbers::pi * i / m;
        s.positions.emplace_back(std::cos(angle), std::sin(angle), 0.0);
    }
    const auto top = static_cast<std::uint32_t>(m), bottom = static_cast<std::uint32_t>(m + 1);
    s.positions.emplace_back(0, 0, 1);
    s.positions.emplace_back(0, 0, -1);
    for (int i = 0; i < m; ++i) {
        const auto a = static_cast<std::uint32_t>(i), b = static_cast<std::uint32_t>((i + 1) % m);
        s.triangles.push_back({a, b, top});
        s.triangles.push_back({b, a, bottom});
    }
    return s;
}

// How many of the coordinates of p are 0 or n: 2 on a cube edge, 3 at a corner.
int extreme_coordinates(const glm::dvec3& p, int n) {
    int count = 0;
    for (int i = 0; i < 3; ++i) count += p[i] == 0.0 || p[i] == n;
    return count;
}

bool on_one_cube_edge(const glm::dvec3& a, const glm::dvec3& b, int n) {
    // Both on a cube edge and agreeing in the two coordinates that put them there.
    if (extreme_coordinates(a, n) < 2 || extreme_coordinates(b, n) < 2) return false;
    int shared = 0;
    for (int i = 0; i < 3; ++i) shared += a[i] == b[i] && (a[i] == 0.0 || a[i] == n);
    return shared == 2;
}

TEST(DenseFeatures, TheCubesEdgesAreItsFeaturesAndItsCornersTheAnchors) {
    const int n = 6;
    const FeatureTestMesh cube = tessellated_cube(n);
    const FeatureGraph features = rgbdetail::find_sharp_features(cube.positions, cube.triangles, 30.0, 0.0);
    std::set<std::array<std::uint32_t, 2>> expected;
    for (const Triangle& t : cube.triangles)
        for (int i = 0; i < 3; ++i) {
            const std::uint32_t a = t[i], b = t[(i + 1) % 3];
            if (on_one_cube_edge(cube.positions[a], cube.positions[b], n)) expected.insert({std::min(a, b), std::max(a, b)});
        }
    ASSERT_EQ(expected.size(), 12u * n);
    const std::set<std::array<std::uint32_t, 2>> found(features.edges().begin(), features.edges().end());
    EXPECT_EQ(found, expected);
    EXPECT_EQ(found.size(), features.edges().size());

    std::vector<std::uint32_t> corners;
    for (std::uint32_t v = 0; v < cube.positions.size(); ++v)
        if (extreme_coordinates(cube.positions[v], n) == 3) corners.push_back(v);
    EXPECT_EQ(rgbdetail::feature_anchors(features), corners);
    for (std::uint32_t v : corners) EXPECT_EQ(features.valence(v), 3u);
}

TEST(DenseFeatures, ShortFeaturesAreDropped) {
    const int n = 4;
    const FeatureTestMesh cube = tessellated_cube(n);
    // The twelve edges are one connected set of length 12 n.
    EXPECT_EQ(rgbdetail::find_sharp_features(cube.positions, cube.triangles, 30.0, 12.0 * n).edges().size(), 12u * n);
    EXPECT_TRUE(rgbdetail::find_sharp_features(cube.positions, cube.triangles, 30.0, 12.0 * n + 0.5).empty());
    // Above the cube's 90 degrees nothing is sharp.
    EXPECT_TRUE(rgbdetail::find_sharp_features(cube.positions, cube.triangles, 90.0, 0.0).empty());
}

TEST(DenseFeatures, AClosedRidgeKeepsThreeSpreadAnchors) {
    const int m = 24;
    const FeatureTestMesh cone = double_cone(m);
    const FeatureGraph features = rgbdetail::find_sharp_features(cone.positions, cone.triangles, 40.0, 0.0);
    ASSERT_EQ(features.edges().size(), static_cast<std::size_t>(m));
    for (const auto& [a, b] : features.edges()) {
        EXPECT_LT(b, static_cast<std::uint32_t>(m));
        EXPECT_TRUE((b - a) == 1 || (a == 0 && b == static_cast<std::uint32_t>(m - 1)));
    }
    const std::vector<std::uint32_t> anchors = rgbdetail::feature_anchors(features);
    ASSERT_EQ(anchors.size(), 3u);
    // Along the ring, every two anchors at least a third of it apart (rounded down).
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = i + 1; j < 3; ++j) {
            const int gap = std::abs(static_cast<int>(anchors[i]) - static_cast<int>(anchors[j]));
            EXPECT_GE(std::min(gap, m - gap), m / 3) << anchors[i] << " " << anchors[j];
        }
}

TEST(DenseFeatures, ChainsRunBetweenKeptVerticesAlongTheFeature) {
    const int n = 5;
    const FeatureTestMesh cube = tessellated_cube(n);
    const FeatureGraph features = rgbdetail::find_sharp_features(cube.positions, cube.triangles, 30.0, 0.0);
    const std::vector<std::uint32_t> corners = rgbdetail::feature_anchors(features);
    std::vector<std::uint8_t> kept(cube.positions.size(), 0);
    for (std::uint32_t v : corners) kept[v] = 1;
    int joined = 0;
    for (std::uint32_t a : corners)
        for (std::uint32_t b : corners) {
            if (a == b) continue;
            const std::vector<std::uint32_t> chain = rgbdetail::feature_chain(features, a, b, kept);
            const glm::dvec3 pa = cube.positions[a], pb = cube.positions[b];
            if (glm::distance(pa, pb) != n) {
                EXPECT_TRUE(chain.empty());  // a face or space diagonal: no cube edge joins them
                continue;
            }
            ++joined;
            ASSERT_EQ(chain.size(), static_cast<std::size_t>(n + 1));
            for (std::size_t i = 0; i < chain.size(); ++i)  // in order from a to b, one unit a step
                EXPECT_EQ(cube.positions[chain[i]], pa + (pb - pa) * (double(i) / n));
            // The nearest point of the chain: the projection onto the segment, clamped to it.
            const glm::dvec3 p = pa + (pb - pa) * 0.3 + glm::dvec3(0.25, -0.5, 0.75);
            const glm::dvec3 d = (pb - pa) / double(n);
            const double t = std::clamp(glm::dot(p - pa, d) / double(n), 0.0, 1.0);
            const glm::dvec3 nearest = rgbdetail::nearest_on_chain(cube.positions, chain, p);
            EXPECT_NEAR(glm::distance(nearest, pa + (pb - pa) * t), 0.0, 1e-12);
        }
    EXPECT_EQ(joined, 24);  // twelve edges, each from both ends
    // A kept vertex in the middle of an edge ends the chain there.
    const std::uint32_t a = corners[0];
    const std::uint32_t middle = rgbdetail::feature_chain(features, a, features.neighbours(a)[0], kept)[1];
    kept[middle] = 1;
    for (std::uint32_t b : corners) {
        const std::vector<std::uint32_t> chain = rgbdetail::feature_chain(features, a, b, kept);
        EXPECT_TRUE(std::find(chain.begin(), chain.end(), middle) == chain.end());
    }
}

// The cage keeps the features (cage.h): each of its feature edges stands for a chain of M's
// between the two M vertices it joins, and the chains cover M's features, each edge once.
TEST(DenseFeatures, TheCageKeepsEveryChain) {
    const int n = 12;
    const FeatureTestMesh cube = tessellated_cube(n);
    const FeatureGraph features = rgbdetail::find_sharp_features(cube.positions, cube.triangles, 30.0, 0.0);
    rgbdetail::CageOptions options;
    options.features = &features;
    const rgbdetail::Cage cage = rgbdetail::make_cage(cube.positions, cube.triangles, 100, options);
    ASSERT_LE(cage.triangles.size(), 100u);
    std::vector<std::uint8_t> kept(cube.positions.size(), 0);
    for (std::uint32_t v : cage.source_vertex) kept[v] = 1;
    for (std::uint32_t v = 0; v < cube.positions.size(); ++v) {
        if (extreme_coordinates(cube.positions[v], n) != 3) continue;
        EXPECT_TRUE(kept[v]) << "corner " << v;
    }
    std::multiset<std::array<std::uint32_t, 2>> covered;
    for (const auto& [a, b] : cage.feature_edges) {
        const std::vector<std::uint32_t> chain =
            rgbdetail::feature_chain(features, cage.source_vertex[a], cage.source_vertex[b], kept);
        ASSERT_FALSE(chain.empty()) << "cage edge " << a << "-" << b << " follows no chain";
        for (std::size_t i = 0; i + 1 < chain.size(); ++i)
            covered.insert({std::min(chain[i], chain[i + 1]), std::max(chain[i], chain[i + 1])});
    }
    const std::multiset<std::array<std::uint32_t, 2>> all(features.edges().begin(), features.edges().end());
    EXPECT_EQ(covered, all);
    // Without the features the decimation is free to cut across the cube's edges.
    const rgbdetail::Cage free_cage = rgbdetail::make_cage(cube.positions, cube.triangles, 100);
    EXPECT_TRUE(free_cage.feature_edges.empty());

    // The detail of every point of the cage's feature edges lies on a cube edge (two coordinates at
    // 0 or n), of its vertices on a corner or a cube edge; points inside faces are left to rays.
    const rgbdetail::FeatureDetail detail(features, cube.positions, cage.source_vertex, cage.feature_edges);
    const rgb::BaseMesh base(cage.positions, cage.triangles);
    const int level = 3;
    const std::uint32_t side = 1u << level;
    std::size_t on_features = 0;
    for (std::uint32_t f = 0; f < base.num_faces(); ++f)
        for (std::uint32_t a1 = 0; a1 <= side; ++a1)
            for (std::uint32_t a2 = 0; a1 + a2 <= side; ++a2) {
                const rgb::SurfacePoint p = rgb::reduced({f, {side - a1 - a2, a1, a2}, level});
                const glm::dvec3 limit = rgb::base_space_position(base, p) + glm::dvec3(0.1, -0.2, 0.05);
                const std::optional<glm::dvec3> q = detail.position(base, p, limit);
                const bool inside = p.a[0] != 0 && p.a[1] != 0 && p.a[2] != 0;
                if (inside) {
                    EXPECT_FALSE(q.has_value());
                    continue;
                }
                if (!q) continue;
                ++on_features;
                int extremes = 0;
                for (int i = 0; i < 3; ++i) extremes += std::abs((*q)[i]) < 1e-12 || std::abs((*q)[i] - n) < 1e-12;
                EXPECT_GE(extremes, 2) << (*q).x << " " << (*q).y << " " << (*q).z;
            }
    EXPECT_GT(on_features, 0u);
}

// A chain vertex whose two chain neighbours share a face with it (a feature ear) goes like any other
// chain vertex: its collapse along the chain merges its other chain edge into the face's third edge,
// which then carries the chain. Refused, it could never go, and on the ridged torus of the
// lod_quality benchmark such vertices stayed next to the ridge crossings in sliver faces, across which
// neighbouring detail points lay a cage edge apart (docs/benchmarks.md).
TEST(DenseFeatures, AChainVertexWhoseNeighboursShareAFaceWithItCanGo) {
    const int n = 12;
    const FeatureTestMesh cube = tessellated_cube(n);
    // A triangle in the middle of the top side: its edges p00-p10 and p10-p11 are the chain, p00 and
    // p11 its ends (kept), p10 the ear.
    const Triangle ear = cube.triangles[2 * static_cast<std::size_t>(n * n + (n / 2) * n + n / 2)];
    const std::uint32_t p00 = ear[0], p10 = ear[1], p11 = ear[2];
    ASSERT_EQ(cube.positions[p00].z, n);
    ASSERT_EQ(cube.positions[p10].z, n);
    const FeatureGraph features(cube.positions.size(), {{std::min(p00, p10), std::max(p00, p10)}, {std::min(p10, p11), std::max(p10, p11)}});
    rgbdetail::CageOptions options;
    options.features = &features;
    const rgbdetail::Cage cage = rgbdetail::make_cage(cube.positions, cube.triangles, 100, options);
    ASSERT_LE(cage.triangles.size(), 100u);
    std::vector<std::uint32_t> cage_vertex(cube.positions.size(), UINT32_MAX);
    for (std::uint32_t v = 0; v < cage.source_vertex.size(); ++v) cage_vertex[cage.source_vertex[v]] = v;
    EXPECT_EQ(cage_vertex[p10], UINT32_MAX) << "the ear stayed";
    ASSERT_NE(cage_vertex[p00], UINT32_MAX);
    ASSERT_NE(cage_vertex[p11], UINT32_MAX);
    const std::uint32_t a = cage_vertex[p00], b = cage_vertex[p11];
    EXPECT_EQ(cage.feature_edges, (std::vector<std::array<std::uint32_t, 2>>{{std::min(a, b), std::max(a, b)}}));
    // That edge follows the chain p00-p10-p11 of M.
    const rgbdetail::FeatureDetail detail(features, cube.positions, cage.source_vertex, cage.feature_edges);
    std::vector<std::uint8_t> kept(cube.positions.size(), 0);
    for (std::uint32_t v : cage.source_vertex) kept[v] = 1;
    EXPECT_EQ(rgbdetail::feature_chain(features, p00, p11, kept), (std::vector<std::uint32_t>{p00, p10, p11}));
}

}  // namespace
