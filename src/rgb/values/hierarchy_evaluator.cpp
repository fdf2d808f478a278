#include "rgb/values/hierarchy_evaluator.h"

#include <vector>

#include "rgb/mesh/base_mesh.h"
#include "rgb/rules/dart_masks.h"
#include "rgb/rules/loop_rules.h"

namespace rgb {

HierarchyEvaluator::Key HierarchyEvaluator::key(const SurfacePoint& p) const {
    const SurfacePoint c = canonical(base_, p);
    return {c.face, c.a[0], c.a[1], c.level, -1};
}

double HierarchyEvaluator::gamma(const SurfacePoint& p) const {
    if (const auto v = base_vertex(base_, p)) return loop_gamma(base_.valence(*v), base_.is_boundary_vertex(*v));
    return loop_gamma(6, is_boundary(base_, p));
}

glm::dvec3 HierarchyEvaluator::insertion_position(const SurfacePoint& p) {
    if (const auto v = base_vertex(base_, p)) return base_.position(*v);
    const Key k = key(p);
    if (const glm::dvec3* known = insertion_.find(k)) return *known;
    const PointStencil s = parent_stencil(base_, p);
    const int l = p.level - 1;
    const glm::dvec3 a = control_point(s.ends[0], l), b = control_point(s.ends[1], l);
    const bool midpoint = s.boundary || (base_.has_sharp_features() && inserted_at_midpoint(base_, p));
    const glm::dvec3 value = midpoint
                                 ? boundary_edge_point(a, b)
                                 : interior_edge_point(a, b, control_point(s.opposite[0], l), control_point(s.opposite[1], l));
    insertion_.insert(k, value);
    return value;
}

glm::dvec3 HierarchyEvaluator::limit_position(const SurfacePoint& p) {
    const Key k = key(p);
    if (const glm::dvec3* known = limit_.find(k)) return *known;
    const glm::dvec3 centre = insertion_position(p);
    glm::dvec3 value;
    if (!follows_untagged_rules(base_, p)) {
        // The limit of the last regime, the one that lasts for ever.
        const Regimes regimes = vertex_regimes(base_, p);
        const std::size_t last = regimes.size() - 1;
        value = regime_limit(p, regimes[last], regime_start_value(p, regimes, last));
    } else if (const auto v = base_vertex(base_, p)) {
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
    limit_.insert(k, value);
    return value;
}

glm::dvec3 HierarchyEvaluator::control_point(const SurfacePoint& p, int k) {
    const glm::dvec3 own = insertion_position(p);
    if (k <= p.level) return own;
    if (!follows_untagged_rules(base_, p)) return tagged_control_point(p, k);
    return closed_form(own, limit_position(p), gamma(p), k - p.level);
}

glm::dvec3 HierarchyEvaluator::tagged_control_point(const SurfacePoint& p, int k) {
    const Regimes regimes = vertex_regimes(base_, p);
    std::size_t i = 0;
    while (i + 1 < regimes.size() && regimes[i + 1].start <= k) ++i;
    return regime_value(p, regimes[i], regime_start_value(p, regimes, i), k);
}

glm::dvec3 HierarchyEvaluator::regime_start_value(const SurfacePoint& p, const Regimes& regimes, std::size_t i) {
    if (i == 0) return insertion_position(p);
    Key k = key(p);
    k.regime = regimes[i].start;
    if (const glm::dvec3* known = regime_start_.find(k)) return *known;
    // docs/loop-creases.md §5: a regime starts where the previous one's closed form has brought p.
    const glm::dvec3 value = regime_value(p, regimes[i - 1], regime_start_value(p, regimes, i - 1), regimes[i].start);
    regime_start_.insert(k, value);
    return value;
}

glm::dvec3 HierarchyEvaluator::regime_value(const SurfacePoint& p, const Regime& r, const glm::dvec3& start, int k) {
    const int steps = k - r.start;
    if (steps <= 0) return start;
    if (r.rule == VertexRule::Dart) {
        const std::vector<glm::dvec3> ring = ring_values(p, r.start);
        return apply_dart_mask(dart_mask(static_cast<int>(ring.size()), steps), start, ring, r.sharp[0]);
    }
    // Spec §4.2's two-term form, whose limit and eigenvalue depend on the rule (docs/loop-creases.md §4).
    return closed_form(start, regime_limit(p, r, start), regime_gamma(p, r.rule), steps);
}

glm::dvec3 HierarchyEvaluator::regime_limit(const SurfacePoint& p, const Regime& r, const glm::dvec3& start) {
    if (r.rule == VertexRule::Corner) return start;
    Key k = key(p);
    k.regime = r.start;
    if (const glm::dvec3* known = regime_limit_.find(k)) return *known;
    glm::dvec3 value;
    if (r.rule == VertexRule::Crease) {
        // A crease vertex behaves like a boundary vertex along its crease (docs/loop-creases.md §4.2):
        // only its two neighbours along the crease count, so only they are evaluated.
        const std::vector<SurfacePoint> ring = ring_at(base_, p, r.start);
        value = boundary_limit(start, control_point(ring[r.sharp[0]], r.start), control_point(ring[r.sharp[1]], r.start));
    } else {
        std::vector<glm::dvec3> ring = ring_values(p, r.start);
        value = r.rule == VertexRule::Dart
                    ? apply_dart_mask(dart_limit_mask(static_cast<int>(ring.size())), start, ring, r.sharp[0])
                    : interior_limit(start, ring);
    }
    regime_limit_.insert(k, value);
    return value;
}

std::vector<glm::dvec3> HierarchyEvaluator::ring_values(const SurfacePoint& p, int t) {
    std::vector<glm::dvec3> values;
    for (const SurfacePoint& q : ring_at(base_, p, t)) values.push_back(control_point(q, t));
    return values;
}

double HierarchyEvaluator::regime_gamma(const SurfacePoint& p, VertexRule rule) const {
    switch (rule) {
        case VertexRule::Crease: return loop_gamma(0, true);
        case VertexRule::Corner: return 0.0;
        default: break;
    }
    const auto v = base_vertex(base_, p);
    return loop_gamma(v ? base_.valence(*v) : 6, false);
}

}  // namespace rgb
