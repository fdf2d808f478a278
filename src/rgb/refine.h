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
// Refines the three edges of f that are below `target_level` (a face request of the brush).
void refine_face(Mesh& mesh, FaceId f, int target_level);
// Splits the limit support of v into existence (§4.4 extra refinement) and returns true when the
// limit position of v is then known.
bool ensure_limit(Mesh& mesh, VertexId v);

// Uniform refinement until every green triangle has level >= `level` (the mesh becomes Σ_level).
void refine_uniform(Mesh& mesh, int level);

// Which part of the mesh a set-level request covers.
struct Region {
    // true if the point is inside the region; a face is inside when any of its vertices is.
    std::function<bool(const glm::dvec3&)> contains;
    static Region everywhere();
    static Region sphere(const glm::dvec3& centre, double radius);
};

struct SetLevelStats {
    std::size_t splits = 0;
    std::size_t removals = 0;
};

// Refines faces in the region whose level is below `target`, and removes removable vertices in the
// region whose level is above it, repeating until nothing changes.
SetLevelStats set_level(Mesh& mesh, const Region& region, int target);

// The same for an explicit set of seed faces (what a brush dab hits): faces below their target
// level are refined, vertices above it are removed where removable. `target_at` gives the target
// level at a point (for falloff), return < 0 to leave a point alone.
SetLevelStats set_level_faces(Mesh& mesh, std::span<const FaceId> faces,
                              const std::function<int(const glm::dvec3&)>& target_at);

}  // namespace rgb
