#pragma once
// A hash map from 64-bit cell keys to 32-bit values for the picking index: open addressing with
// linear probing and backward-shift deletion (no tombstones, so lookups stay short however many
// cells come and go), 16 bytes a cell.
#include <cstdint>
#include <vector>

namespace app {

class CellTable {
public:
    static constexpr std::uint32_t kNone = 0xffffffffu;

    // The value of `key`, or kNone.
    std::uint32_t find(std::uint64_t key) const;
    // A reference to the value of `key`, inserted as kNone when absent.
    std::uint32_t& at(std::uint64_t key);
    void erase(std::uint64_t key);
    void clear();
    std::size_t size() const { return size_; }
    std::size_t memory_bytes() const { return entries_.capacity() * sizeof(Entry); }

private:
    static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
    struct Entry {
        std::uint64_t key = kEmpty;
        std::uint32_t value = kNone;
    };
    std::size_t home(std::uint64_t key) const { return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> shift_); }
    std::size_t slot_of(std::uint64_t key) const;
    void grow();

    std::vector<Entry> entries_;  // power-of-two size
    int shift_ = 64;
    std::size_t size_ = 0;
};

}  // namespace app
