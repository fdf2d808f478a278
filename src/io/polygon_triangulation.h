#pragma once
// Triangulation of OBJ polygons by ear clipping in the polygon's best-fit plane (Newell normal).
// Every triangle keeps the polygon's winding, and for a simple polygon (convex or concave) every
// triangle lies inside it, so none is flipped against the polygon's normal.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

namespace rgbio {

// `polygon` holds indices into `positions` (at least 3, all distinct). Returns polygon.size() - 2
// triangles as index triples. For self-intersecting or zero-area polygons, where no true ear
// exists, the most convex corner is clipped so the result is still a full triangulation.
std::vector<std::array<std::uint32_t, 3>> triangulate_polygon(std::span<const glm::dvec3> positions,
                                                              std::span<const std::uint32_t> polygon);

}  // namespace rgbio
