#pragma once
// How far a mesh's displayed surface is from the Loop limit surface (docs/requests.md "Tolerance to the limit
// surface"): at the samples of every face, the vertices of Σ(l+2) that lie in a face of level l (the
// face's corners, points along its edges and inside it), each compared with its exact limit point
// (hierarchy_evaluator.h); the displayed surface there is the flat face between its corners'
// displayed positions (spec §4.6). This is the measure the tolerance criterion (limit_error.h)
// bounds.
#include <cstddef>

#include <glm/vec3.hpp>

namespace rgb {

class Mesh;

struct SurfaceError {
    double max_error = 0.0;
    glm::dvec3 where{0.0};  // the limit point of the sample with the largest error
    std::size_t samples = 0;
};

SurfaceError displayed_surface_error(const Mesh& mesh);

}  // namespace rgb
