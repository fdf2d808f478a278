#include "app/surface_picking.h"

#include <glm/geometric.hpp>

namespace app {

std::optional<double> front_hit(const Ray& ray, const std::array<glm::dvec3, 3>& t) {
    const glm::dvec3 e1 = t[1] - t[0];
    const glm::dvec3 e2 = t[2] - t[0];
    const glm::dvec3 p = glm::cross(ray.direction, e2);
    const double det = glm::dot(e1, p);
    if (det <= 0.0) return std::nullopt;  // back facing or parallel
    const glm::dvec3 s = ray.origin - t[0];
    const double u = glm::dot(s, p) / det;
    if (u < 0.0 || u > 1.0) return std::nullopt;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(ray.direction, q) / det;
    if (v < 0.0 || u + v > 1.0) return std::nullopt;
    const double distance = glm::dot(e2, q) / det;
    if (distance <= 0.0) return std::nullopt;
    return distance;
}

}  // namespace app
