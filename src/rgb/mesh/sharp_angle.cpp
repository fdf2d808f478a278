#include "rgb/mesh/sharp_angle.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace rgb {

namespace {

glm::dvec3 face_normal(const BaseMesh& base, std::uint32_t f) {
    const Triangle& t = base.face(f);
    return glm::cross(base.position(t[1]) - base.position(t[0]), base.position(t[2]) - base.position(t[0]));
}

}  // namespace

double dihedral_angle_degrees(const BaseMesh& base, std::uint32_t h) {
    const glm::dvec3 n = face_normal(base, h / 3), m = face_normal(base, base.opposite(h) / 3);
    if (glm::dot(n, n) == 0.0 || glm::dot(m, m) == 0.0) return 0.0;
    // atan2 of |n x m| and n . m stays accurate for nearly flat and nearly folded edges alike.
    return std::atan2(glm::length(glm::cross(n, m)), glm::dot(n, m)) * 180.0 / std::numbers::pi;
}

std::vector<EdgeSharpness> edges_sharper_than(const BaseMesh& base, double degrees) {
    std::vector<EdgeSharpness> edges;
    for (std::uint32_t h = 0; h < 3 * base.num_faces(); ++h) {
        const std::uint32_t o = base.opposite(h);
        if (o == BaseMesh::kNone || o < h || dihedral_angle_degrees(base, h) <= degrees) continue;
        const std::uint32_t a = base.face(h / 3)[h % 3], b = base.to_vertex(h);
        edges.push_back({std::min(a, b), std::max(a, b), kInfiniteSharpness});
    }
    std::sort(edges.begin(), edges.end(), [](const EdgeSharpness& x, const EdgeSharpness& y) {
        return x.a != y.a ? x.a < y.a : x.b < y.b;
    });
    return edges;
}

}  // namespace rgb
