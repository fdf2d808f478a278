// A view-dependent dab whose centre lies on a vertex that several facing base faces share, with faces
// turned away between them (a silhouette vertex): every facing face is at distance 0, so the tie
// decides which faces are reached. It must go by the faces' corner positions (dab.cpp), never by
// their order in the input.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "rgb/lod/dab.h"
#include "rgb/mesh/mesh.h"

namespace rgbtest {
namespace {

using Corners = std::array<glm::dvec3, 3>;

bool corners_before(const Corners& x, const Corners& y) {
    auto less = [](const glm::dvec3& p, const glm::dvec3& q) { return std::tie(p.x, p.y, p.z) < std::tie(q.x, q.y, q.z); };
    return std::lexicographical_compare(x.begin(), x.end(), y.begin(), y.end(), less);
}

Corners sorted_corners(const std::vector<glm::dvec3>& positions, const rgb::Triangle& t) {
    Corners c{positions[t[0]], positions[t[1]], positions[t[2]]};
    std::sort(c.begin(), c.end(), [](const glm::dvec3& p, const glm::dvec3& q) { return std::tie(p.x, p.y, p.z) < std::tie(q.x, q.y, q.z); });
    return c;
}

TEST(DabTies, AHitOnASharedVertexGoesByCornerPositionsNotFaceOrder) {
    // A pleated fan around the origin: seen from +z its ring turns +150 and -30 degrees in turn, so
    // faces 0, 2 and 4 face a camera looking down -z and faces 1, 3 and 5 are turned away. No two
    // facing faces share an edge: the dab reaches the hit face alone.
    const std::array<double, 6> degrees{0, 150, 120, 270, 240, 30};
    std::vector<glm::dvec3> positions{{0, 0, 0}};
    for (std::size_t i = 0; i < degrees.size(); ++i) {
        const double a = degrees[i] * std::numbers::pi / 180.0;
        positions.push_back({std::cos(a), std::sin(a), 0.2 * double(i % 3) - 0.1});
    }
    std::vector<rgb::Triangle> triangles;
    for (std::uint32_t i = 0; i < 6; ++i) triangles.push_back({0, 1 + i, 1 + (i + 1) % 6});
    const glm::dvec3 view(0, 0, -1);

    // Expected, computed here: of the faces whose plain normal faces the camera, the least corners.
    std::optional<Corners> expected;
    for (const rgb::Triangle& t : triangles) {
        const glm::dvec3 n = glm::cross(positions[t[1]] - positions[t[0]], positions[t[2]] - positions[t[0]]);
        if (glm::dot(n, view) >= 0.0) continue;
        const Corners c = sorted_corners(positions, t);
        if (!expected || corners_before(c, *expected)) expected = c;
    }
    ASSERT_TRUE(expected.has_value());

    for (std::size_t shift = 0; shift < triangles.size(); ++shift) {
        std::vector<rgb::Triangle> stored = triangles;
        std::rotate(stored.begin(), stored.begin() + static_cast<std::ptrdiff_t>(shift), stored.end());
        const rgb::Mesh mesh(positions, stored);
        const std::vector<std::uint32_t> reached = rgb::facing_base_faces(mesh, rgb::Sphere{{0, 0, 0}, 0.3}, view);
        ASSERT_EQ(reached.size(), 1u) << "face order shifted by " << shift;
        EXPECT_EQ(sorted_corners(positions, stored[reached.front()]), *expected) << "face order shifted by " << shift;
    }
}

}  // namespace
}  // namespace rgbtest
