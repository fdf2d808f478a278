#include "small_meshes.h"

#include <cmath>
#include <fstream>
#include <numbers>
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

std::string write_torus(const std::filesystem::path& folder, int n, int m) {
    const std::filesystem::path path = folder / ("torus_" + std::to_string(2 * n * m) + ".obj");
    std::ofstream out(path);
    constexpr double kTau = 2.0 * std::numbers::pi;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < m; ++j) {
            const double u = kTau * i / n, v = kTau * j / m;
            // Bumps, so there is detail for a cage to keep.
            const double r = 0.3 + 0.01 * std::sin(7.0 * u) * std::sin(5.0 * v);
            out << "v " << (1.0 + r * std::cos(v)) * std::cos(u) << ' ' << (1.0 + r * std::cos(v)) * std::sin(u) << ' ' << r * std::sin(v)
                << '\n';
        }
    const auto id = [&](int i, int j) { return ((i + n) % n) * m + (j + m) % m + 1; };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < m; ++j) {
            out << "f " << id(i, j) << ' ' << id(i + 1, j) << ' ' << id(i + 1, j + 1) << '\n';
            out << "f " << id(i, j) << ' ' << id(i + 1, j + 1) << ' ' << id(i, j + 1) << '\n';
        }
    return path.string();
}

}  // namespace app::test
