#include "small_meshes.h"

#include <vector>

namespace app::test {

rgb::Mesh tetrahedron() {
    const std::vector<glm::dvec3> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const std::vector<rgb::Triangle> t{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return rgb::Mesh(p, t);
}

rgb::Mesh stacked_sheets(int n, double gap) {
    std::vector<glm::dvec3> points;
    std::vector<rgb::Triangle> triangles;
    for (const double y : {0.0, gap}) {
        const auto first = static_cast<std::uint32_t>(points.size());
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) points.emplace_back(-1.0 + 2.0 * i / n, y, -1.0 + 2.0 * j / n);
        const auto id = [&](int i, int j) { return first + static_cast<std::uint32_t>(j * (n + 1) + i); };
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                // Counter-clockwise seen from +y: x to the right, z towards the viewer.
                triangles.push_back({id(i, j), id(i, j + 1), id(i + 1, j + 1)});
                triangles.push_back({id(i, j), id(i + 1, j + 1), id(i + 1, j)});
            }
    }
    return rgb::Mesh(points, triangles);
}

}  // namespace app::test
