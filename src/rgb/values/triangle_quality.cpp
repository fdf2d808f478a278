#include "rgb/values/triangle_quality.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <glm/geometric.hpp>

#include "rgb/mesh/mesh.h"
#include "rgb/values/loop_geometry.h"

namespace rgb {

namespace {

// The angle at p between the edges to q and r, in degrees; atan2 of the cross and dot products keeps
// small angles accurate where acos of a cosine near 1 would not.
double corner_angle(const glm::dvec3& p, const glm::dvec3& q, const glm::dvec3& r) {
    const glm::dvec3 u = q - p, v = r - p;
    return std::atan2(glm::length(glm::cross(u, v)), glm::dot(u, v)) * 180.0 / std::numbers::pi;
}

}  // namespace

TriangleQuality triangle_quality(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const double ab = glm::distance(a, b), bc = glm::distance(b, c), ca = glm::distance(c, a);
    const double area = 0.5 * glm::length(glm::cross(b - a, c - a));
    TriangleQuality q;
    q.min_angle = ab == 0.0 || bc == 0.0 || ca == 0.0
                      ? 0.0
                      : std::min({corner_angle(a, b, c), corner_angle(b, c, a), corner_angle(c, a, b)});
    q.aspect_ratio = area > 0.0 ? std::max({ab, bc, ca}) * (ab + bc + ca) / (4.0 * std::sqrt(3.0) * area)
                                : std::numeric_limits<double>::infinity();
    return q;
}

std::map<int, QualitySummary> quality_by_level(const Mesh& mesh) {
    std::vector<glm::dvec3> position(mesh.vertex_capacity());
    for (VertexId v : mesh.vertices()) position[v.idx] = displayed_position(mesh, v);
    std::map<int, QualitySummary> out;
    for (FaceId f : mesh.faces()) {
        const auto& v = mesh.face_vertices(f);
        const TriangleQuality q = triangle_quality(position[v[0].idx], position[v[1].idx], position[v[2].idx]);
        QualitySummary& s = out[mesh.level(f)];
        ++s.triangles;
        s.min_angle = std::min(s.min_angle, q.min_angle);
        s.mean_min_angle += q.min_angle;
        s.max_aspect_ratio = std::max(s.max_aspect_ratio, q.aspect_ratio);
    }
    for (auto& [level, s] : out) s.mean_min_angle /= static_cast<double>(s.triangles);
    return out;
}

}  // namespace rgb
