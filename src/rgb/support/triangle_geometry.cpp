#include "rgb/support/triangle_geometry.h"

#include <algorithm>

#include <glm/geometric.hpp>

namespace rgb {

double distance_to_triangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    // Ericson, Real-Time Collision Detection §5.1.5.
    const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return glm::distance(p, a);
    const glm::dvec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return glm::distance(p, b);
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return glm::distance(p, a + ab * (d1 / (d1 - d3)));
    const glm::dvec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return glm::distance(p, c);
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return glm::distance(p, a + ac * (d2 / (d2 - d6)));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
        return glm::distance(p, b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))));
    const double denom = 1.0 / (va + vb + vc);
    return glm::distance(p, a + ab * (vb * denom) + ac * (vc * denom));
}

bool triangle_meets_sphere(std::array<glm::dvec3, 3> corners, const glm::dvec3& centre, double radius) {
    std::sort(corners.begin(), corners.end(), [](const glm::dvec3& x, const glm::dvec3& y) {
        if (x.x != y.x) return x.x < y.x;
        if (x.y != y.y) return x.y < y.y;
        return x.z < y.z;
    });
    return distance_to_triangle(centre, corners[0], corners[1], corners[2]) <= radius;
}

bool sphere_contains_triangle(const std::array<glm::dvec3, 3>& corners, const glm::dvec3& centre, double radius) {
    const double r2 = radius * radius;
    return std::all_of(corners.begin(), corners.end(), [&](const glm::dvec3& p) {
        const glm::dvec3 d = p - centre;
        return glm::dot(d, d) <= r2;
    });
}

}  // namespace rgb
