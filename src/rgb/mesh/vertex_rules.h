#pragma once
// Which Loop rule moves each vertex of the hierarchy at each level, and which rule makes each edge
// point, from the base mesh's crease and corner tags (OpenSubdiv's uniform creasing;
// docs/loop-creases.md §2-§5). Pure functions of a vertex's address: the adaptive mesh and the
// hierarchy evaluator ask the same questions and so get the same answers.
//
// Tags pass to finer levels by address: an edge of Σk lying on a base edge of sharpness s has
// sharpness s - k (10, infinite, stays 10); every other edge is smooth. So:
//  * a vertex of level >= 1 on a base edge sharp at its level is a crease vertex until the edge's
//    sharpness runs out, then smooth; every other vertex of level >= 1 is smooth;
//  * a base vertex's rule follows from its corner sharpness and the sharpness of its base edges
//    level by level (corner, crease, dart, smooth), and can change several times.
// With integer sharpness a rule applies unblended from the level where it starts (§2).
#include <cstdint>
#include <optional>
#include <vector>

#include "rgb/mesh/surface_point.h"
#include "rgb/support/inline_vector.h"

namespace rgb {

class BaseMesh;

enum class VertexRule : std::uint8_t { Smooth, Dart, Crease, Corner };

// A run of levels, from `start` up to the next regime's start (or for ever), in which a vertex moves
// by one rule. `sharp` names the ring entries (in ring_at_level's order) joined to the vertex by sharp
// edges: two for a crease, one for a dart.
struct Regime {
    int start = 0;
    VertexRule rule = VertexRule::Smooth;
    std::uint32_t sharp[2] = {0, 0};
};
// A rule changes only where a finite sharpness runs out (levels 1-9), so at most eleven regimes.
using Regimes = InlineVector<Regime, 11>;

// The regimes of p from its own level on (the first starts at p.level).
Regimes vertex_regimes(const BaseMesh& base, const SurfacePoint& p);
// The same for base vertex v, computed from its tags (BaseMesh keeps them for its tagged vertices).
Regimes base_vertex_regimes(const BaseMesh& base, std::uint32_t v);

// Whether p moves as in untagged Loop: smooth for ever (interior) or the boundary rule for ever
// (boundary). Cheap; true for every vertex of a base mesh without sharp features.
bool follows_untagged_rules(const BaseMesh& base, const SurfacePoint& p);

// Whether the vertex p (level >= 1) is the midpoint of its parent edge rather than Loop's smooth edge
// point: the parent edge is on the boundary or on a base edge still sharp at the parent's level.
bool inserted_at_midpoint(const BaseMesh& base, const SurfacePoint& p);

// Whether p lies on a base edge or is a base vertex, the only points a sharp edge can join.
bool on_base_edge_or_vertex(const SurfacePoint& p);
// The base halfedge (of some face) whose edge the hierarchy edge (a, b) lies on, if it lies on one.
std::optional<std::uint32_t> base_edge_between(const BaseMesh& base, const SurfacePoint& a, const SurfacePoint& b);

// The neighbours of p in Σk (k >= p.level). For a base vertex: one per base edge, counter-clockwise
// from its vertex halfedge (a boundary vertex's two boundary neighbours first and last, as
// BaseMesh::ring); for a vertex of level >= 1: ring_at_level's order (the two along a base edge first).
std::vector<SurfacePoint> ring_at(const BaseMesh& base, const SurfacePoint& p, int k);

}  // namespace rgb
