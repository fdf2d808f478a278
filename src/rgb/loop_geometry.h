#pragma once
// Exact Loop positions of the vertices of an RGB mesh without a hierarchy (spec §4.2, §4.6). Every
// value is available for every vertex: from the vertex's ring in the mesh when the mesh holds it,
// otherwise from the hierarchy evaluator (hierarchy_evaluator.h); both give the same bits. Limits are
// cached in the mesh once computed.
#include <glm/vec3.hpp>

#include "rgb/handles.h"

namespace rgb {

class Mesh;

// p^inf(v), cached in the mesh once computed (a coarser vertex is a stencil point of many splits).
glm::dvec3 limit_position(const Mesh& mesh, VertexId v);
// Caches p^inf(v) if that is cheap now: where v's ring at its own level is its neighbours.
void limit_position_where_uniform(const Mesh& mesh, VertexId v);
// The same without storing it: for one-off uses such as display and saving, so that the cache holds
// only the limits the operators need.
glm::dvec3 limit_position_uncached(const Mesh& mesh, VertexId v);

// Control point p^k(v) of v in the uniform mesh of level k >= level(v), by the closed form
// gamma^j Pl + (1 - gamma^j) Pinf.
glm::dvec3 control_point(const Mesh& mesh, VertexId v, int k);

// The level at which v is displayed: max(level(v), min level of its incident edges), red included.
int display_level(const Mesh& mesh, VertexId v);

// p^k(v) for k = display_level(v): the mesh vertex position a viewer shows.
glm::dvec3 displayed_position(const Mesh& mesh, VertexId v);

}  // namespace rgb
