#include "io/polygon_triangulation.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

namespace rgbio {

namespace {

// Newell's method: robust normal of a possibly non-planar polygon, length = twice the area.
glm::dvec3 newell_normal(std::span<const glm::dvec3> positions, std::span<const std::uint32_t> polygon) {
    glm::dvec3 n(0.0);
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const glm::dvec3& a = positions[polygon[i]];
        const glm::dvec3& b = positions[polygon[(i + 1) % polygon.size()]];
        n += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    }
    return n;
}

double cross2(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

bool strictly_inside(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
    return cross2(a, b, p) > 0 && cross2(b, c, p) > 0 && cross2(c, a, p) > 0;
}

}  // namespace

std::vector<std::array<std::uint32_t, 3>> triangulate_polygon(std::span<const glm::dvec3> positions,
                                                              std::span<const std::uint32_t> polygon) {
    std::vector<std::array<std::uint32_t, 3>> triangles;
    const std::size_t n = polygon.size();
    triangles.reserve(n - 2);

    // Project into the best-fit plane so that the polygon winds counter-clockwise in 2D.
    glm::dvec3 normal = newell_normal(positions, polygon);
    const double length = glm::length(normal);
    normal = length > 0 ? normal / length : glm::dvec3(0, 0, 1);
    const glm::dvec3 helper = std::abs(normal.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 u = glm::normalize(glm::cross(helper, normal));
    const glm::dvec3 v = glm::cross(normal, u);
    std::vector<glm::dvec2> projected(n);
    for (std::size_t i = 0; i < n; ++i)
        projected[i] = glm::dvec2(glm::dot(positions[polygon[i]], u), glm::dot(positions[polygon[i]], v));

    std::vector<std::size_t> remaining(n);
    for (std::size_t i = 0; i < n; ++i) remaining[i] = i;

    auto is_ear = [&](std::size_t k) {
        const std::size_t m = remaining.size();
        const glm::dvec2& a = projected[remaining[(k + m - 1) % m]];
        const glm::dvec2& b = projected[remaining[k]];
        const glm::dvec2& c = projected[remaining[(k + 1) % m]];
        if (cross2(a, b, c) <= 0) return false;
        for (std::size_t j = 0; j < m; ++j) {
            if (j == k || j == (k + m - 1) % m || j == (k + 1) % m) continue;
            if (strictly_inside(projected[remaining[j]], a, b, c)) return false;
        }
        return true;
    };
    auto convexity = [&](std::size_t k) {
        const std::size_t m = remaining.size();
        return cross2(projected[remaining[(k + m - 1) % m]], projected[remaining[k]], projected[remaining[(k + 1) % m]]);
    };

    while (remaining.size() > 3) {
        const std::size_t m = remaining.size();
        std::size_t clip = m;
        for (std::size_t k = 0; k < m && clip == m; ++k)
            if (is_ear(k)) clip = k;
        if (clip == m) {  // no true ear: degenerate or self-intersecting input
            clip = 0;
            for (std::size_t k = 1; k < m; ++k)
                if (convexity(k) > convexity(clip)) clip = k;
        }
        triangles.push_back({polygon[remaining[(clip + m - 1) % m]], polygon[remaining[clip]], polygon[remaining[(clip + 1) % m]]});
        remaining.erase(remaining.begin() + static_cast<std::ptrdiff_t>(clip));
    }
    triangles.push_back({polygon[remaining[0]], polygon[remaining[1]], polygon[remaining[2]]});
    return triangles;
}

}  // namespace rgbio
