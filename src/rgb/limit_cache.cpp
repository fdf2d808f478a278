#include "rgb/limit_cache.h"

#include <utility>

namespace rgb {

std::size_t LimitCache::slot_of(std::uint32_t vertex) const {
    std::size_t i = home(vertex);
    while (entries_[i].key != vertex) i = next(i);
    return i;
}

glm::dvec3 LimitCache::find(std::uint32_t vertex) const {
    const Entry& e = entries_[slot_of(vertex)];
    return {e.x, e.y, e.z};
}

void LimitCache::insert(std::uint32_t vertex, const glm::dvec3& limit) {
    if (8 * (size_ + 1) > 7 * entries_.size()) grow();
    std::size_t i = home(vertex);
    while (entries_[i].key != kEmpty) i = next(i);
    entries_[i] = {vertex, limit.x, limit.y, limit.z};
    ++size_;
}

void LimitCache::erase(std::uint32_t vertex) {
    std::size_t i = slot_of(vertex);
    // Backward-shift deletion: pull later members of the probe run into the hole, so that lookups
    // never need tombstones.
    for (std::size_t j = next(i); entries_[j].key != kEmpty; j = next(j)) {
        const std::size_t h = home(entries_[j].key);
        // Entry j may fill the hole at i unless its home lies cyclically in (i, j].
        const bool home_between = i <= j ? (h > i && h <= j) : (h > i || h <= j);
        if (!home_between) {
            entries_[i] = entries_[j];
            i = j;
        }
    }
    entries_[i] = Entry{};
    --size_;
}

void LimitCache::grow() {
    const std::size_t grown = entries_.empty() ? 64 : (entries_.size() + entries_.size() / 4 + 15) / 16 * 16;
    std::vector<Entry> old = std::exchange(entries_, std::vector<Entry>(grown));
    size_ = 0;
    for (const Entry& e : old)
        if (e.key != kEmpty) insert(e.key, {e.x, e.y, e.z});
}

}  // namespace rgb
