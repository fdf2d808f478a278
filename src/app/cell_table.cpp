#include "app/cell_table.h"

#include <algorithm>
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

std::size_t CellTable::insert_empty(std::uint64_t key) {
    // Keep the load at most 1/2 so probe runs stay short; a rebuild drops the emptied cells.
    if (2 * (size_ + 1) > entries_.size()) rebuild(4 * (size_ - emptied_ + 1) > entries_.size() ? 2 * entries_.size() : entries_.size());
    const std::size_t mask = entries_.size() - 1;
    std::size_t i = home(key);
    while (entries_[i].key != kEmpty) i = (i + 1) & mask;
    entries_[i] = {key, kNone};
    ++size_;
    ++emptied_;
    return i;
}

void CellTable::clear() {
    entries_.clear();
    shift_ = 64;
    size_ = 0;
    emptied_ = 0;
}

void CellTable::rebuild(std::size_t capacity) {
    capacity = std::max<std::size_t>(capacity, 1024);
    std::vector<Entry> old = std::exchange(entries_, std::vector<Entry>(capacity));
    shift_ = 64 - std::countr_zero(capacity);
    size_ = 0;
    emptied_ = 0;
    const std::size_t mask = capacity - 1;
    for (const Entry& e : old) {
        if (e.key == kEmpty || e.value == kNone) continue;
        std::size_t i = home(e.key);
        while (entries_[i].key != kEmpty) i = (i + 1) & mask;
        entries_[i] = e;
        ++size_;
    }
}

}  // namespace app
