#include "rgb/values/uv_evaluator.h"

#include <stdexcept>

#include "rgb/mesh/base_mesh.h"
#include "rgb/rules/dart_masks.h"
#include "rgb/rules/loop_rules.h"

namespace rgb {

namespace {

int corner_of_base_vertex(const SurfacePoint& p) { return p.a[0] != 0 ? 0 : p.a[1] != 0 ? 1 : 2; }

glm::dvec3 lifted(const glm::dvec2& uv) { return {uv.x, uv.y, 0.0}; }

}  // namespace

glm::dvec2 UvEvaluator::control_uv(const SurfacePoint& p, int k) {
    const glm::dvec3 uv = control(representative(p), k);
    return {uv.x, uv.y};
}

SurfacePoint UvEvaluator::representative(const SurfacePoint& p) const {
    if (p.level == 0) {
        const std::uint32_t f = layout_.span_face(layout_.span_of(p.face, corner_of_base_vertex(p)));
        return *in_face(base_, p, f);
    }
    if (const auto h = base_edge_of(p); h && layout_.is_seam(*h)) return p;
    return canonical(base_, p);
}

glm::dvec2 UvEvaluator::limit_uv(const SurfacePoint& p) {
    const SurfacePoint q = representative(p);
    const UvRegimes r = regimes(q);
    const std::size_t last = r.size() - 1;
    const glm::dvec3 uv = regime_limit(q, r[last], regime_start_value(q, r, last), last == 0 ? &values(q) : nullptr);
    return {uv.x, uv.y};
}

UvEvaluator::Key UvEvaluator::key(const SurfacePoint& p) const {
    if (p.level == 0) {
        const SurfacePoint c = canonical(base_, p);
        return {c.face, c.a[0], c.a[1], 0, layout_.span_of(p.face, corner_of_base_vertex(p))};
    }
    if (const auto h = base_edge_of(p); h && layout_.is_seam(*h)) return {p.face, p.a[0], p.a[1], p.level, p.face};
    const SurfacePoint c = canonical(base_, p);
    return {c.face, c.a[0], c.a[1], c.level, UvLayout::kNone};
}

UvRegimes UvEvaluator::regimes(const SurfacePoint& p) const {
    const UvInterpolation option = layout_.interpolation();
    UvRegime corner;
    corner.start = p.level;
    if (option == UvInterpolation::All) return {corner};
    if (p.level == 0) {
        const UvRegimes& span = layout_.span_regimes(layout_.span_of(p.face, corner_of_base_vertex(p)));
        if (!span.empty()) return span;
    } else if (const auto h = base_edge_of(p)) {
        const bool seam = layout_.is_seam(*h), boundary = base_.opposite(*h) == BaseMesh::kNone;
        if ((seam || boundary) && option == UvInterpolation::Boundaries) return {corner};
        if (seam) {
            // Each side moves along the seam, pinned to the two neighbours on its own side.
            UvRegime crease = corner;
            crease.rule = VertexRule::Crease;
            crease.sharp[0] = 0;
            crease.sharp[1] = 1;
            crease.end_face[0] = crease.end_face[1] = p.face;
            return {crease};
        }
    }
    // A value that matches its vertex: the vertex's own rules.
    UvRegimes own;
    for (const Regime& r : vertex_regimes(base_, p)) {
        UvRegime u;
        u.start = r.start;
        u.rule = r.rule;
        u.sharp[0] = r.sharp[0];
        u.sharp[1] = r.sharp[1];
        own.push_back(u);
    }
    return own;
}

UvEvaluator::Values& UvEvaluator::values(const SurfacePoint& p) {
    const Key k = key(p);
    if (const auto it = values_.find(k); it != values_.end()) return it->second;
    Values v;
    if (p.level == 0) {
        v.insertion = lifted(layout_.corner_uv(p.face, corner_of_base_vertex(p)));
    } else {
        // §3's edge points: the stencil is read in p's face, so a seam's ends are on p's side.
        const PointStencil s = parent_stencil(base_, p);
        const int l = p.level - 1;
        auto at = [&](const SurfacePoint& q) { return control(representative(reduced(q)), l); };
        const glm::dvec3 a = at(s.ends[0]), b = at(s.ends[1]);
        const auto h = base_edge_of(p);
        const bool midpoint = s.boundary || layout_.interpolation() == UvInterpolation::All || (h && layout_.is_seam(*h)) ||
                              (base_.has_sharp_features() && inserted_at_midpoint(base_, p));
        v.insertion = midpoint ? boundary_edge_point(a, b) : interior_edge_point(a, b, at(s.opposite[0]), at(s.opposite[1]));
    }
    return values_.emplace(k, v).first->second;
}

glm::dvec3 UvEvaluator::insertion(const SurfacePoint& p) { return values(p).insertion; }

glm::dvec3 UvEvaluator::control(const SurfacePoint& p, int k) {
    Values& own = values(p);
    if (k <= p.level) return own.insertion;
    const UvRegimes r = regimes(p);
    std::size_t i = 0;
    while (i + 1 < r.size() && r[i + 1].start <= k) ++i;
    if (i == 0) return regime_value(p, r[0], own.insertion, k, &own);
    return regime_value(p, r[i], regime_start_value(p, r, i), k, nullptr);
}

glm::dvec3 UvEvaluator::regime_start_value(const SurfacePoint& p, const UvRegimes& regimes, std::size_t i) {
    if (i == 0) return insertion(p);
    Key k = key(p);
    k.regime = regimes[i].start;
    if (const auto it = regime_start_.find(k); it != regime_start_.end()) return it->second;
    const glm::dvec3 value = regime_value(p, regimes[i - 1], regime_start_value(p, regimes, i - 1), regimes[i].start,
                                          i == 1 ? &values(p) : nullptr);
    regime_start_.emplace(k, value);
    return value;
}

glm::dvec3 UvEvaluator::regime_value(const SurfacePoint& p, const UvRegime& r, const glm::dvec3& start, int k, Values* first) {
    const int steps = k - r.start;
    if (steps <= 0 || r.rule == VertexRule::Corner) return start;
    if (r.rule == VertexRule::Dart) {
        const std::vector<glm::dvec3> ring = ring_values(p, r.start);
        return apply_dart_mask(dart_mask(static_cast<int>(ring.size()), steps), start, ring, r.sharp[0]);
    }
    return closed_form(start, regime_limit(p, r, start, first), regime_gamma(p, r.rule), steps);
}

glm::dvec3 UvEvaluator::regime_limit(const SurfacePoint& p, const UvRegime& r, const glm::dvec3& start, Values* first) {
    if (r.rule == VertexRule::Corner) return start;
    if (first && first->first_limit_known) return first->first_limit;
    Key k = key(p);
    k.regime = r.start;
    if (!first)
        if (const auto it = regime_limit_.find(k); it != regime_limit_.end()) return it->second;
    glm::dvec3 value;
    if (r.rule == VertexRule::Crease) {
        const std::vector<SurfacePoint> ring = ring_at(base_, p, r.start);
        value = boundary_limit(start, neighbour_value(ring[r.sharp[0]], r.end_face[0], r.start),
                               neighbour_value(ring[r.sharp[1]], r.end_face[1], r.start));
    } else {
        std::vector<glm::dvec3> ring = ring_values(p, r.start);
        value = r.rule == VertexRule::Dart
                    ? apply_dart_mask(dart_limit_mask(static_cast<int>(ring.size())), start, ring, r.sharp[0])
                    : interior_limit(start, ring);
    }
    if (first) {
        first->first_limit = value;
        first->first_limit_known = true;
    } else {
        regime_limit_.emplace(k, value);
    }
    return value;
}

std::vector<glm::dvec3> UvEvaluator::ring_values(const SurfacePoint& p, int t) {
    std::vector<glm::dvec3> values;
    for (const SurfacePoint& q : ring_at(base_, p, t)) values.push_back(neighbour_value(q, UvLayout::kNone, t));
    return values;
}

glm::dvec3 UvEvaluator::neighbour_value(const SurfacePoint& q, std::uint32_t face, int t) {
    if (face == UvLayout::kNone) return control(representative(reduced(q)), t);
    const auto in = in_face(base_, q, face);
    if (!in) throw std::logic_error("UvEvaluator: a crease end outside its side's face");
    return control(representative(reduced(*in)), t);
}

double UvEvaluator::regime_gamma(const SurfacePoint& p, VertexRule rule) const {
    if (rule == VertexRule::Crease) return loop_gamma(0, true);
    const auto v = base_vertex(base_, p);
    return loop_gamma(v ? base_.valence(*v) : 6, false);
}

}  // namespace rgb
