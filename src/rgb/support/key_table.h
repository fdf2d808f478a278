#pragma once
// A map from small trivially copyable keys to values that only grows: open addressing with linear
// probing in one array, a power-of-two size kept at most half full. The hierarchy evaluator's caches
// use it: they hold millions of entries when a whole mesh's error is measured (rgbsub lods), and
// std::unordered_map spent two thirds of that time chasing and allocating its nodes.
#include <algorithm>
#include <cstddef>
#include <vector>

namespace rgb {

template <class Key, class Hash, class Value>
class KeyTable {
public:
    // The value stored for `key`, or null. The pointer lasts until the next insert.
    const Value* find(const Key& key) const {
        if (slots_.empty()) return nullptr;
        const std::size_t mask = slots_.size() - 1;
        for (std::size_t s = Hash{}(key) & mask;; s = (s + 1) & mask) {
            const Slot& slot = slots_[s];
            if (!slot.used) return nullptr;
            if (slot.key == key) return &slot.value;
        }
    }
    // Stores `value` for `key` unless the table has a value for it already.
    void insert(const Key& key, const Value& value) {
        if (2 * (size_ + 1) > slots_.size()) grow(std::max<std::size_t>(64, 2 * slots_.size()));
        if (place(key, value)) ++size_;
    }
    std::size_t size() const { return size_; }
    // Empties the table, keeping its memory for the next use (no fresh pages to fault in) up to
    // kKeptSlots: a table grown larger (one base face of a very fine mesh) is let go, so that emptying
    // it does not cost every later use of a small one its whole size.
    void clear() {
        if (slots_.size() > kKeptSlots) {
            slots_ = {};
        } else {
            std::fill(slots_.begin(), slots_.end(), Slot{});
        }
        size_ = 0;
    }
    static constexpr std::size_t kKeptSlots = std::size_t(1) << 17;

private:
    struct Slot {
        Key key{};
        Value value{};
        bool used = false;
    };
    bool place(const Key& key, const Value& value) {
        const std::size_t mask = slots_.size() - 1;
        for (std::size_t s = Hash{}(key) & mask;; s = (s + 1) & mask) {
            Slot& slot = slots_[s];
            if (slot.used && slot.key == key) return false;
            if (!slot.used) {
                slot = Slot{key, value, true};
                return true;
            }
        }
    }
    void grow(std::size_t slots) {
        std::vector<Slot> old(slots);
        old.swap(slots_);
        for (const Slot& slot : old)
            if (slot.used) place(slot.key, slot.value);
    }

    std::vector<Slot> slots_;
    std::size_t size_ = 0;
};

}  // namespace rgb
