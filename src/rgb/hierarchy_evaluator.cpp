#include "rgb/hierarchy_evaluator.h"

#include <vector>

#include "rgb/base_mesh.h"
#include "rgb/loop_rules.h"

namespace rgb {

HierarchyEvaluator::Key HierarchyEvaluator::key(const SurfacePoint& p) const {
    const SurfacePoint c = canonical(base_, p);
    return {c.face, c.a[0], c.a[1], c.level};
}

double HierarchyEvaluator::gamma(const SurfacePoint& p) const {
    if (const auto v = base_vertex(base_, p)) return loop_gamma(base_.valence(*v), base_.is_boundary_vertex(*v));
    return loop_gamma(6, is_boundary(base_, p));
}

glm::dvec3 HierarchyEvaluator::insertion_position(const SurfacePoint& p) {
    if (const auto v = base_vertex(base_, p)) return base_.position(*v);
    const Key k = key(p);
    if (const auto it = insertion_.find(k); it != insertion_.end()) return it->second;
    const PointStencil s = parent_stencil(base_, p);
    const int l = p.level - 1;
    const glm::dvec3 a = control_point(s.ends[0], l), b = control_point(s.ends[1], l);
    const glm::dvec3 value = s.boundary
                                 ? boundary_edge_point(a, b)
                                 : interior_edge_point(a, b, control_point(s.opposite[0], l), control_point(s.opposite[1], l));
    insertion_.emplace(k, value);
    return value;
}

glm::dvec3 HierarchyEvaluator::limit_position(const SurfacePoint& p) {
    const Key k = key(p);
    if (const auto it = limit_.find(k); it != limit_.end()) return it->second;
    const glm::dvec3 centre = insertion_position(p);
    glm::dvec3 value;
    if (const auto v = base_vertex(base_, p)) {
        const std::vector<std::uint32_t> ring = base_.ring(*v);
        if (base_.is_boundary_vertex(*v)) {
            value = boundary_limit(centre, base_.position(ring.front()), base_.position(ring.back()));
        } else {
            std::vector<glm::dvec3> points;
            points.reserve(ring.size());
            for (std::uint32_t u : ring) points.push_back(base_.position(u));
            value = interior_limit(centre, points);
        }
    } else {
        const auto ring = ring_at_own_level(base_, p);
        if (is_boundary(base_, p)) {
            value = boundary_limit(centre, control_point(ring[0], p.level), control_point(ring[1], p.level));
        } else {
            std::array<glm::dvec3, 6> points;
            for (std::size_t i = 0; i < 6; ++i) points[i] = control_point(ring[i], p.level);
            value = interior_limit(centre, points);
        }
    }
    limit_.emplace(k, value);
    return value;
}

glm::dvec3 HierarchyEvaluator::control_point(const SurfacePoint& p, int k) {
    const glm::dvec3 own = insertion_position(p);
    if (k <= p.level) return own;
    return closed_form(own, limit_position(p), gamma(p), k - p.level);
}

}  // namespace rgb
