#pragma once
// How far a mesh's displayed surface is from the Loop limit surface, or from the dense surface of a
// cage with detail (target_position; docs/requests.md, docs/detail.md): at the samples of every face, the vertices of Σ(l+2) that lie in a face of level l (the
// face's corners, points along its edges and inside it), each compared with its exact limit point
// (hierarchy_evaluator.h); the displayed surface there is the flat face between its corners'
// displayed positions (spec §4.6). This is the measure the tolerance criterion (limit_error.h)
// bounds.
#include <cstddef>

#include <glm/vec3.hpp>

#include "rgb/mesh/surface_point.h"

namespace rgb {

class BaseMesh;
class HierarchyEvaluator;
class Mesh;

// The surface a displayed mesh approximates, at hierarchy point p: the Loop limit point, or on a cage
// with detail (BaseMesh::detail) the detail's point, which lies on the dense surface for every p up to
// the detail's level. Tolerances and errors measure against it.
glm::dvec3 target_position(const BaseMesh& base, HierarchyEvaluator& evaluator, const SurfacePoint& p);

struct SurfaceError {
    double max_error = 0.0;
    glm::dvec3 where{0.0};  // the target point of the sample with the largest error
    std::size_t samples = 0;
};

SurfaceError displayed_surface_error(const Mesh& mesh);

}  // namespace rgb
