#include "rgb/loop_geometry.h"

#include <algorithm>
#include <array>
#include <vector>

#include "rgb/hierarchy_evaluator.h"
#include "rgb/loop_rules.h"
#include "rgb/mesh.h"
#include "rgb/navigation.h"

namespace rgb {

namespace {

// The limit from v's ring in the current mesh, if the mesh holds that ring.
std::optional<glm::dvec3> limit_from_ring(const Mesh& mesh, VertexId v) {
    const std::vector<VertexId> ring = uniform_ring(mesh, v);
    if (ring.empty()) return std::nullopt;
    const int l = mesh.level(v);
    const glm::dvec3& centre = mesh.insertion_position(v);
    if (mesh.is_boundary(v)) return boundary_limit(centre, control_point(mesh, ring[0], l), control_point(mesh, ring[1], l));
    std::vector<glm::dvec3> points;
    points.reserve(ring.size());
    for (VertexId w : ring) points.push_back(control_point(mesh, w, l));
    return interior_limit(centre, points);
}

}  // namespace

glm::dvec3 limit_position(const Mesh& mesh, VertexId v) {
    if (auto known = mesh.cached_limit(v)) return *known;
    std::optional<glm::dvec3> limit = limit_from_ring(mesh, v);
    if (!limit) limit = HierarchyEvaluator(mesh.base()).limit_position(mesh.address(v));
    mesh.cache_limit(v, *limit);
    return *limit;
}

glm::dvec3 control_point(const Mesh& mesh, VertexId v, int k) {
    const int l = mesh.level(v);
    if (k <= l) return mesh.insertion_position(v);
    return closed_form(mesh.insertion_position(v), limit_position(mesh, v),
                       loop_gamma(mesh.uniform_valence(v), mesh.is_boundary(v)), k - l);
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

glm::dvec3 displayed_position(const Mesh& mesh, VertexId v) { return control_point(mesh, v, display_level(mesh, v)); }

}  // namespace rgb
