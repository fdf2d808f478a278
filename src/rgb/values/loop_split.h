#pragma once
// The split operator with Loop's value for the new vertex: the topology (mesh/operators.h) takes the
// position as data; this computes it, the odd rule on the edge's stencil at the edge's level (spec
// §4.4), or the midpoint on a boundary or on a base edge still sharp there (docs/loop-creases.md §3).
// The stencil's control points are exact whatever the neighbourhood holds (loop_geometry.h).
#include <glm/vec3.hpp>

#include "rgb/mesh/handles.h"

namespace rgb {

class Mesh;

// p^(l+1) of the vertex a split of the edge of h inserts (requires can_split_edge).
glm::dvec3 split_position(const Mesh& mesh, HalfedgeId h);
// split_edge_at(mesh, h, split_position(mesh, h)): the split every refinement makes.
VertexId split_edge(Mesh& mesh, HalfedgeId h);

}  // namespace rgb
