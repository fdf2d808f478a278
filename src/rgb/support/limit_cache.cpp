#include "rgb/support/limit_cache.h"

#include <algorithm>
#include <utility>

namespace rgb {

std::size_t LimitCache::slot_in_new(std::uint32_t vertex) const {
    const std::size_t n = entries_.size();
    for (std::size_t i = home(vertex, n);; i = next(i, n)) {
        if (entries_[i].key == key_of(vertex)) return i;
        // Never at 7/8 full when the key is there: an empty slot ends its probe run.
        if (entries_[i].key == kEmpty) return n;
    }
}

std::size_t LimitCache::slot_in_old(std::uint32_t vertex) const {
    std::size_t i = home(vertex, moving_.size());
    while (moving_[i].key != key_of(vertex)) i = next(i, moving_.size());
    return i;
}

glm::dvec3 LimitCache::find(std::uint32_t vertex) const {
    const std::size_t i = slot_in_new(vertex);
    const Entry& e = i < entries_.size() ? entries_[i] : moving_[slot_in_old(vertex)];
    return {e.x, e.y, e.z};
}

void LimitCache::insert(std::uint32_t vertex, const glm::dvec3& limit) {
    move_some(kMovedPerChange);
    if (insert_grows()) grow();
    place(vertex, limit.x, limit.y, limit.z);
    ++size_;
}

void LimitCache::place(std::uint32_t vertex, double x, double y, double z) {
    std::size_t i = home(vertex, entries_.size());
    while (entries_[i].key != kEmpty) i = next(i, entries_.size());
    entries_[i] = {key_of(vertex), x, y, z};
}

void LimitCache::erase(std::uint32_t vertex) {
    move_some(kMovedPerChange);
    const std::size_t i = slot_in_new(vertex);
    if (i < entries_.size()) erase_slot(i);
    else moving_[slot_in_old(vertex)].key = kGone;
    --size_;
}

// Backward-shift deletion: pull later members of the probe run into the hole, so that lookups
// never need tombstones.
void LimitCache::erase_slot(std::size_t i) {
    const std::size_t n = entries_.size();
    for (std::size_t j = next(i, n); entries_[j].key != kEmpty; j = next(j, n)) {
        const std::size_t h = home(entries_[j].key - 1, n);
        // Entry j may fill the hole at i unless its home lies cyclically in (i, j].
        const bool home_between = i <= j ? (h > i && h <= j) : (h > i || h <= j);
        if (!home_between) {
            entries_[i] = entries_[j];
            i = j;
        }
    }
    entries_[i] = Entry{};
}

void LimitCache::grow() {
    move_some(moving_.size());  // done long before, by the pace kMovedPerChange sets
    start_moving_into(entries_.empty() ? 64 : (entries_.size() + entries_.size() / 4 + 15) / 16 * 16);
}

void LimitCache::reserve(std::size_t entries) {
    const std::size_t slots = slots_for(entries);
    if (slots <= entries_.size()) return;
    move_some(moving_.size());
    start_moving_into(slots);
    move_some(moving_.size());
}

void LimitCache::start_moving_into(std::size_t slots) {
    moving_ = std::exchange(entries_, ZeroedVector<Entry>(slots));
    moved_ = 0;
}

void LimitCache::move_some(std::size_t slots) {
    if (moving_.empty()) return;
    const std::size_t end = std::min(moving_.size(), moved_ + slots);
    for (; moved_ < end; ++moved_) {
        Entry& e = moving_[moved_];
        if (e.key == kEmpty || e.key == kGone) continue;
        place(e.key - 1, e.x, e.y, e.z);
        e.key = kGone;
    }
    if (moved_ == moving_.size()) {
        ZeroedVector<Entry>().swap(moving_);
        moved_ = 0;
    }
}

}  // namespace rgb
