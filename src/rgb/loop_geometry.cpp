#include "rgb/loop_geometry.h"

#include <algorithm>
#include <array>
#include <memory>
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

// One evaluator per thread and base mesh, kept between calls: neighbouring vertices share most of
// the hierarchy values they need. Its values are only a cache, so it starts afresh when it grows large.
HierarchyEvaluator& shared_evaluator(const BaseMesh& base) {
    constexpr std::size_t kMaxValues = std::size_t(1) << 18;
    thread_local std::unique_ptr<HierarchyEvaluator> evaluator;
    thread_local std::uint64_t serial = 0;
    if (!evaluator || serial != base.serial() || evaluator->cached_values() > kMaxValues) {
        evaluator = std::make_unique<HierarchyEvaluator>(base);
        serial = base.serial();
    }
    return *evaluator;
}

}  // namespace

glm::dvec3 limit_position_uncached(const Mesh& mesh, VertexId v) {
    if (auto known = mesh.cached_limit(v)) return *known;
    if (auto limit = limit_from_ring(mesh, v)) return *limit;
    return shared_evaluator(mesh.base()).limit_position(mesh.address(v));
}

glm::dvec3 limit_position(const Mesh& mesh, VertexId v) {
    if (auto known = mesh.cached_limit(v)) return *known;
    const glm::dvec3 limit = limit_position_uncached(mesh, v);
    mesh.cache_limit(v, limit);
    return limit;
}

void limit_position_where_uniform(const Mesh& mesh, VertexId v) {
    if (!mesh.cached_limit(v) && ring_is_direct(mesh, v)) limit_position(mesh, v);
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

glm::dvec3 displayed_position(const Mesh& mesh, VertexId v) {
    const int k = display_level(mesh, v), l = mesh.level(v);
    if (k <= l) return mesh.insertion_position(v);
    return closed_form(mesh.insertion_position(v), limit_position_uncached(mesh, v),
                       loop_gamma(mesh.uniform_valence(v), mesh.is_boundary(v)), k - l);
}

}  // namespace rgb
