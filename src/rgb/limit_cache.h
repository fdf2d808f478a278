#pragma once
// Limit positions p^inf of the vertices that needed one (spec §4.2), keyed by vertex slot: an
// open-addressing table of 28-byte entries, so that the minority of vertices with a known limit is
// all that costs memory (a dense array would add 24 bytes to every vertex). A limit depends only on
// the base mesh, so an entry never goes stale while its vertex lives. The mesh keeps a flag per
// vertex for "cached", so lookups only ever probe for keys that are there: the table can run full
// (up to 7/8) and grow by a quarter, which keeps it between 70% and 88% full (an entry is moved
// about four times in all, cheap beside computing a limit).
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace rgb {

class LimitCache {
public:
    // The caller knows which keys are present (the mesh's flag): find and erase take present keys,
    // insert absent ones, so no probe ever runs to an empty slot at high load.
    glm::dvec3 find(std::uint32_t vertex) const;
    void insert(std::uint32_t vertex, const glm::dvec3& limit);
    void erase(std::uint32_t vertex);
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
    // Runs of 16 consecutive slots stay together (vertices made together are read together, so their
    // entries share cache lines); the runs are scattered over the table (any multiple of 16 long), so
    // no stride of ids clusters.
    std::size_t home(std::uint32_t key) const {
        const std::uint64_t run = (std::uint64_t(std::uint32_t((key >> 4) * 2654435761u)) * (entries_.size() / 16)) >> 32;
        return 16 * run + (key & 15u);
    }
    std::size_t next(std::size_t i) const { return i + 1 == entries_.size() ? 0 : i + 1; }
    std::size_t slot_of(std::uint32_t vertex) const;
    void grow();

    std::vector<Entry> entries_;  // a multiple of 16 long, linear probing
    std::size_t size_ = 0;
};

}  // namespace rgb
