#include "test_meshes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "rgb/mesh/detail_positions.h"
#include "rgb/mesh/face_location.h"

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

glm::dvec3 bumpy_sphere_point(const glm::dvec3& p) {
    const glm::dvec3 d = glm::normalize(p);
    return d * (1.0 + 0.04 * std::sin(6.0 * d.x + 1.0) * std::sin(5.0 * d.y + 2.0) * std::sin(4.0 * d.z + 3.0));
}

rgb::Mesh bumpy_cage(int subdivisions, int detail_level) {
    const rgb::Mesh sphere = icosphere(subdivisions);
    const rgb::BaseMesh& base = sphere.base();
    std::vector<glm::dvec3> positions;
    for (std::uint32_t v = 0; v < base.num_vertices(); ++v) positions.push_back(base.position(v));
    std::vector<rgb::Triangle> triangles;
    for (std::uint32_t f = 0; f < base.num_faces(); ++f) triangles.push_back(base.face(f));
    std::vector<glm::dvec3> values;
    for (const rgb::SurfacePoint& p : rgb::DetailPositions::grid_points(base, detail_level))
        values.push_back(bumpy_sphere_point(rgb::base_space_position(base, p)));
    auto detail = std::make_shared<const rgb::DetailPositions>(base, detail_level, values);
    return rgb::Mesh(std::make_shared<const rgb::BaseMesh>(positions, triangles, rgb::SharpFeatures{}, std::move(detail)));
}

double brute_force_detail_distance(const rgb::Mesh& mesh, rgb::FaceId f) {
    const rgb::BaseMesh& base = mesh.base();
    const rgb::DetailPositions& detail = *base.detail();
    std::array<glm::dvec3, 3> at, shown;  // f's corners in base space and as displayed
    for (int c = 0; c < 3; ++c) {
        const rgb::VertexId v = mesh.face_vertices(f)[c];
        at[c] = mesh.base_space_position(v);
        shown[c] = detail.position(base, mesh.address(v));
    }
    const glm::dvec3 normal = glm::cross(at[1] - at[0], at[2] - at[0]);
    const int level = mesh.level(f) + 2;
    const std::uint32_t n = 1u << level;
    double worst = 0.0;
    for (std::uint32_t a2 = 0; a2 <= n; ++a2)
        for (std::uint32_t a1 = 0; a1 + a2 <= n; ++a1) {
            const rgb::SurfacePoint p = rgb::reduced({rgb::base_face_of(mesh, f), {n - a1 - a2, a1, a2}, level});
            const glm::dvec3 q = rgb::base_space_position(base, p);
            std::array<double, 3> w{};
            for (int c = 0; c < 3; ++c)
                w[c] = glm::dot(glm::cross(at[(c + 2) % 3] - at[(c + 1) % 3], q - at[(c + 1) % 3]), normal) / glm::dot(normal, normal);
            if (w[0] < -1e-9 || w[1] < -1e-9 || w[2] < -1e-9) continue;
            const glm::dvec3 flat = w[0] * shown[0] + w[1] * shown[1] + w[2] * shown[2];
            worst = std::max(worst, glm::distance(flat, detail.position(base, p)));
        }
    return worst;
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
