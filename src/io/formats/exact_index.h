#pragma once
// Numbers a stream of points (N doubles each) by exact value: a point equal to an earlier one
// (compared as doubles, so +0 and -0 are one) gets that one's number; a new point the next number.
// An open-addressing table over flat arrays: welding a million-triangle file's three million corners
// must cost little next to reading it.
#include <array>
#include <bit>
#include <cstdint>
#include <vector>

namespace rgbio {

// A hash of a point's exact value: equal points (+0 and -0 alike) hash alike.
template <std::size_t N>
std::size_t exact_hash(const std::array<double, N>& p) {
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    for (double x : p) {
        // + 0.0 makes -0 into +0, which compares equal and must land in the same slot.
        h ^= std::bit_cast<std::uint64_t>(x + 0.0);
        h *= 0xBF58476D1CE4E5B9ull;
        h ^= h >> 31;
    }
    return static_cast<std::size_t>(h);
}

template <std::size_t N>
class ExactIndex {
public:
    using Point = std::array<double, N>;
    static constexpr std::uint32_t kEmpty = UINT32_MAX;

    explicit ExactIndex(std::size_t expected = 0) { rehash(std::bit_ceil(std::max<std::size_t>(16, 2 * expected))); }

    // The point's number; `added` says whether it is new.
    std::uint32_t number(const Point& p, bool& added) {
        if (2 * (points_.size() + 1) > slots_.size()) rehash(2 * slots_.size());
        std::size_t slot = hash(p) & (slots_.size() - 1);
        for (;; slot = (slot + 1) & (slots_.size() - 1)) {
            const std::uint32_t id = slots_[slot];
            if (id == kEmpty) break;
            if (points_[id] == p) {
                added = false;
                return id;
            }
        }
        added = true;
        slots_[slot] = static_cast<std::uint32_t>(points_.size());
        points_.push_back(p);
        return slots_[slot];
    }
    const std::vector<Point>& points() const { return points_; }

private:
    static std::size_t hash(const Point& p) { return exact_hash<N>(p); }
    void rehash(std::size_t size) {
        slots_.assign(size, kEmpty);
        for (std::uint32_t id = 0; id < points_.size(); ++id) {
            std::size_t slot = hash(points_[id]) & (size - 1);
            while (slots_[slot] != kEmpty) slot = (slot + 1) & (size - 1);
            slots_[slot] = id;
        }
    }
    std::vector<std::uint32_t> slots_;
    std::vector<Point> points_;
};

}  // namespace rgbio
