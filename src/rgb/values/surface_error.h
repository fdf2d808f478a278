#pragma once
// How far a mesh's displayed surface is from the Loop limit surface, or from the dense surface of a
// cage with detail (target_position; docs/requests.md, docs/detail.md): at the samples of every face, the vertices of Σ(l+2) that lie in a face of level l (the
// face's corners, points along its edges and inside it), each compared with its exact limit point
// (hierarchy_evaluator.h); the displayed surface there is the flat face between its corners'
// displayed positions (spec §4.6). This is the measure the tolerance criterion (limit_error.h)
// bounds.
#include <cstddef>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "rgb/mesh/handles.h"
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

// One live face's part of the measure: the largest error at its samples (the display's distance heat
// map colours each face by it). `evaluator` is over the mesh's base and may be shared between calls.
SurfaceError face_surface_error(const Mesh& mesh, HierarchyEvaluator& evaluator, FaceId f);

// The largest error over every face (face_surface_error's), the first face in slot order where tied.
SurfaceError displayed_surface_error(const Mesh& mesh);

// The same measure for the flat faces between other corner positions, one per vertex slot (such as
// the limit positions a file is written with: rgbsub lods), on all cores; the first face in slot order
// where tied, as above.
SurfaceError surface_error_at(const Mesh& mesh, const std::vector<glm::dvec3>& corner_positions);

// The same for several meshes on one base mesh (the levels of an LOD set, finest first), each with
// its corner positions by slot. The samples and their target points are those above, mesh by mesh;
// the work is shared: the faces are taken base face by base face, every mesh in turn, the limit
// points inside the base face from one grid (face_grid_limits.h: the evaluator's bits at array
// reads) and those on its edges from an evaluator kept for a few thousand of the finest mesh's faces,
// so that where the meshes nest (a coarser face's samples are among the finer faces' samples that
// cover it) a coarser mesh's samples are looked up rather than evaluated again.
std::vector<SurfaceError> surface_errors_at(std::span<const Mesh* const> meshes, std::span<const std::vector<glm::dvec3>> corner_positions);

// The length that percentages of the mesh's size are of (tolerances and automatic LOD in the editor,
// the distance heat map's scale): the diagonal of the base mesh's bounding box, so that it does not
// change as the detail does.
double bounding_box_diagonal(const BaseMesh& base);

}  // namespace rgb
