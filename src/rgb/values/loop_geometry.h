#pragma once
// Layer rgb/values (positions, limits, normals, UVs and channels of any vertex by its address):
// includes rgb/mesh, rgb/rules and rgb/support. docs/architecture.md draws the layers.
// Exact Loop positions of the vertices of an RGB mesh without a hierarchy (spec §4.2, §4.6). Every
// value is available for every vertex: from the vertex's ring in the mesh when the mesh holds it,
// otherwise from the hierarchy evaluator (hierarchy_evaluator.h); both give the same bits. Limits are
// cached in the mesh once computed.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "rgb/mesh/handles.h"

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
// The same with p^inf(v) given (a caller's copy of limit_position's value): the same bits, without
// the lookup in the mesh's limit table.
glm::dvec3 control_point(const Mesh& mesh, VertexId v, int k, const glm::dvec3& limit);

// The same for a vertex whose rules the base mesh's tags leave as Loop's (every vertex of a mesh
// without sharp features) and k > level(v): the closed form alone, for a caller that knows this of
// every vertex it asks about (the LOD driver's keys).
glm::dvec3 untagged_control_point(const Mesh& mesh, VertexId v, int k, const glm::dvec3& limit);

// The level at which v is displayed: max(level(v), min level of its incident edges), red included.
int display_level(const Mesh& mesh, VertexId v);

// display_level of every vertex at once, by slot (dead slots 0), in one pass over the faces: for a
// whole-mesh use such as saving, where walking each vertex's star reaches its faces out of memory order.
std::vector<std::uint8_t> display_levels(const Mesh& mesh);

// p^k(v) for k = display_level(v): the mesh vertex position a viewer shows; on a cage with detail
// (BaseMesh::detail), the vertex's detail position instead, whatever its display level.
glm::dvec3 displayed_position(const Mesh& mesh, VertexId v);
// The same with v's display level already known (display_levels).
glm::dvec3 displayed_position(const Mesh& mesh, VertexId v, int display_level);

}  // namespace rgb
