#include "rgb/values/face_grid_limits.h"

#include <algorithm>
#include <array>
#include <bit>

#include "rgb/mesh/vertex_rules.h"
#include "rgb/rules/loop_rules.h"
#include "rgb/values/hierarchy_evaluator.h"

namespace rgb {

void FaceGridLimits::start(std::uint32_t face, int level) {
    face_ = face;
    level_ = std::clamp(level, 0, kMaxLevel);
    stride_ = (std::size_t(1) << level_) + 1;
    if (slots_.size() < stride_ * stride_) slots_.resize(stride_ * stride_);
    if (edge_slots_.size() < 3 * stride_) {
        edge_slots_.resize(3 * stride_);
        evaluated_.resize(edge_slots_.size() * (kMaxLevel + 2));
        evaluated_stamps_.resize(evaluated_.size());
    }
    ++stamp_;
}

int FaceGridLimits::level_of(const Point& p) const {
    return level_ - std::min(std::countr_zero(p[0] | p[1] | p[2]), level_);
}

SurfacePoint FaceGridLimits::surface_point(const Point& p) const {
    const int level = level_of(p);
    const int shift = level_ - level;
    return SurfacePoint{face_, {p[0] >> shift, p[1] >> shift, p[2] >> shift}, level};
}

glm::dvec3 FaceGridLimits::limit_position(const SurfacePoint& p) {
    if (p.face != face_ || p.level > level_) return evaluator_.limit_position(reduced(p));
    const int shift = level_ - p.level;
    const Point q{p.a[0] << shift, p.a[1] << shift, p.a[2] << shift};
    if (!inside(q)) return boundary_value(q, kMaxLevel + 1);
    return limit(q, level_of(q));
}

glm::dvec3 FaceGridLimits::control_point(const SurfacePoint& p, int k) {
    if (p.face != face_ || p.level > level_ || k > kMaxLevel) return evaluator_.control_point(reduced(p), k);
    const int shift = level_ - p.level;
    const Point q{p.a[0] << shift, p.a[1] << shift, p.a[2] << shift};
    return control_point(q, k);
}

glm::dvec3 FaceGridLimits::boundary_value(const Point& p, int k) {
    const int zeros = (p[0] == 0) + (p[1] == 0) + (p[2] == 0);
    if (zeros > 1) return evaluators_value(p, k);
    const int edge = p[0] == 0 ? 0 : p[1] == 0 ? 1 : 2;
    EdgeSlot& e = edge_slots_[std::size_t(edge) * stride_ + p[static_cast<std::size_t>((edge + 1) % 3)]];
    if (e.stamp != stamp_) {
        const SurfacePoint q = surface_point(p);
        e.tagged = !follows_untagged_rules(base_, q);
        if (!e.tagged) {
            e.insertion = evaluator_.insertion_position(q);
            e.gamma = loop_gamma(6, is_boundary(base_, q));
        }
        e.stamp = stamp_;
    }
    if (e.tagged) return evaluators_value(p, k);
    const int level = level_of(p);
    if (k <= level) return e.insertion;
    if (e.limit_stamp != stamp_) {
        e.limit = evaluator_.limit_position(surface_point(p));
        e.limit_stamp = stamp_;
    }
    // As HierarchyEvaluator::control_point, and its limit where k is beyond every level.
    return k > kMaxLevel ? e.limit : closed_form(e.insertion, e.limit, e.gamma, k - level);
}

glm::dvec3 FaceGridLimits::evaluators_value(const Point& p, int k) {
    const int edge = p[0] == 0 ? 0 : p[1] == 0 ? 1 : 2;
    const std::size_t at = (std::size_t(edge) * stride_ + p[static_cast<std::size_t>((edge + 1) % 3)]) * (kMaxLevel + 2) +
                           static_cast<std::size_t>(k);
    if (evaluated_stamps_[at] == stamp_) return evaluated_[at];
    const SurfacePoint q = surface_point(p);
    evaluated_[at] = k > kMaxLevel ? evaluator_.limit_position(q) : evaluator_.control_point(q, k);
    evaluated_stamps_[at] = stamp_;
    return evaluated_[at];
}

// A point inside the face has level >= 1; its stencil's points are all on the face's closed
// triangle: two of its numerators at its level are odd (its parent edge runs along them), the third
// even and so at least 2.
glm::dvec3 FaceGridLimits::insertion(const Point& p, int level) {
    const std::size_t at = slot(p);
    if (slots_[at].insertion_stamp == stamp_) return slots_[at].insertion;
    const std::uint32_t unit = std::uint32_t(1) << (level_ - level);
    const int even = (p[0] & unit) == 0 ? 0 : (p[1] & unit) == 0 ? 1 : 2;
    const int i = (even + 1) % 3, k = (even + 2) % 3;
    Point ends[2] = {p, p}, opposite[2] = {p, p};
    ends[0][i] += unit, ends[0][k] -= unit;
    ends[1][i] -= unit, ends[1][k] += unit;
    opposite[0][even] += 2 * unit, opposite[0][i] -= unit, opposite[0][k] -= unit;
    opposite[1][even] -= 2 * unit, opposite[1][i] += unit, opposite[1][k] += unit;
    const glm::dvec3 value = interior_edge_point(control_point(ends[0], level - 1), control_point(ends[1], level - 1),
                                                 control_point(opposite[0], level - 1), control_point(opposite[1], level - 1));
    slots_[at].insertion = value;
    slots_[at].insertion_stamp = stamp_;
    return value;
}

glm::dvec3 FaceGridLimits::limit(const Point& p, int level) {
    const std::size_t at = slot(p);
    if (slots_[at].limit_stamp == stamp_) return slots_[at].limit;
    const std::uint32_t unit = std::uint32_t(1) << (level_ - level);
    const glm::dvec3 centre = insertion(p, level);
    std::array<glm::dvec3, 6> ring;
    std::size_t n = 0;
    for (int x = 0; x < 3; ++x)
        for (int y = 0; y < 3; ++y) {
            if (x == y) continue;
            Point q = p;
            q[static_cast<std::size_t>(x)] += unit;
            q[static_cast<std::size_t>(y)] -= unit;
            ring[n++] = control_point(q, level);
        }
    const glm::dvec3 value = interior_limit(centre, ring);
    slots_[at].limit = value;
    slots_[at].limit_stamp = stamp_;
    return value;
}

glm::dvec3 FaceGridLimits::control_point(const Point& p, int k) {
    if (!inside(p)) return boundary_value(p, k);
    // As HierarchyEvaluator::control_point for an interior point (valence 6, not on the boundary).
    static const double gamma = loop_gamma(6, false);
    const int level = level_of(p);
    const glm::dvec3 own = insertion(p, level);
    if (k <= level) return own;
    return closed_form(own, limit(p, level), gamma, k - level);
}

}  // namespace rgb
