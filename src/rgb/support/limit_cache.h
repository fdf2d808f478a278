#pragma once
// Limit positions p^inf of the vertices that needed one (spec §4.2), keyed by vertex slot: an
// open-addressing table of 28-byte entries, so that the minority of vertices with a known limit is
// all that costs memory (a dense array would add 24 bytes to every vertex). A limit depends only on
// the base mesh, so an entry never goes stale while its vertex lives. The mesh keeps a flag per
// vertex for "cached", so lookups only ever probe for keys that are there: the table can run full
// (up to 7/8) and grow by a quarter, which keeps it between 70% and 88% full.
//
// Growing moves the entries a few at a time: the table grown into takes the inserts while every
// insert and erase also moves the next kMovedPerChange slots of the table grown from, which empties
// it well before the new one is full (a quarter more room is 0.22 of the old size in inserts, and
// moving the old size takes a fifth of that at kMovedPerChange = 8). So no single insert rehashes
// the whole table: that took 1-6 ms at 130k entries (3.8M triangles), in the middle of a brush
// stroke's frame, and grows with the mesh.
#include <cstddef>
#include <cstdint>
#include <span>

#include <glm/vec3.hpp>

#include "rgb/support/zeroed_vector.h"

namespace rgb {

class LimitCache {
public:
    // The caller knows which keys are present (the mesh's flag): find and erase take present keys,
    // insert absent ones, so no probe of the table being filled ever runs to an empty slot at high load.
    glm::dvec3 find(std::uint32_t vertex) const;
    // Asks the processor for the slot where a probe for `vertex` starts, ahead of a find or insert.
    void prefetch(std::uint32_t vertex) const {
        if (!entries_.empty()) __builtin_prefetch(&entries_[home(vertex, entries_.size())]);
    }
    void insert(std::uint32_t vertex, const glm::dvec3& limit);
    // Whether the next insert, or reserving room for `entries`, moves the table (table() to another).
    bool insert_grows() const { return 8 * (size_ + 1) > 7 * entries_.size(); }
    bool reserve_grows(std::size_t entries) const { return slots_for(entries) > entries_.size(); }
    void erase(std::uint32_t vertex);
    // Room for `entries` in all without growing (a restore knows its count: growing step by step
    // moved every entry about four times over). Moves any growth under way to its end and rehashes
    // into the larger table at once, so it is for loading, not for a frame.
    void reserve(std::size_t entries);
    // The table's memory (for Prefault: a reserved table is untouched until filled, and its inserts
    // land all over it).
    std::span<std::byte> table() { return std::as_writable_bytes(std::span(entries_)); }
    std::size_t size() const { return size_; }
    std::size_t memory_bytes() const { return (entries_.size() + moving_.size()) * sizeof(Entry); }

    // Slots of the table grown from that each insert and erase moves while a growth is under way.
    static constexpr std::size_t kMovedPerChange = 8;

private:
#pragma pack(push, 4)
    // 28 bytes rather than 32: the doubles need no 8-byte alignment on the targets we build for.
    // The key is the vertex + 1, so that an empty slot is all zeros: a new table comes from fresh pages
    // untouched rather than written through (12 MB for a budget of 1.5M triangles).
    struct Entry {
        std::uint32_t key = kEmpty;
        double x = 0, y = 0, z = 0;
    };
#pragma pack(pop)
    static constexpr std::uint32_t kEmpty = 0;
    // In the table grown from: an entry moved or erased. Lookups there never stop before their key,
    // so a hole needs no backward shift; it is never filled again.
    static constexpr std::uint32_t kGone = 0xffffffffu;
    static std::uint32_t key_of(std::uint32_t vertex) { return vertex + 1; }
    // Runs of 16 consecutive slots stay together (vertices made together are read together, so their
    // entries share cache lines); the runs are scattered over the table (any multiple of 16 long), so
    // no stride of ids clusters.
    static std::size_t home(std::uint32_t key, std::size_t table_size) {
        const std::uint64_t run = (std::uint64_t(std::uint32_t((key >> 4) * 2654435761u)) * (table_size / 16)) >> 32;
        return 16 * run + (key & 15u);
    }
    static std::size_t next(std::size_t i, std::size_t table_size) { return i + 1 == table_size ? 0 : i + 1; }
    // The fewest slots, a multiple of 16, that hold `entries` at 7/8 full.
    static std::size_t slots_for(std::size_t entries) { return ((8 * entries + 6) / 7 + 15) / 16 * 16; }
    // The slot of `vertex` in entries_, or entries_.size() if it is not there (then it is in moving_).
    std::size_t slot_in_new(std::uint32_t vertex) const;
    // The slot of `vertex` in moving_, where it must be.
    std::size_t slot_in_old(std::uint32_t vertex) const;
    void place(std::uint32_t vertex, double x, double y, double z);
    void erase_slot(std::size_t i);
    void grow();
    // Makes entries_ an empty table of `slots` and the table it was the one to move from.
    void start_moving_into(std::size_t slots);
    // Moves up to `slots` more slots of moving_ into entries_ (all when asked for its size).
    void move_some(std::size_t slots);

    ZeroedVector<Entry> entries_;  // a multiple of 16 long, linear probing
    ZeroedVector<Entry> moving_;   // the table grown from, while its entries move; else empty
    std::size_t moved_ = 0;       // slots of moving_ done
    std::size_t size_ = 0;        // entries in both
};

}  // namespace rgb
