#pragma once
// Which vertex of a mesh being restored sits at a given address (surface_point.h): a hash table of
// canonical addresses with one region per base face, so that the lookups of one neighbourhood (a
// vertex's stencil and ring lie in its base face or the next) stay within a few kilobytes, and
// building and querying it is linear in the number of vertices.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "rgb/mesh/surface_point.h"

namespace rgb {

class AddressIndex {
public:
    static constexpr std::uint32_t kAbsent = 0xffffffffu;

    // points[i] is vertex i's canonical address (canonical()), valid for a base mesh with
    // num_base_faces faces.
    AddressIndex(std::span<const SurfacePoint> points, std::size_t num_base_faces);

    // The first vertex whose address is an earlier vertex's, if any (it is then not in the index).
    std::optional<std::uint32_t> first_repeat() const { return first_repeat_; }
    // The vertex at canonical address p, or kAbsent.
    std::uint32_t find(const SurfacePoint& p) const {
        const std::size_t begin = region_start_[p.face], end = region_start_[p.face + 1];
        if (begin == end) return kAbsent;
        const std::uint32_t a1l = a1_level(p);
        for (std::size_t s = home(p, begin, end);; s = s + 1 == end ? begin : s + 1) {
            const Entry& e = entries_[s];
            if (e.vertex == kAbsent) return kAbsent;
            if (e.a0 == p.a[0] && e.a1_level == a1l) return e.vertex;
        }
    }

private:
    struct Entry {
        std::uint32_t a0 = 0, a1_level = 0;  // a1 in bits 0-20, the level above
        std::uint32_t vertex = kAbsent;
    };
    static std::uint32_t a1_level(const SurfacePoint& p) { return p.a[1] | static_cast<std::uint32_t>(p.level) << 21; }
    // The first slot of p's probe sequence within its face's region [begin, end).
    static std::size_t home(const SurfacePoint& p, std::size_t begin, std::size_t end) {
        std::uint32_t h = p.a[0] * 0x9e3779b1u ^ a1_level(p) * 0x85ebca77u;
        h ^= h >> 15;
        h *= 0x2c1b3c6du;
        h ^= h >> 13;
        // Lemire's range reduction: uniform over a region of any size, without a division.
        return begin + static_cast<std::size_t>((std::uint64_t(h) * (end - begin)) >> 32);
    }

    std::vector<std::uint32_t> region_start_;  // base face f's slots are [region_start_[f], region_start_[f + 1])
    std::vector<Entry> entries_;
    std::optional<std::uint32_t> first_repeat_;
};

}  // namespace rgb
