#pragma once
// Recursive edge refinement (spec §3.1): the step every request is made of.
#include "rgb/mesh/handles.h"

namespace rgb {

class Mesh;

// Refines the edge {a, b} if it is a green edge: first whatever coarser neighbours the RGB topology
// requires, then the split. Returns false if nothing was split (no such edge, or red).
bool refine_edge(Mesh& mesh, VertexId a, VertexId b);
bool refine_edge(Mesh& mesh, HalfedgeId h);
// The edge whose refinement moves face f one step towards a finer level: a green edge of f's level
// for green and red faces, and for a blue face the coarse edge of the red beyond its red edge.
HalfedgeId edge_refining_face(const Mesh& mesh, FaceId f);
// Refines level by level until no face is coarser than `level`: the whole-surface refine request,
// and the fast path of a whole-surface set after its coarsening. Finer vertices already there stay
// (a refine removes nothing); without any, the mesh becomes Σ_level.
void refine_uniform(Mesh& mesh, int level);
// Removes v after removing, finest first, every vertex that cannot exist without it (its finer
// neighbours, recursively). Returns the number of vertices removed.
std::size_t remove_with_dependents(Mesh& mesh, VertexId v);

}  // namespace rgb
