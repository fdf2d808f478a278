#include "app/cell_table.h"

#include <bit>
#include <utility>

namespace app {

std::size_t CellTable::slot_of(std::uint64_t key) const {
    if (entries_.empty()) return entries_.size();
    const std::size_t mask = entries_.size() - 1;
    for (std::size_t i = home(key);; i = (i + 1) & mask) {
        if (entries_[i].key == key) return i;
        if (entries_[i].key == kEmpty) return entries_.size();
    }
}

std::uint32_t CellTable::find(std::uint64_t key) const {
    const std::size_t i = slot_of(key);
    return i == entries_.size() ? kNone : entries_[i].value;
}

std::uint32_t& CellTable::at(std::uint64_t key) {
    const std::size_t found = slot_of(key);
    if (found != entries_.size()) return entries_[found].value;
    // Keep the load at most 1/2 so probe runs stay short.
    if (2 * (size_ + 1) > entries_.size()) grow();
    const std::size_t mask = entries_.size() - 1;
    std::size_t i = home(key);
    while (entries_[i].key != kEmpty) i = (i + 1) & mask;
    entries_[i] = {key, kNone};
    ++size_;
    return entries_[i].value;
}

void CellTable::erase(std::uint64_t key) {
    std::size_t i = slot_of(key);
    if (i == entries_.size()) return;
    // Backward shift: later members of the probe run move into the hole unless their home lies
    // cyclically in (hole, member].
    const std::size_t mask = entries_.size() - 1;
    for (std::size_t j = (i + 1) & mask; entries_[j].key != kEmpty; j = (j + 1) & mask) {
        const std::size_t h = home(entries_[j].key);
        const bool home_between = i <= j ? (h > i && h <= j) : (h > i || h <= j);
        if (!home_between) {
            entries_[i] = entries_[j];
            i = j;
        }
    }
    entries_[i] = Entry{};
    --size_;
}

void CellTable::clear() {
    entries_.clear();
    shift_ = 64;
    size_ = 0;
}

void CellTable::grow() {
    const std::size_t capacity = entries_.empty() ? 1024 : 2 * entries_.size();
    std::vector<Entry> old = std::exchange(entries_, std::vector<Entry>(capacity));
    shift_ = 64 - std::countr_zero(capacity);
    size_ = 0;
    for (const Entry& e : old)
        if (e.key != kEmpty) at(e.key) = e.value;
}

}  // namespace app
