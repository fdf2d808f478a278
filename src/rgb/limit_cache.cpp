#include "rgb/limit_cache.h"

#include <utility>

namespace rgb {

std::size_t LimitCache::slot_of(std::uint32_t vertex) const {
    if (entries_.empty()) return kAbsent;
    for (std::size_t i = home(vertex);; i = (i + 1) & (entries_.size() - 1)) {
        if (entries_[i].key == vertex) return i;
        if (entries_[i].key == kEmpty) return kAbsent;
    }
}

std::optional<glm::dvec3> LimitCache::find(std::uint32_t vertex) const {
    const std::size_t i = slot_of(vertex);
    if (i == kAbsent) return std::nullopt;
    return glm::dvec3(entries_[i].x, entries_[i].y, entries_[i].z);
}

void LimitCache::insert(std::uint32_t vertex, const glm::dvec3& limit) {
    if (contains(vertex)) return;
    // Keep the load under 3/4 so probes stay short.
    if (4 * (size_ + 1) > 3 * entries_.size()) grow();
    std::size_t i = home(vertex);
    while (entries_[i].key != kEmpty) i = (i + 1) & (entries_.size() - 1);
    entries_[i] = {vertex, limit.x, limit.y, limit.z};
    ++size_;
}

void LimitCache::erase(std::uint32_t vertex) {
    std::size_t i = slot_of(vertex);
    if (i == kAbsent) return;
    // Backward-shift deletion: pull later members of the probe run into the hole, so that lookups
    // never need tombstones.
    const std::size_t mask = entries_.size() - 1;
    for (std::size_t j = (i + 1) & mask; entries_[j].key != kEmpty; j = (j + 1) & mask) {
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

void LimitCache::clear() {
    entries_.clear();
    size_ = 0;
}

void LimitCache::grow() {
    std::vector<Entry> old = std::exchange(entries_, std::vector<Entry>(entries_.empty() ? 64 : 2 * entries_.size()));
    size_ = 0;
    for (const Entry& e : old)
        if (e.key != kEmpty) insert(e.key, {e.x, e.y, e.z});
}

}  // namespace rgb
