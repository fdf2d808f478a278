#pragma once
// Navigation in the uniform meshes Σ_l hidden inside an RGB mesh, by topological angles (spec §1.5,
// §8.3): turning around a vertex by a given angle, and walking "straight" through vertices that are
// finer than the level of interest.
#include <optional>
#include <vector>

#include "rgb/mesh/handles.h"

namespace rgb {

class Mesh;

// An outgoing halfedge of v chosen by a rule that depends only on the mesh's contents (the boundary
// halfedge, or the one to the neighbour with the smallest id), never on edit history. Operators
// that walk a star start here, so a mesh restored from its state (state.h) makes the same choices,
// and so the same slot allocations, as the original.
HalfedgeId canonical_outgoing(const Mesh& mesh, VertexId v);

// Neighbour of c reached by turning `units` (30-degree steps) from the direction c->from,
// counter-clockwise or clockwise; nullopt if the boundary or no edge lies at that angle.
std::optional<VertexId> turn_ccw(const Mesh& mesh, VertexId c, VertexId from, int units);
std::optional<VertexId> turn_cw(const Mesh& mesh, VertexId c, VertexId from, int units);

// Starting with the step from->to, keep going straight (180 degrees) through vertices of level
// > max_level; returns the first vertex of level <= max_level, or nullopt at the boundary.
std::optional<VertexId> walk_straight(const Mesh& mesh, VertexId from, VertexId to, int max_level);

// Whether every face around v is a green triangle of v's own level, so that v's ring at its level
// is simply its neighbours.
bool ring_is_direct(const Mesh& mesh, VertexId v);

// The ring of v in the uniform mesh of its own level: the base neighbours for base vertices, 6 for
// interior vertices of level >= 1, the two boundary neighbours for boundary vertices (in that case
// exactly 2 entries). Empty if part of that ring is not in the current mesh.
std::vector<VertexId> uniform_ring(const Mesh& mesh, VertexId v);

}  // namespace rgb
