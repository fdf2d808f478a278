#pragma once
// Limit positions p^inf of the vertices that needed one (spec §4.2), keyed by vertex slot: an
// open-addressing table of 28-byte entries, so that the minority of vertices with a known limit is
// all that costs memory (a dense array would add 24 bytes to every vertex). A limit depends only on
// the base mesh, so an entry never goes stale while its vertex lives.
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

namespace rgb {

class LimitCache {
public:
    std::optional<glm::dvec3> find(std::uint32_t vertex) const;
    bool contains(std::uint32_t vertex) const { return slot_of(vertex) != kAbsent; }
    void insert(std::uint32_t vertex, const glm::dvec3& limit);  // no-op if present
    void erase(std::uint32_t vertex);
    void clear();
    std::size_t size() const { return size_; }
    std::size_t memory_bytes() const { return entries_.size() * sizeof(Entry); }

private:
#pragma pack(push, 4)
    // 28 bytes rather than 32: the doubles need no 8-byte alignment on the targets we build for.
    struct Entry {
        std::uint32_t key = kEmpty;
        double x = 0, y = 0, z = 0;
    };
#pragma pack(pop)
    static constexpr std::uint32_t kEmpty = 0xffffffffu;
    static constexpr std::size_t kAbsent = static_cast<std::size_t>(-1);
    // Runs of 16 consecutive slots stay together (vertices made together are read together, so their
    // entries share cache lines); the runs themselves are scattered, so no stride of ids clusters.
    std::size_t home(std::uint32_t key) const {
        return ((std::size_t((key >> 4) * 2654435761u) << 4) | (key & 15u)) & (entries_.size() - 1);
    }
    std::size_t slot_of(std::uint32_t vertex) const;
    void grow();

    std::vector<Entry> entries_;  // power-of-two size, linear probing
    std::size_t size_ = 0;
};

}  // namespace rgb
