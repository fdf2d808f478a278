#pragma once
// Screen-space detail (docs/requests.md "Detail by size, accuracy and view"): the value of an edge of Σl for
// one camera is its length in pixels in the uniform Loop mesh of its level, or 0 where it cannot be
// seen: when a ball around its midpoint with the edge's length as radius lies outside the view
// frustum, or when every base face it lies in faces away from the eye (screen_detail.cpp's margin). It depends on the edge and the camera alone,
// so `render --screen-lod` is a canonical request, and the editor's continuous mode (view_lod.h)
// judges edges by the same numbers.
#include <memory>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "rgb/lod/lod_criteria.h"
#include "rgb/mesh/surface_point.h"

namespace rgb {

class BaseMesh;
class HierarchyEvaluator;

struct ScreenView {
    glm::dmat4 view_projection{1.0};  // world to clip space, OpenGL conventions
    glm::dvec2 viewport{1.0, 1.0};    // in pixels
    glm::dvec3 eye{0.0};
};

class ScreenCriterion {
public:
    ScreenCriterion(std::shared_ptr<const BaseMesh> base, const ScreenView& view);

    // The value of the edge of Σl between the points shown at a and b in the uniform mesh of its
    // level, whose midpoint has address `midpoint`.
    double value(const glm::dvec3& a, const glm::dvec3& b, const SurfacePoint& midpoint) const;
    const ScreenView& view() const { return view_; }
    // Whether a triangle with these corners (in base space, so in the plane of its base face) may be
    // seen: some of it inside the frustum and not turned away from the eye by more than a base face
    // counts as turned away. A cheap test for ordering work (view_priority.h), not the value: that
    // judges each edge from its own points.
    bool may_see(const glm::dvec3 (&corners)[3]) const;

    // The criterion for requests (the positions from the hierarchy evaluator).
    EdgeValue edge_value() const;

private:
    bool seen(const SurfacePoint& midpoint) const;

    std::shared_ptr<const BaseMesh> base_;
    ScreenView view_;
    std::vector<glm::dvec4> planes_;   // of the frustum, inward, with unit normals
    std::vector<bool> facing_away_;    // by base face
};

}  // namespace rgb
