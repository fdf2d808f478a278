#include "test_meshes.h"

#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

namespace render_test {

rgb::Mesh icosphere(int subdivisions, double scale) {
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    std::vector<glm::dvec3> points{{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                                   {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    std::vector<rgb::Triangle> triangles{{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                         {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                         {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                         {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (glm::dvec3& p : points) p = glm::normalize(p);
    for (int s = 0; s < subdivisions; ++s) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
        auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
            const auto key = std::minmax(a, b);
            auto [it, inserted] = midpoints.try_emplace(key, static_cast<std::uint32_t>(points.size()));
            if (inserted) points.push_back(glm::normalize(points[a] + points[b]));
            return it->second;
        };
        std::vector<rgb::Triangle> finer;
        for (const rgb::Triangle& tri : triangles) {
            const std::uint32_t ab = midpoint(tri[0], tri[1]), bc = midpoint(tri[1], tri[2]), ca = midpoint(tri[2], tri[0]);
            finer.push_back({tri[0], ab, ca});
            finer.push_back({tri[1], bc, ab});
            finer.push_back({tri[2], ca, bc});
            finer.push_back({ab, bc, ca});
        }
        triangles = std::move(finer);
    }
    for (glm::dvec3& p : points) p *= scale;
    return rgb::Mesh(points, triangles);
}

rgb::Mesh grid(int n) {
    std::vector<glm::dvec3> points;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
            points.emplace_back(-1.0 + 2.0 * i / n, 0.0, -1.0 + 2.0 * j / n);
    std::vector<rgb::Triangle> triangles;
    const auto id = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            // Counter-clockwise seen from +y: x to the right, z towards the viewer.
            triangles.push_back({id(i, j), id(i, j + 1), id(i + 1, j + 1)});
            triangles.push_back({id(i, j), id(i + 1, j + 1), id(i + 1, j)});
        }
    return rgb::Mesh(points, triangles);
}

}  // namespace render_test
