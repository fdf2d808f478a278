// The LOD driver's band lists (speed machinery beside the canonical order, canonical_order.h): the
// candidates wait in one list per band, and a band is sorted only when its turn comes, by a radix
// sort of its keys into a second list reserved with the first. So the splits come in the canonical
// order without a heap over every candidate.
#include "rgb/lod/lod_driver.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>

namespace rgb {

namespace {

// A key's low 48 bits a byte at a time: a band's keys share their top 16 (the band).
constexpr int kKeyBytes = 6;
// Shorter lists are sorted by comparison: the radix sort's six tables of counts would cost more.
constexpr std::size_t kShortList = 256;

// The items in descending order of their keys, equal keys in the order they came: a radix sort, a
// byte per pass from the least significant (each pass stable, so the earlier bytes' order holds
// within each byte's buckets), through `spare` (the two swap at each pass). A byte every key shares
// needs no pass. It replaced std::sort with the full comparison (two halves on two cores, then
// merged): a comparison's outcome on keys in no particular order is a branch the processor cannot
// predict, and the sort took 18 of them per candidate; this takes a few sequential passes on one core.
template <class Items>
void sort_by_key_highest_first(Items& items, Items& spare) {
    std::array<std::array<std::uint32_t, 256>, kKeyBytes> counts{};
    for (const auto& item : items)
        for (int byte = 0; byte < kKeyBytes; ++byte) ++counts[byte][(item.key >> (8 * byte)) & 0xff];
    spare.resize(items.size());
    for (int byte = 0; byte < kKeyBytes; ++byte) {
        std::array<std::uint32_t, 256>& next = counts[byte];
        if (std::find(next.begin(), next.end(), items.size()) != next.end()) continue;
        // Each bucket's first place, the highest byte's bucket first.
        std::uint32_t place = 0;
        for (std::size_t value = 256; value-- > 0;) place += std::exchange(next[value], place);
        for (const auto& item : items) spare[next[(item.key >> (8 * byte)) & 0xff]++] = item;
        items.swap(spare);
    }
}

}  // namespace

// The current band's list, highest first: by key, then each run of equal keys (edges whose midpoints
// share a cell of the Morton grid, or keys lowered to their ends') by the full order.
void LodDriver::sort_band_list() {
    auto higher = [this](const Candidate& x, const Candidate& y) { return outranks(x, y); };
    if (band_list_.size() < kShortList) {
        std::sort(band_list_.begin(), band_list_.end(), higher);
        return;
    }
    // The second list was reserved and faulted in with the first; grown, it moves under the thread
    // that faults the room in.
    if (band_list_.size() > band_spare_.capacity()) stop_room_prefault();
    sort_by_key_highest_first(band_list_, band_spare_);
    for (auto run = band_list_.begin(); run != band_list_.end();) {
        const auto end = std::find_if(run + 1, band_list_.end(), [&](const Candidate& c) { return c.key != run->key; });
        if (end - run > 1) std::sort(run, end, higher);
        run = end;
    }
}

}  // namespace rgb
