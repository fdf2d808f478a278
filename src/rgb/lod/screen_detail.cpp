#include "rgb/lod/screen_detail.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "rgb/mesh/base_mesh.h"
#include "rgb/values/hierarchy_evaluator.h"

namespace rgb {

namespace {

// A base face counts as facing away when the eye sees it from behind by more than this (the cosine of
// the angle between its normal and the direction from the eye), so that the surface refined over it
// near a silhouette, which bends towards the eye, is not taken for hidden.
constexpr double kFacingAwayCosine = 0.3;

// The point where the segment from p to q leaves the half-space z >= -w (in front of the near plane).
glm::dvec4 clip_to_near(const glm::dvec4& p, const glm::dvec4& q) {
    const double dp = p.z + p.w, dq = q.z + q.w;
    return p + (dp / (dp - dq)) * (q - p);
}

// Whether the eye sees the triangle from behind by more than kFacingAwayCosine allows.
bool turned_away(const glm::dvec3 (&corners)[3], const glm::dvec3& eye) {
    const glm::dvec3 n = glm::cross(corners[1] - corners[0], corners[2] - corners[0]);
    const glm::dvec3 to_face = (corners[0] + corners[1] + corners[2]) / 3.0 - eye;
    const double scale = glm::length(n) * glm::length(to_face);
    return scale > 0.0 && glm::dot(n, to_face) > kFacingAwayCosine * scale;
}

}  // namespace

ScreenCriterion::ScreenCriterion(std::shared_ptr<const BaseMesh> base, const ScreenView& view) : base_(std::move(base)), view_(view) {
    // Gribb and Hartmann: the frustum's planes are sums and differences of the matrix's rows.
    const glm::dmat4 m = glm::transpose(view.view_projection);  // rows of view_projection as columns
    for (int axis = 0; axis < 3; ++axis)
        for (double sign : {1.0, -1.0}) {
            glm::dvec4 plane = m[3] + sign * m[axis];
            plane /= glm::length(glm::dvec3(plane));
            planes_.push_back(plane);
        }
    facing_away_.resize(base_->num_faces());
    for (std::uint32_t f = 0; f < base_->num_faces(); ++f) {
        const Triangle& t = base_->face(f);
        facing_away_[f] = turned_away({base_->position(t[0]), base_->position(t[1]), base_->position(t[2])}, view.eye);
    }
}

bool ScreenCriterion::seen(const SurfacePoint& midpoint) const {
    if (!facing_away_[midpoint.face]) return true;
    // On a base edge, the face across counts too.
    for (int i = 0; i < 3; ++i)
        if (midpoint.a[static_cast<std::size_t>(i)] == 0) {
            const std::uint32_t across = base_->opposite(3 * midpoint.face + static_cast<std::uint32_t>((i + 1) % 3));
            return across != BaseMesh::kNone && !facing_away_[across / 3];
        }
    return false;
}

bool ScreenCriterion::may_see(const glm::dvec3 (&corners)[3]) const {
    if (turned_away(corners, view_.eye)) return false;
    for (const glm::dvec4& plane : planes_)
        if (std::ranges::all_of(corners, [&](const glm::dvec3& p) { return glm::dot(glm::dvec3(plane), p) + plane.w < 0.0; }))
            return false;
    return true;
}

double ScreenCriterion::value(const glm::dvec3& a, const glm::dvec3& b, const SurfacePoint& midpoint) const {
    const glm::dvec3 centre = 0.5 * (a + b);
    const double reach = glm::distance(a, b);
    for (const glm::dvec4& plane : planes_)
        if (glm::dot(glm::dvec3(plane), centre) + plane.w < -reach) return 0.0;
    if (!seen(midpoint)) return 0.0;
    glm::dvec4 p = view_.view_projection * glm::dvec4(a, 1.0), q = view_.view_projection * glm::dvec4(b, 1.0);
    const bool p_in = p.z + p.w > 0.0, q_in = q.z + q.w > 0.0;
    if (!p_in && !q_in) return 0.0;
    if (!p_in) p = clip_to_near(q, p);
    if (!q_in) q = clip_to_near(p, q);
    const glm::dvec2 pp = glm::dvec2(p) / p.w, pq = glm::dvec2(q) / q.w;
    return glm::length(0.5 * (pp - pq) * view_.viewport);
}

EdgeValue ScreenCriterion::edge_value() const {
    auto criterion = std::make_shared<ScreenCriterion>(*this);
    auto evaluator = std::make_shared<HierarchyEvaluator>(*base_);
    return [criterion, evaluator](const SurfacePoint& a, const SurfacePoint& b) {
        const int level = std::max(a.level, b.level);
        return criterion->value(evaluator->control_point(a, level), evaluator->control_point(b, level), midpoint(*criterion->base_, a, b));
    };
}

}  // namespace rgb
