// Ear clipping keeps every triangle inside the polygon: no flips for concave input, areas add up.
#include <cmath>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "io/polygon_triangulation.h"

namespace rgbio {
namespace {

glm::dvec3 triangle_normal(const std::vector<glm::dvec3>& p, const std::array<std::uint32_t, 3>& t) {
    return glm::cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]);
}

// A star with `points` spikes in a tilted plane: strongly concave, counter-clockwise about `axis`.
std::vector<glm::dvec3> tilted_star(int points, glm::dvec3& axis) {
    const glm::dvec3 u = glm::normalize(glm::dvec3(1, 0.3, -0.2));
    const glm::dvec3 v = glm::normalize(glm::cross(glm::dvec3(0.1, 0.2, 1), u));
    axis = glm::cross(u, v);
    std::vector<glm::dvec3> p;
    for (int i = 0; i < 2 * points; ++i) {
        const double a = 3.141592653589793 * i / points;
        const double r = i % 2 ? 0.3 : 1.0;
        p.push_back(r * std::cos(a) * u + r * std::sin(a) * v + glm::dvec3(2, -1, 3));
    }
    return p;
}

TEST(PolygonTriangulation, ConcaveStarHasNoFlippedTrianglesAndKeepsItsArea) {
    glm::dvec3 axis;
    const std::vector<glm::dvec3> star = tilted_star(7, axis);
    std::vector<std::uint32_t> polygon(star.size());
    for (std::uint32_t i = 0; i < polygon.size(); ++i) polygon[i] = i;
    const auto triangles = triangulate_polygon(star, polygon);
    ASSERT_EQ(triangles.size(), star.size() - 2);
    double area = 0;
    for (const auto& t : triangles) {
        const glm::dvec3 n = triangle_normal(star, t);
        EXPECT_GT(glm::dot(n, axis), 0) << "flipped triangle " << t[0] << " " << t[1] << " " << t[2];
        area += 0.5 * glm::length(n);
    }
    // A star polygon is 2n triangles (centre, tip, notch) of area r1*r2*sin(pi/n)/2 each.
    const double expected = 2 * 7 * 0.5 * 1.0 * 0.3 * std::sin(3.141592653589793 / 7);
    EXPECT_NEAR(area, expected, 1e-12);
}

TEST(PolygonTriangulation, FanWouldFlipButEarClippingDoesNot) {
    // An arrow whose first vertex is reflex: a fan from it would produce an inverted triangle.
    const std::vector<glm::dvec3> arrow = {{1, 1, 0}, {0, 2, 0}, {0, 0, 0}, {3, 1, 0}, {0, 3, 0}};
    const std::vector<std::uint32_t> polygon = {2, 3, 4, 1, 0};
    for (const auto& t : triangulate_polygon(arrow, polygon)) EXPECT_GT(triangle_normal(arrow, t).z, 0);
}

TEST(PolygonTriangulation, DegenerateCollinearPolygonStillGivesAllTriangles) {
    const std::vector<glm::dvec3> line = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}};
    const std::vector<std::uint32_t> polygon = {0, 1, 2, 3, 4};
    EXPECT_EQ(triangulate_polygon(line, polygon).size(), 3u);
}

}  // namespace
}  // namespace rgbio
