#pragma once
// The Loop values of a whole vertex set at once (restoring a saved mesh, a vertex channel's values): every vertex's insertion
// position p^l, and the limit p^inf of every vertex that some insertion position needs or that the
// caller asks for, from the vertices' addresses alone. Neighbours are found through an AddressIndex, never by walking a mesh, so the
// work is a few table lookups per vertex. Every value goes through the formulas of loop_rules.h
// like the mesh's own (loop_geometry.h) and the hierarchy evaluator's, so it has the same bits.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "rgb/mesh/surface_point.h"

namespace rgb {

class AddressIndex;
class BaseMesh;

struct HierarchyPositions {
    struct Limit {
        std::uint32_t vertex;
        glm::dvec3 position;
    };
    std::vector<glm::dvec3> insertion;  // per vertex
    std::vector<Limit> limits;          // the limits computed, by increasing vertex
    std::vector<glm::dvec3> at_levels;  // per vertex, its value at the level asked for (empty if none asked)
};

// points[i]: vertex i's canonical address; base vertices are vertices 0..n0-1 in base order.
// want_limit[i] != 0: vertex i's limit is wanted too. `levels`, if not empty: vertex i's value at
// levels[i] is wanted too, as hierarchy_values gives it (HierarchyPositions::at_levels).
// Throws std::invalid_argument when a vertex's parent triangles are not all present (then the
// vertex set is no RGB mesh: every vertex needs the corners of the triangles around its parent edge).
HierarchyPositions hierarchy_positions(const BaseMesh& base, std::span<const SurfacePoint> points, const AddressIndex& index,
                                       std::span<const std::uint8_t> want_limit, std::span<const std::uint8_t> levels = {});

// hierarchy_values' level that asks for the limit.
inline constexpr std::uint8_t kLimitLevel = 255;

// Each vertex's value at levels[i] (p^k for k = levels[i] >= its own level) or, where levels[i] is
// kLimitLevel, its limit p^inf; the same vertices, bits and failure as hierarchy_positions. The values
// are those of the base mesh's positions: a base mesh whose positions are a vertex channel's base
// values (vertex_channel.h) gives that channel's values.
std::vector<glm::dvec3> hierarchy_values(const BaseMesh& base, std::span<const SurfacePoint> points, const AddressIndex& index,
                                         std::span<const std::uint8_t> levels);

// Both at once, in one pass (a restored mesh with a vertex channel): hierarchy_positions over `base`,
// and channel_values = hierarchy_values over `channel` (base's faces and tags, other positions).
// The neighbours are looked up once for both, so the channel costs its arithmetic only.
HierarchyPositions hierarchy_positions(const BaseMesh& base, std::span<const SurfacePoint> points, const AddressIndex& index,
                                       std::span<const std::uint8_t> want_limit, std::span<const std::uint8_t> levels,
                                       const BaseMesh& channel, std::span<const std::uint8_t> channel_levels,
                                       std::vector<glm::dvec3>& channel_values);

}  // namespace rgb
