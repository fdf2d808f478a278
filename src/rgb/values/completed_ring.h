#pragma once
// The limit of a vertex whose ring at its own level the mesh holds only in part (spec §4.4): some
// faces around it are still the red halves of coarser triangles, with the vertex as their top. The
// ring point such a red lacks is the edge point of its coarse edge, so it follows from the four
// vertices of that edge's stencil, which the mesh holds around it. This is the common case of a
// selective refinement (the LOD driver splits one edge of a vertex before the others), and it costs a
// walk around the vertex instead of a descent of the hierarchy evaluator.
#include <optional>

#include <glm/vec3.hpp>

#include "rgb/mesh/handles.h"

namespace rgb {

class Mesh;

// p^inf(v) from its completed ring, the same bits as loop_geometry's limit_position; nullopt where
// the shape around v is not the one described above (or the base mesh has sharp features), and the
// caller takes the general way.
std::optional<glm::dvec3> limit_from_completed_ring(const Mesh& mesh, VertexId v);

}  // namespace rgb
