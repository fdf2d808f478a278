#pragma once
// Selective refinement (spec §3): recursive edge refinement and the level-of-detail API shared by the
// brush, the CLI and the tests. Every call costs in proportion to the work it does.
#include <cstddef>
#include <functional>
#include <span>

#include <glm/vec3.hpp>

#include "rgb/handles.h"

namespace rgb {

class Mesh;

// Refines the edge {a, b} if it is a green edge: first whatever coarser neighbours it requires, then
// the extra refinement its Loop stencil needs, then the split. Returns false if nothing was split
// (no such edge, or red).
bool refine_edge(Mesh& mesh, VertexId a, VertexId b);
// Splits the limit support of v into existence (§4.4 extra refinement) and returns true when the
// limit position of v is then known.
bool ensure_limit(Mesh& mesh, VertexId v);
// The edge whose refinement moves face f one step towards a finer level: a green edge of f's level
// for green and red faces, and for a blue face the coarse edge of the red beyond its red edge.
HalfedgeId edge_refining_face(const Mesh& mesh, FaceId f);

// Uniform refinement until every triangle is green of level `level` (the mesh becomes Σ_level,
// assuming no vertex is finer than that).
void refine_uniform(Mesh& mesh, int level);

// Which part of the mesh a set-level request covers.
struct Region {
    // true if the point is inside the region; a face is inside when any of its vertices is.
    std::function<bool(const glm::dvec3&)> contains;
    static Region everywhere();
    static Region sphere(const glm::dvec3& centre, double radius);
};

enum class LodDirection { Refine, Coarsen, Both };

struct SetLevelStats {
    std::size_t splits = 0;
    std::size_t removals = 0;
};

// Refines faces in the region whose level is below `target`, and removes removable vertices in the
// region whose level is above it, repeating until nothing changes.
// This scans every face once to find the region; brush dabs use set_level_faces instead.
SetLevelStats set_level(Mesh& mesh, const Region& region, int target, LodDirection direction = LodDirection::Both);

// The same from an explicit set of seed faces (what a brush dab hits), spreading to the faces the
// edits create. `target_at` gives the target level at a displayed position (a brush falloff);
// negative means "leave alone". A face's target is the highest target of its corners. Costs in
// proportion to the faces visited and the operators applied, never to the mesh size.
SetLevelStats set_level_faces(Mesh& mesh, std::span<const FaceId> seeds,
                              const std::function<int(const glm::dvec3&)>& target_at,
                              LodDirection direction = LodDirection::Both);

}  // namespace rgb
