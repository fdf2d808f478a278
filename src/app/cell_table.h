#pragma once
// A hash map from 64-bit cell keys to 32-bit values for the picking index: open addressing with
// linear probing, 16 bytes a cell. A cell whose value becomes kNone stays until the table is rebuilt
// without such cells, which happens when they are half of it (so lookups stay short however many
// cells come and go).
#include <cstdint>
#include <vector>

namespace app {

class CellTable {
public:
    static constexpr std::uint32_t kNone = 0xffffffffu;

    // The value of `key`, or kNone.
    std::uint32_t find(std::uint64_t key) const;
    // Sets the value of `key` to change(old value) (kNone when absent; kNone empties the cell), with
    // one probe.
    template <class Change>
    void update(std::uint64_t key, Change&& change) {
        std::size_t i = slot_of(key);
        const std::uint32_t before = i == entries_.size() ? kNone : entries_[i].value;
        const std::uint32_t after = change(before);
        if (i == entries_.size()) {
            if (after == kNone) return;
            i = insert_empty(key);
        }
        entries_[i].value = after;
        if (before == kNone && after != kNone) --emptied_;
        if (before != kNone && after == kNone && 2 * ++emptied_ > size_ && size_ > 1024) rebuild(entries_.size());
    }
    void clear();
    std::size_t memory_bytes() const { return entries_.capacity() * sizeof(Entry); }

private:
    static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
    struct Entry {
        std::uint64_t key = kEmpty;
        std::uint32_t value = kNone;
    };
    std::size_t home(std::uint64_t key) const { return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> shift_); }
    std::size_t slot_of(std::uint64_t key) const;
    // Adds `key` with the value kNone (growing first if needed) and returns its slot.
    std::size_t insert_empty(std::uint64_t key);
    // Rehashes the cells with a value into a table of `capacity` entries.
    void rebuild(std::size_t capacity);

    std::vector<Entry> entries_;  // power-of-two size
    int shift_ = 64;
    std::size_t size_ = 0;     // entries with a key
    std::size_t emptied_ = 0;  // of those, entries whose value is kNone
};

}  // namespace app
