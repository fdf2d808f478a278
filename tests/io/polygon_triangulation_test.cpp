// Ear clipping keeps every triangle inside the polygon: no flips for concave input, areas add up.
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <span>
#include <utility>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "io/repair/polygon_triangulation.h"
#include "polygon_shapes.h"

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

// Whatever the geometry, n - 2 triangles triangulate the polygon when they glue into a disc bounded
// by it: each polygon side is used once, in the polygon's direction, and every other edge (a
// diagonal) twice, once in each direction; no triangle repeats a vertex or leaves the polygon.
void expect_triangulates(std::span<const std::uint32_t> polygon, const std::vector<std::array<std::uint32_t, 3>>& triangles) {
    ASSERT_EQ(triangles.size(), polygon.size() - 2);
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    for (const auto& t : triangles) {
        EXPECT_TRUE(t[0] != t[1] && t[1] != t[2] && t[2] != t[0]) << t[0] << " " << t[1] << " " << t[2];
        for (int i = 0; i < 3; ++i) {
            EXPECT_NE(std::find(polygon.begin(), polygon.end(), t[i]), polygon.end()) << "vertex " << t[i];
            ++directed[{t[i], t[(i + 1) % 3]}];
        }
    }
    std::set<std::pair<std::uint32_t, std::uint32_t>> sides;
    for (std::size_t i = 0; i < polygon.size(); ++i) sides.insert({polygon[i], polygon[(i + 1) % polygon.size()]});
    for (const auto& [edge, count] : directed) {
        const std::pair<std::uint32_t, std::uint32_t> reverse{edge.second, edge.first};
        EXPECT_EQ(count, 1) << "edge " << edge.first << "->" << edge.second << " used twice in one direction";
        EXPECT_FALSE(sides.contains(reverse)) << "side " << reverse.first << "->" << reverse.second << " reversed";
        if (!sides.contains(edge)) {
            EXPECT_TRUE(directed.contains(reverse)) << "diagonal " << edge.first << "-" << edge.second << " used once";
        }
    }
    for (const auto& side : sides) EXPECT_TRUE(directed.contains(side)) << "side " << side.first << "->" << side.second << " missing";
}

TEST(PolygonTriangulation, DegenerateCollinearPolygonStillGivesAllTriangles) {
    const std::vector<glm::dvec3> line = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}};
    const std::vector<std::uint32_t> polygon = {0, 1, 2, 3, 4};
    expect_triangulates(polygon, triangulate_polygon(line, polygon));
    // The same points in another order along the line: the polygon folds back on itself.
    const std::vector<std::uint32_t> folded = {0, 3, 1, 4, 2};
    expect_triangulates(folded, triangulate_polygon(line, folded));
}

TEST(PolygonTriangulation, TriangulationsAreDiscsBoundedByThePolygon) {
    glm::dvec3 axis;
    const std::vector<glm::dvec3> star = tilted_star(7, axis);
    std::vector<std::uint32_t> polygon(star.size());
    for (std::uint32_t i = 0; i < polygon.size(); ++i) polygon[i] = i;
    expect_triangulates(polygon, triangulate_polygon(star, polygon));
    const std::vector<glm::dvec3> arrow = {{1, 1, 0}, {0, 2, 0}, {0, 0, 0}, {3, 1, 0}, {0, 3, 0}};
    const std::vector<std::uint32_t> arrow_polygon = {2, 3, 4, 1, 0};
    expect_triangulates(arrow_polygon, triangulate_polygon(arrow, arrow_polygon));
}

TEST(PolygonTriangulation, QuadIsCutAtItsFirstEarInCornerOrder) {
    const std::vector<glm::dvec3> square = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    const std::vector<std::uint32_t> quad = {0, 1, 2, 3};
    EXPECT_EQ(triangulate_polygon_corners(square, quad), (std::vector<std::array<std::uint32_t, 3>>{{3, 0, 1}, {1, 2, 3}}));
    // A dart whose corner 0 is reflex: corner 1 is the first ear.
    const std::vector<glm::dvec3> dart = {{0.5, 0.4, 0}, {0, 0, 0}, {0.5, 1, 0}, {1, 0, 0}};
    EXPECT_EQ(triangulate_polygon_corners(dart, quad), (std::vector<std::array<std::uint32_t, 3>>{{0, 1, 2}, {0, 2, 3}}));
}

// Every triangle turns the polygon's way and the areas add up to the polygon's.
void expect_full_triangulation(const std::vector<glm::dvec3>& p, double area, const glm::dvec3& axis) {
    std::vector<std::uint32_t> polygon(p.size());
    for (std::uint32_t i = 0; i < polygon.size(); ++i) polygon[i] = i;
    const auto triangles = triangulate_polygon(p, polygon);
    ASSERT_EQ(triangles.size(), p.size() - 2);
    double sum = 0;
    std::size_t flipped = 0;
    for (const auto& t : triangles) {
        const double signed_area = 0.5 * glm::dot(triangle_normal(p, t), axis);
        flipped += signed_area <= 0;
        sum += signed_area;
    }
    EXPECT_EQ(flipped, 0u);
    EXPECT_NEAR(sum, area, 1e-9 * area);
}

TEST(PolygonTriangulation, LargeConcavePolygonsAreTriangulatedCompletely) {
    glm::dvec3 axis;
    expect_full_triangulation(tilted_star(20000, axis), 2 * 20000 * 0.5 * 1.0 * 0.3 * std::sin(3.141592653589793 / 20000), axis);
    expect_full_triangulation(test::comb_polygon(5000), test::comb_area(5000), glm::dvec3(0, 0, -1));
    // A winding strip, its area by the shoelace formula.
    const std::vector<glm::dvec3> spiral = test::spiral_polygon(20000);
    double twice_area = 0;
    for (std::size_t i = 0; i < spiral.size(); ++i) {
        const glm::dvec3 &a = spiral[i], &b = spiral[(i + 1) % spiral.size()];
        twice_area += a.x * b.y - b.x * a.y;
    }
    expect_full_triangulation(spiral, std::abs(twice_area) / 2, glm::dvec3(0, 0, twice_area > 0 ? 1 : -1));
}

}  // namespace
}  // namespace rgbio
