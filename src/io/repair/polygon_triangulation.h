#pragma once
// Triangulation of OBJ polygons by ear clipping in the polygon's best-fit plane (Newell normal).
// Every triangle keeps the polygon's winding, and for a simple polygon (convex or concave) every
// triangle lies inside it, so none is flipped against the polygon's normal.
//
// Near-linear in practice (a 200,000-vertex polygon takes well under a second; see obj_load_bench):
// the remaining corners form a linked list; the ear test looks only at the reflex corners in the
// grid cells the candidate ear covers (in a simple polygon, a triangle of consecutive corners that
// holds any corner holds a reflex one); a corner's ear status is recomputed only when its neighbours
// change or the corner that blocked it is clipped; and the search resumes past the last ear instead
// of restarting, which keeps the ears small. A quad is cut at its first ear in corner order, as
// before.
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

namespace rgbio {

// `polygon` holds indices into `positions` (at least 3, all distinct). Returns polygon.size() - 2
// triangles as triples of corner numbers (0 .. polygon.size() - 1). For self-intersecting or
// zero-area polygons, where no true ear exists, the most convex corner is clipped so the result
// is still a full triangulation. Returns no triangles when a polygon is so tangled that the work
// (point-in-triangle checks and grid cells visited) would exceed work_budget, by default
// polygon_work_budget(), so that the caller reports it instead of hanging.
std::vector<std::array<std::uint32_t, 3>> triangulate_polygon_corners(std::span<const glm::dvec3> positions,
                                                                      std::span<const std::uint32_t> polygon,
                                                                      std::optional<std::uint64_t> work_budget = std::nullopt);

// The default work budget: linear in the size, with room for ten million checks at any size.
inline std::uint64_t polygon_work_budget(std::size_t corners) { return 10'000'000 + 2'000 * std::uint64_t(corners); }

// The same triangles as triples of indices into `positions`.
std::vector<std::array<std::uint32_t, 3>> triangulate_polygon(std::span<const glm::dvec3> positions,
                                                              std::span<const std::uint32_t> polygon);

}  // namespace rgbio
