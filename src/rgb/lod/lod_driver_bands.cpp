// The LOD driver's band lists (speed machinery beside the canonical order, canonical_order.h): the
// candidates wait in one list per band, and a band is sorted only when its turn comes, in two halves
// on two cores, merged into a second list reserved with the first (inplace_merge took a buffer of
// half the band from fresh pages each time). So the splits come in the canonical order without a heap
// over every candidate.
#include "rgb/lod/lod_driver.h"

#include <algorithm>

#include "rgb/support/parallel.h"

namespace rgb {

// The current band's list, highest first. A long list in two halves on two cores, then merged into
// the driver's second list, which the two then swap (equal candidates are the same edge queued
// twice, so the order among them does not matter).
void LodDriver::sort_band_list() {
    auto higher = [this](const Candidate& x, const Candidate& y) { return outranks(x, y); };
    const auto middle = band_list_.begin() + static_cast<std::ptrdiff_t>(band_list_.size() / 2);
    if (parallel_blocks(band_list_.size(), 16384) < 2) {
        std::sort(band_list_.begin(), band_list_.end(), higher);
        return;
    }
    parallel_invoke([&] { std::sort(band_list_.begin(), middle, higher); },
                    [&] { std::sort(middle, band_list_.end(), higher); });
    // Not in place: inplace_merge takes a buffer of half the band from the heap each time, megabytes
    // of fresh pages; the second list was reserved and faulted in with the first.
    if (band_list_.size() > merged_.capacity()) stop_room_prefault();
    merged_.resize(band_list_.size());
    std::merge(band_list_.begin(), middle, middle, band_list_.end(), merged_.begin(), higher);
    band_list_.swap(merged_);
}

}  // namespace rgb
