#pragma once
// Small geometric predicates on triangles in base space, written so that the answer does not depend
// on the order in which a triangle's corners are given (a canonical request must not change with the
// input's corner rotation, spec §3.5).
#include <array>

#include <glm/vec3.hpp>

namespace rgb {

// Distance from p to the triangle (a, b, c) (closest point by Voronoi regions).
double distance_to_triangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

// Whether the closed triangle meets the closed ball; the corners are put in lexicographic order
// first, so any rotation or reflection of the same corners gives the same answer.
bool triangle_meets_sphere(std::array<glm::dvec3, 3> corners, const glm::dvec3& centre, double radius);

// Whether the ball contains the whole triangle.
bool sphere_contains_triangle(const std::array<glm::dvec3, 3>& corners, const glm::dvec3& centre, double radius);

}  // namespace rgb
