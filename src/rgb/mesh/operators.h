#pragma once
// The atomic operators of RGB subdivision (spec §2), each with its predicate. They keep the mesh a
// valid RGB triangulation and report every change through the mesh observers.
#include <optional>

#include <glm/vec3.hpp>

#include "rgb/mesh/handles.h"
#include "rgb/support/inline_vector.h"

namespace rgb {

class Mesh;

enum class SplitKind { GG, RG, RR_Opposite, RR_Same, BoundaryG, BoundaryR };
enum class MergeKind { R4, R2GB, GBGB, G2B2, BoundaryR2, BoundaryGB };

const char* split_kind_name(SplitKind k);
const char* merge_kind_name(MergeKind k);

// ---- splits (§2.1, §2.2) ----
// Which split applies to the edge of h, or nullopt if the edge is not splittable now (red, or an
// incident triangle of a coarser level).
std::optional<SplitKind> split_kind(const Mesh& mesh, HalfedgeId h);
bool can_split_edge(const Mesh& mesh, HalfedgeId h);
// The vertices whose control points at the edge's level give the new vertex's position: the two
// endpoints, then (interior edges) the two opposite vertices of the uniform mesh of that level.
InlineVector<VertexId, 4> split_stencil(const Mesh& mesh, HalfedgeId h);
// Splits the edge of h (requires can_split_edge, which split_edge checks), applies the automatic
// BB-swaps and keeps the normal form of spec §3.5 (in a parent with two split edges, the red
// triangle's red edge enters its top vertex). The new vertex's p^l is `position`: the topology takes
// it as data, and values/loop_split.h's split_edge computes Loop's (spec §4.4). Returns the new vertex.
VertexId split_edge_at(Mesh& mesh, HalfedgeId h, const glm::dvec3& position);

// ---- swaps (§2.5); h is a halfedge of the edge to flip ----
bool can_bb_swap(const Mesh& mesh, HalfedgeId h);
void bb_swap(Mesh& mesh, HalfedgeId h);
bool can_gg_swap(const Mesh& mesh, HalfedgeId h);
void gg_swap(Mesh& mesh, HalfedgeId h);
bool can_rb_swap(const Mesh& mesh, HalfedgeId h);
void rb_swap(Mesh& mesh, HalfedgeId h);

// ---- merges (§2.3) and vertex removal (§2.4) ----
// Which merge removes v right now (without swaps), or nullopt.
std::optional<MergeKind> merge_kind(const Mesh& mesh, VertexId v);
bool can_merge_vertex(const Mesh& mesh, VertexId v);
void merge_vertex(Mesh& mesh, VertexId v);
// Removable: level >= 1 and every incident triangle is G_{l}, R_{l-1} or B_{l-1} (l = level(v)).
bool can_remove_vertex(const Mesh& mesh, VertexId v);
// Normalising swaps (GG-swap, RB-swap) then the merge, then the normal form of spec §3.5 restored
// where a parent is left with two split edges. Requires can_remove_vertex.
void remove_vertex(Mesh& mesh, VertexId v);

// ---- normal form (spec §3.5) ----
// Whether f, a red triangle sharing its red edge with a blue (a parent with two split edges), has its
// red edge entering its top vertex; true for any other face.
bool in_normal_form(const Mesh& mesh, FaceId f);

}  // namespace rgb
