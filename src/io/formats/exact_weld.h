#pragma once
// Welding a file's vertices by exact position, in parallel: what ExactIndex does for a stream of
// points, for a whole array at once. Speed: numbering a million-triangle file's 500,000 points one
// by one in one table misses the cache at nearly every point; cut by their hash into buckets that
// fit the cache, welded on every core, they cost a fraction of that.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

namespace rgbio {

// Per point, the index of the first point `used` marks that equals it (compared as doubles: +0 and
// -0 alike), which is the point itself when no earlier one does; UINT32_MAX for a point `used` does
// not mark. The same result for any cut and thread count.
std::vector<std::uint32_t> first_equal_points(std::span<const glm::dvec3> points, std::span<const std::uint8_t> used);

}  // namespace rgbio
