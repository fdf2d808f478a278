#pragma once
// Lists of items by band (the LOD driver's candidates by the top bits of their keys), appended to
// one at a time and taken whole, a band at a time. Items live in fixed chunks from a shared pool, and
// the chunks of a band taken go back to the pool: the memory the lists touch is about the most they
// hold at once, not the sum of every list's doublings, and a run that knows how many it will hold can
// have that room faulted in ahead (reserve). Only the bands used have a list: a run touches a dozen of
// its 65536 bands, whose list headers written at once were 2 MiB of page faults.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "rgb/support/zeroed_vector.h"

namespace rgb {

template <class Item>
class BandLists {
public:
    explicit BandLists(std::size_t bands) : list_of_band_(bands) {}

    std::size_t num_bands() const { return list_of_band_.size(); }
    bool empty(std::size_t band) const { return size(band) == 0; }
    std::size_t size(std::size_t band) const {
        if (list_of_band_[band] == 0) return 0;
        const Band& b = lists_[list_of_band_[band] - 1];
        return b.chunks.empty() ? 0 : (b.chunks.size() - 1) * kChunk + b.fill;
    }

    // Items the pool has room for, held or free.
    std::size_t capacity() const {
        std::size_t items = 0;
        for (const ZeroedVector<Item>& block : blocks_) items += block.size();
        return items;
    }

    void push(std::size_t band, const Item& item) {
        Band& b = list(band);
        if (b.fill == kChunk) {
            b.chunks.push_back(new_chunk());
            b.fill = 0;
        }
        Item* at = b.chunks.back() + b.fill++;
        *at = item;
        // The list is written far from where it is read: ask for the lines ahead of the writes.
        __builtin_prefetch(at + 8, 1);
    }

    // Room in the pool for this many items at once; the memory added for it, untouched so far.
    std::span<std::byte> reserve(std::size_t items) {
        if (items <= free_.size() * kChunk) return {};
        add_block((items - free_.size() * kChunk + kChunk - 1) / kChunk);
        return std::as_writable_bytes(std::span(blocks_.back()));
    }
    // The whole pool's memory, held or free: for a faulting-in that starts again after one stopped
    // part way (a run that begins anew), where reserve finds the room there and returns none.
    std::vector<std::span<std::byte>> memory() {
        std::vector<std::span<std::byte>> spans;
        for (ZeroedVector<Item>& block : blocks_) spans.push_back(std::as_writable_bytes(std::span(block)));
        return spans;
    }

    // The band's items, in the order pushed, into `out` (replacing what it held); the band is empty after.
    template <class Vector>
    void take(std::size_t band, Vector& out) {
        out.clear();
        if (list_of_band_[band] == 0) return;
        Band& b = lists_[list_of_band_[band] - 1];
        out.reserve(size(band));
        for (std::size_t i = 0; i < b.chunks.size(); ++i) {
            const std::size_t n = i + 1 < b.chunks.size() ? kChunk : b.fill;
            out.insert(out.end(), b.chunks[i], b.chunks[i] + n);
            free_.push_back(b.chunks[i]);
        }
        b = Band();
    }

    void clear() {
        for (Band& b : lists_) {
            for (Item* chunk : b.chunks) free_.push_back(chunk);
            b = Band();
        }
    }

private:
    // 32 KiB of 16-byte items: small enough that the partly filled last chunks of the dozen bands a
    // run fills at once waste little, large enough that taking a chunk is rare.
    static constexpr std::uint32_t kChunk = 2048;
    struct Band {
        std::vector<Item*> chunks;
        std::uint32_t fill = kChunk;  // items in the last chunk; kChunk when there is none
    };

    // The band's list, made at its first push (an index of 0 means none).
    Band& list(std::size_t band) {
        std::uint32_t& index = list_of_band_[band];
        if (index == 0) {
            lists_.emplace_back();
            index = static_cast<std::uint32_t>(lists_.size());
        }
        return lists_[index - 1];
    }

    Item* new_chunk() {
        if (free_.empty()) add_block(std::max<std::size_t>(16, blocks_.size() * 16));
        Item* chunk = free_.back();
        free_.pop_back();
        return chunk;
    }
    void add_block(std::size_t chunks) {
        ZeroedVector<Item>& block = blocks_.emplace_back();
        block.resize(chunks * kChunk);
        // Handed out first to last, so that a faulting-in of the block keeps ahead of its use.
        for (std::size_t i = chunks; i-- > 0;) free_.push_back(block.data() + i * kChunk);
    }

    ZeroedVector<std::uint32_t> list_of_band_;  // 1 + the index of the band's list in lists_, or 0
    std::vector<Band> lists_;
    std::vector<ZeroedVector<Item>> blocks_;
    std::vector<Item*> free_;
};

}  // namespace rgb
