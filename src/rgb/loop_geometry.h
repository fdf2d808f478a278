#pragma once
// Exact Loop positions of the vertices of an RGB mesh without a hierarchy (spec §4.2, §4.5, §4.6).
#include <optional>

#include <glm/vec3.hpp>

#include "rgb/handles.h"

namespace rgb {

class Mesh;

// Control point p^k(v) of v in the uniform mesh of level k >= level(v), by the closed form
// gamma^j Pl + (1 - gamma^j) Pinf. Requires the limit of v when k > level(v) (see ensure_limit).
glm::dvec3 control_point(const Mesh& mesh, VertexId v, int k);

// The level at which v is displayed: max(level(v), min level of its incident edges), red included.
int display_level(const Mesh& mesh, VertexId v);

// p^k(v) for k = display_level(v): the mesh vertex position a viewer shows.
glm::dvec3 displayed_position(const Mesh& mesh, VertexId v);

// p^inf(v) if the ring of v at its own level is present in the current mesh (computing and caching
// it if needed); nullopt otherwise. Never changes the topology.
std::optional<glm::dvec3> try_limit_position(const Mesh& mesh, VertexId v);

}  // namespace rgb
