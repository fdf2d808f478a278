#include "rgb/values/face_grid_limits.h"

#include <algorithm>
#include <array>
#include <bit>

#include "rgb/mesh/base_mesh.h"
#include "rgb/rules/loop_rules.h"
#include "rgb/values/hierarchy_evaluator.h"

namespace rgb {

namespace {
// As HierarchyEvaluator::gamma for a point inside a face or an untagged interior edge (valence 6, not
// on the boundary).
double regular_gamma() {
    static const double gamma = loop_gamma(6, false);
    return gamma;
}
}  // namespace

void FaceGridLimits::start(std::uint32_t face, int level) {
    face_ = face;
    level_ = std::clamp(level, 0, kMaxLevel);
    stride_ = (std::size_t(1) << level_) + 1;
    if (slots_.size() < stride_ * stride_) slots_.resize(stride_ * stride_);
    if (edge_slots_.size() < 3 * stride_) {
        edge_slots_.resize(3 * stride_);
        evaluated_.resize(edge_slots_.size() * (kMaxLevel + 2));
        evaluated_stamps_.resize(evaluated_.size());
        band_.resize(3 * 2 * (stride_ - 1));
    }
    for (std::size_t e = 0; e < 3; ++e) {
        // Edge e runs from corner e + 1 to corner e + 2: base halfedge 3 face + e + 1.
        const std::uint32_t h = 3 * face + static_cast<std::uint32_t>((e + 1) % 3), twin = base_.opposite(h);
        Edge& edge = edges_[e];
        if (twin == BaseMesh::kNone) {
            edge.rule = EdgeRule::kBoundary;
            edge.gamma = loop_gamma(6, true);
        } else if (base_.edge_sharpness(h) == 0) {
            // The twin runs from this face's corner e + 2 to its corner e + 1.
            const std::uint8_t c = static_cast<std::uint8_t>(twin % 3);
            edge = {EdgeRule::kDiamond, twin / 3, {static_cast<std::uint8_t>((c + 1) % 3), c, static_cast<std::uint8_t>((c + 2) % 3)}, regular_gamma()};
        } else {
            edge.rule = EdgeRule::kTagged;
        }
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
    const Edge& rule = edges_[static_cast<std::size_t>(edge)];
    if (rule.rule == EdgeRule::kTagged) return evaluators_value(p, k);
    const std::uint32_t t = p[static_cast<std::size_t>((edge + 1) % 3)];
    EdgeSlot& e = edge_slots_[std::size_t(edge) * stride_ + t];
    const int level = level_of(p);
    if (e.stamp != stamp_) {
        e.insertion = rule.rule == EdgeRule::kDiamond ? diamond_insertion(edge, t, level) : evaluator_.insertion_position(surface_point(p));
        e.stamp = stamp_;
    }
    if (k <= level) return e.insertion;
    if (e.limit_stamp != stamp_) {
        e.limit = rule.rule == EdgeRule::kDiamond ? diamond_limit(edge, t, level, e.insertion) : evaluator_.limit_position(surface_point(p));
        e.limit_stamp = stamp_;
    }
    // As HierarchyEvaluator::control_point, and its limit where k is beyond every level.
    return k > kMaxLevel ? e.limit : closed_form(e.insertion, e.limit, rule.gamma, k - level);
}

FaceGridLimits::Point FaceGridLimits::on_edge(int edge, std::uint32_t t) const {
    Point p;
    p[static_cast<std::size_t>(edge)] = 0;
    p[static_cast<std::size_t>((edge + 1) % 3)] = t;
    p[static_cast<std::size_t>((edge + 2) % 3)] = (std::uint32_t(1) << level_) - t;
    return p;
}

// The edge point's parent edge runs along the base edge; its opposite points are one step of the
// parent level into this face and into the neighbour.
glm::dvec3 FaceGridLimits::diamond_insertion(int edge, std::uint32_t t, int level) {
    const std::uint32_t unit = std::uint32_t(1) << (level_ - level);
    Point inward = on_edge(edge, t - unit);
    inward[static_cast<std::size_t>(edge)] = 2 * unit, inward[static_cast<std::size_t>((edge + 2) % 3)] -= 2 * unit;
    return interior_edge_point(control_point(on_edge(edge, t + unit), level - 1), control_point(on_edge(edge, t - unit), level - 1),
                               control_point(inward, level - 1), band_insertion(edge, level - 1, (t - unit) / (2 * unit)));
}

// The ring: two neighbours along the edge, two in this face, two in the neighbour.
glm::dvec3 FaceGridLimits::diamond_limit(int edge, std::uint32_t t, int level, const glm::dvec3& insertion) {
    const std::uint32_t unit = std::uint32_t(1) << (level_ - level);
    const std::size_t e = static_cast<std::size_t>(edge), next = (e + 1) % 3, previous = (e + 2) % 3;
    Point inward[2] = {on_edge(edge, t), on_edge(edge, t)};
    inward[0][e] = unit, inward[0][next] -= unit;
    inward[1][e] = unit, inward[1][previous] -= unit;
    std::array<glm::dvec3, 6> ring{control_point(on_edge(edge, t + unit), level), control_point(on_edge(edge, t - unit), level),
                                   control_point(inward[0], level),        control_point(inward[1], level),
                                   band_insertion(edge, level, t / unit - 1), band_insertion(edge, level, t / unit)};
    return interior_limit(insertion, ring);
}

// The neighbour's point (b, 2^level - 1 - b, 1) over its corners at the edge's next and previous
// corners and opposite the edge, at its own level (its far numerator is odd). Inside the neighbour,
// its parent edge runs from the base edge to the band one level coarser, and so do its opposites.
glm::dvec3 FaceGridLimits::band_insertion(int edge, int level, std::uint32_t b) {
    BandSlot& slot = band_[std::size_t(edge) * 2 * (stride_ - 1) + (std::size_t(1) << level) + b];
    if (slot.stamp == stamp_) return slot.insertion;
    const std::uint32_t across = (std::uint32_t(1) << level) - 1 - b;
    if (b == 0 || across == 0) {
        // On another edge of the neighbour (or its far corner): the evaluator's.
        const Edge& rule = edges_[static_cast<std::size_t>(edge)];
        SurfacePoint q{rule.neighbour, {}, level};
        q.a[rule.corners[0]] = b, q.a[rule.corners[1]] = across, q.a[rule.corners[2]] = 1;
        slot.insertion = evaluator_.control_point(reduced(q), level);
    } else {
        const std::uint32_t unit = std::uint32_t(1) << (level_ - level);
        const int parent = level - 1;
        // b odd: the parent edge runs from (b + 1, across, 0) to (b - 1, across, 2); b even, from
        // (b, across + 1, 0) to (b, across - 1, 2).
        const std::uint32_t shift = b & 1u;
        slot.insertion = interior_edge_point(control_point(on_edge(edge, (b + shift) * unit), parent), band_insertion(edge, parent, (b - shift) / 2),
                                             control_point(on_edge(edge, (b + 2 - 3 * shift) * unit), parent),
                                             band_insertion(edge, parent, (b + 3 * shift - 2) / 2));
    }
    slot.stamp = stamp_;
    return slot.insertion;
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
    const int level = level_of(p);
    const glm::dvec3 own = insertion(p, level);
    if (k <= level) return own;
    return closed_form(own, limit(p, level), regular_gamma(), k - level);
}

// Level by level: every point's value at level j from the slots (those of coarser levels by the
// closed form, the new ones by the edge rule over level j - 1's values), then the new points' limits
// over their rings at level j; the points on the face's boundary as boundary_value gives them.
void FaceGridLimits::fill() {
    std::vector<glm::dvec3>&previous = fill_values_[0], &current = fill_values_[1];
    previous.resize(4);
    for (std::uint32_t b1 = 0; b1 <= 1; ++b1)
        for (std::uint32_t b2 = 0; b1 + b2 <= 1; ++b2) {
            const std::uint32_t n = std::uint32_t(1) << level_;
            previous[b1 * 2 + b2] = boundary_value({n - (b1 + b2) * n, b1 * n, b2 * n}, 0);
        }
    for (int j = 1; j <= level_; ++j) {
        const std::uint32_t side = std::uint32_t(1) << j, unit = std::uint32_t(1) << (level_ - j);
        const std::size_t row = side + 1, parent_row = side / 2 + 1;
        current.resize(row * row);
        // Level j - 1's value of a point given by its level-j numerators (all even).
        const auto parent = [&](std::uint32_t b1, std::uint32_t b2) { return previous[(b1 / 2) * parent_row + b2 / 2]; };
        for (std::uint32_t b1 = 0; b1 <= side; ++b1)
            for (std::uint32_t b2 = 0; b1 + b2 <= side; ++b2) {
                const std::uint32_t b0 = side - b1 - b2;
                const Point p{b0 * unit, b1 * unit, b2 * unit};
                glm::dvec3& value = current[b1 * row + b2];
                if (!inside(p)) {
                    value = boundary_value(p, j);
                    continue;
                }
                Slot& s = slots_[slot(p)];
                if (((b0 | b1 | b2) & 1u) == 0) {
                    value = closed_form(s.insertion, s.limit, regular_gamma(), j - level_of(p));
                    continue;
                }
                // As insertion(): the parent edge joins the two odd numerators' neighbours.
                if ((b0 & 1u) == 0)
                    value = interior_edge_point(parent(b1 - 1, b2 + 1), parent(b1 + 1, b2 - 1), parent(b1 - 1, b2 - 1), parent(b1 + 1, b2 + 1));
                else if ((b1 & 1u) == 0)
                    value = interior_edge_point(parent(b1, b2 + 1), parent(b1, b2 - 1), parent(b1 + 2, b2 - 1), parent(b1 - 2, b2 + 1));
                else
                    value = interior_edge_point(parent(b1 + 1, b2), parent(b1 - 1, b2), parent(b1 - 1, b2 + 2), parent(b1 + 1, b2 - 2));
                s.insertion = value;
                s.insertion_stamp = stamp_;
            }
        for (std::uint32_t b1 = 1; b1 < side; ++b1)
            for (std::uint32_t b2 = 1; b1 + b2 < side; ++b2) {
                if ((((side - b1 - b2) | b1 | b2) & 1u) == 0) continue;
                std::array<glm::dvec3, 6> ring{current[(b1 + 1) * row + b2], current[(b1 - 1) * row + b2],    current[b1 * row + b2 + 1],
                                               current[b1 * row + b2 - 1],   current[(b1 + 1) * row + b2 - 1], current[(b1 - 1) * row + b2 + 1]};
                Slot& s = slots_[slot({(side - b1 - b2) * unit, b1 * unit, b2 * unit})];
                s.limit = interior_limit(current[b1 * row + b2], ring);
                s.limit_stamp = stamp_;
            }
        std::swap(previous, current);
    }
}

}  // namespace rgb
