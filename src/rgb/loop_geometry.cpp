#include "rgb/loop_geometry.h"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include "rgb/loop_rules.h"
#include "rgb/mesh.h"
#include "rgb/navigation.h"

namespace rgb {

namespace {

double vertex_gamma(const Mesh& mesh, VertexId v) {
    return loop_gamma(mesh.uniform_valence(v), mesh.is_boundary(v));
}

bool lexicographic_less(const glm::dvec3& a, const glm::dvec3& b) {
    if (a.x != b.x) return a.x < b.x;
    if (a.y != b.y) return a.y < b.y;
    return a.z < b.z;
}

}  // namespace

glm::dvec3 control_point(const Mesh& mesh, VertexId v, int k) {
    const int l = mesh.level(v);
    if (k <= l) return mesh.insertion_position(v);
    const auto limit = mesh.limit_position(v);
    if (!limit)
        throw std::logic_error("control point of vertex " + std::to_string(v.idx) + " at level " + std::to_string(k) +
                               " needs its limit position, which is not known");
    const double gamma = vertex_gamma(mesh, v);
    double g = 1.0;
    for (int j = l; j < k; ++j) g *= gamma;
    return g * mesh.insertion_position(v) + (1.0 - g) * *limit;
}

int display_level(const Mesh& mesh, VertexId v) {
    int lowest = 255;
    const HalfedgeId start = mesh.vertex_halfedge(v);
    HalfedgeId h = start;
    do {
        lowest = std::min({lowest, mesh.edge_type(h).level, mesh.edge_type(Mesh::prev(h)).level});
        h = mesh.ccw_rotated(h);
    } while (h.valid() && h != start);
    return std::max(mesh.level(v), lowest);
}

glm::dvec3 displayed_position(const Mesh& mesh, VertexId v) {
    const int k = display_level(mesh, v);
    if (k > mesh.level(v)) try_limit_position(mesh, v);
    return control_point(mesh, v, k);
}

std::optional<glm::dvec3> try_limit_position(const Mesh& mesh, VertexId v) {
    if (auto known = mesh.limit_position(v)) return known;
    const std::vector<VertexId> ring = uniform_ring(mesh, v);
    if (ring.empty()) return std::nullopt;
    const int l = mesh.level(v);
    for (VertexId w : ring)
        if (mesh.level(w) < l && !try_limit_position(mesh, w)) return std::nullopt;

    const glm::dvec3 centre = mesh.insertion_position(v);
    glm::dvec3 limit;
    if (mesh.is_boundary(v)) {
        limit = (2.0 / 3.0) * centre + (1.0 / 6.0) * (control_point(mesh, ring[0], l) + control_point(mesh, ring[1], l));
    } else {
        // Summed in a canonical order so the result is bit-identical whatever order the mesh was
        // built in (the ring is found starting from an arbitrary edge).
        std::vector<glm::dvec3> points;
        points.reserve(ring.size());
        for (VertexId w : ring) points.push_back(control_point(mesh, w, l));
        std::sort(points.begin(), points.end(), lexicographic_less);
        glm::dvec3 sum(0.0);
        for (const glm::dvec3& p : points) sum += p;
        const int n = static_cast<int>(ring.size());
        const double c = loop_limit_ring_weight(n);
        limit = (1.0 - c) * centre + (c / n) * sum;
    }
    mesh.set_limit_position(v, limit);
    return limit;
}

}  // namespace rgb
