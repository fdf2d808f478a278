#pragma once
// The canonical order of the LOD driver (docs/requests.md "What a request means": a budget; spec §3.3), as
// the definition states it. The speed machinery that walks it fast is in lod_driver*.cpp.
//
// Every possible split of the hierarchy is an edge of some uniform level Σk, named by the vertex it
// would insert (its midpoint). Its key, a 64-bit number, is
//   1. the half-octave band of its criterion value (by default the edge's length in the uniform
//      Loop mesh of its level): floor(2 log2 value), biased to 1..65535 in the top 16 bits;
//   2. then the Morton order of its base-space midpoint in the base mesh's bounding box, 16 bits
//      per axis interleaved (x highest) in the low 48 bits;
//   3. lowered to the keys of its two endpoints, so that no vertex outranks a vertex it needs (a base
//      vertex's key is the largest there is).
// Key 0 means "not wanted": the value is not above the threshold, or the edge is at the level cap.
// Between equal keys, the base-space midpoint decides, by x, then y, then z. Two different edges
// with the same midpoint (their ends coincide in base space: a UV seam stored as two vertex copies, as
// glTF exporters write it, or a polygon soup) are told apart by what surrounds them, never by storage:
// their ends' base-space positions, then the vertices opposite them in the uniform mesh of their level
// (the corners of the triangles on either side), each list greatest first (surroundings_come_before).
// Only edges whose triangles coincide too (a face stored twice) stay equal.
//
// A run's result is the minimal RGB mesh holding every wanted vertex whose key is above a threshold,
// with the lowest threshold that keeps the mesh within the budget: the driver splits in this order,
// highest first, and stops before the split that would cross the budget. All of it is a function of
// the hierarchy (base-space positions, levels, values of uniform meshes): no storage order or history
// reaches it.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <tuple>
#include <vector>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include "rgb/lod/half_octave.h"

namespace rgb {

// A base vertex's key: above every split's, so that a split's key is never lowered by it.
inline constexpr std::uint64_t kBaseVertexKey = std::numeric_limits<std::uint64_t>::max();

// The criterion's band: half octaves of the value, biased to 1..65535 (0 is kept for "not wanted").
inline std::uint64_t value_band(double value) {
    if (!(value > 0.0)) return 1;
    if (!std::isfinite(value)) return 65535;
    return static_cast<std::uint64_t>(std::clamp(half_octave(value), -32767L, 32767L) + 32768L);
}

// Each bit b of a byte moved to bit 3b (Morton interleaving), for the bytes of a grid coordinate.
inline constexpr std::array<std::uint32_t, 256> kSpreadByte = [] {
    std::array<std::uint32_t, 256> spread{};
    for (std::uint32_t byte = 0; byte < 256; ++byte)
        for (std::uint32_t bit = 0; bit < 8; ++bit) spread[byte] |= ((byte >> bit) & 1u) << (3 * bit);
    return spread;
}();

// The base mesh's bounding box mapped onto the 16-bit grid of the Morton order.
struct MortonFrame {
    static constexpr int kBitsPerAxis = 16;
    glm::dvec3 lo{0.0}, scale{1.0};

    static MortonFrame of_box(const glm::dvec3& lo, const glm::dvec3& hi) {
        MortonFrame frame;
        frame.lo = lo;
        frame.scale = double((1 << kBitsPerAxis) - 1) / glm::max(hi - lo, glm::dvec3(1e-300));
        return frame;
    }
    // The grid coordinate of a cell position: clamped to [0, 65535] (a point on or past the box's
    // far side in the last cell), then truncated.
    static std::uint32_t grid(double cell) { return static_cast<std::uint32_t>(std::min(std::max(0.0, cell), 65535.0)); }
    // The Morton code of a base-space point (x in the highest bit of each triple): the three
    // coordinates' low bytes interleaved into the low 24 bits, their high bytes into the 24 above.
    // Per byte from a table: a key is computed for every edge a split makes.
    std::uint64_t code(const glm::dvec3& point) const {
        const std::uint32_t x = grid((point.x - lo.x) * scale.x), y = grid((point.y - lo.y) * scale.y),
                            z = grid((point.z - lo.z) * scale.z);
        const std::uint32_t low = kSpreadByte[x & 0xff] << 2 | kSpreadByte[y & 0xff] << 1 | kSpreadByte[z & 0xff];
        const std::uint32_t high = kSpreadByte[x >> 8] << 2 | kSpreadByte[y >> 8] << 1 | kSpreadByte[z >> 8];
        return std::uint64_t(high) << 24 | low;
    }
};

// The key of a wanted split (steps 1-3 above) from its value, its base-space midpoint and the lesser
// of its endpoints' keys.
inline std::uint64_t split_key(const MortonFrame& frame, double value, const glm::dvec3& midpoint, std::uint64_t ends_key) {
    return std::min((value_band(value) << 48) | frame.code(midpoint), ends_key);
}

// Whether the split (key x, base-space midpoint mx) comes before (y, my): the higher key, and between
// equal keys the greater midpoint by x, y, z.
inline bool comes_before(std::uint64_t x, const glm::dvec3& mx, std::uint64_t y, const glm::dvec3& my) {
    if (x != y) return x > y;
    return std::tie(mx.x, mx.y, mx.z) > std::tie(my.x, my.y, my.z);
}

// What surrounds a split in base space, for ties of key and midpoint: its two ends and the vertices
// opposite it in the uniform mesh of its level (one on the boundary), each list greatest first.
struct SplitSurroundings {
    std::vector<std::tuple<double, double, double>> ends, opposite;
};

inline SplitSurroundings split_surroundings(const glm::dvec3& end_a, const glm::dvec3& end_b, std::span<const glm::dvec3> opposite) {
    auto greatest_first = [](std::vector<std::tuple<double, double, double>>& points) { std::sort(points.rbegin(), points.rend()); };
    SplitSurroundings s;
    s.ends = {{end_a.x, end_a.y, end_a.z}, {end_b.x, end_b.y, end_b.z}};
    for (const glm::dvec3& p : opposite) s.opposite.emplace_back(p.x, p.y, p.z);
    greatest_first(s.ends);
    greatest_first(s.opposite);
    return s;
}

// Whether a split with surroundings x comes before one with y (same key and midpoint): the greater
// ends, then the greater opposite vertices (a longer list first where one is the start of the other).
inline bool surroundings_come_before(const SplitSurroundings& x, const SplitSurroundings& y) {
    if (x.ends != y.ends) return x.ends > y.ends;
    return x.opposite > y.opposite;
}

}  // namespace rgb
