// The limit cache against a plain map: every present key finds its value through growths, while the
// entries move from the table grown from a few at a time, and after erasures in both tables.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <random>
#include <span>
#include <unordered_map>
#include <vector>

#include <gtest/gtest.h>

#include "rgb/support/limit_cache.h"

namespace {

glm::dvec3 value_of(std::uint32_t key) { return {0.5 * key, -1.0 * key, key + 0.25}; }

void expect_all_found(const rgb::LimitCache& cache, const std::unordered_map<std::uint32_t, glm::dvec3>& reference) {
    ASSERT_EQ(cache.size(), reference.size());
    for (const auto& [key, value] : reference) ASSERT_EQ(cache.find(key), value) << "key " << key;
}

// As the mesh uses it: vertices made in runs of consecutive slots get limits, some are removed
// (their slots freed and reused), in waves of growth and shrinking.
TEST(LimitCache, FindsEveryPresentKeyThroughGrowthsAndErasures) {
    rgb::LimitCache cache;
    std::unordered_map<std::uint32_t, glm::dvec3> reference;
    std::vector<std::uint32_t> present;
    std::mt19937 rng(3);
    std::uint32_t next_slot = 0;
    std::size_t checks = 0;
    for (int wave = 0; wave < 6; ++wave) {
        const bool growing = wave % 2 == 0;
        for (int op = 0; op < 30000; ++op) {
            const bool add = present.empty() || (growing ? rng() % 4 != 0 : rng() % 4 == 0);
            if (add) {
                const std::uint32_t key = rng() % 3 == 0 && next_slot > 0 ? next_slot + (rng() % 5) * 7 : next_slot;
                next_slot = key + 1;
                if (reference.count(key) != 0) continue;
                cache.insert(key, value_of(key));
                reference[key] = value_of(key);
                present.push_back(key);
            } else {
                const std::size_t i = rng() % present.size();
                const std::uint32_t key = present[i];
                present[i] = present.back();
                present.pop_back();
                cache.erase(key);
                reference.erase(key);
            }
            if (!present.empty()) {
                const std::uint32_t key = present[rng() % present.size()];
                ASSERT_EQ(cache.find(key), reference[key]) << "key " << key << " after op " << op << " of wave " << wave;
            }
            if (op % 2999 == 0) {
                expect_all_found(cache, reference);
                ++checks;
            }
        }
        expect_all_found(cache, reference);
    }
    EXPECT_GT(checks, 50u);
}

// The table grown from is empty and released before the table grown into is full: the entries
// move a few per insert, fast enough (tables of 64 slots, each growth a quarter larger, rounded up to
// 16; 28 bytes a slot).
TEST(LimitCache, ReleasesTheTableGrownFromBeforeItMustGrowAgain) {
    rgb::LimitCache cache;
    std::uint32_t key = 0;
    std::size_t table = 64;
    for (int growth = 0; growth < 40; ++growth) {
        // Filled to 7/8: the most the table takes before the next insert grows it.
        for (; 8 * (cache.size() + 1) <= 7 * table; ++key) cache.insert(key, value_of(key));
        ASSERT_EQ(cache.memory_bytes(), 28 * table) << "a table of " << table << " slots";
        table = (table + table / 4 + 15) / 16 * 16;
    }
    EXPECT_GT(cache.size(), 300000u);
    for (std::uint32_t k = 0; k < key; k += 97) ASSERT_EQ(cache.find(k), value_of(k));
}

// Reserved for a count, the table takes that many inserts without growing: at 7/8 full, 1000 entries
// need 1143 slots, 1152 as a multiple of 16 (28 bytes a slot). Reserving in the middle of a growth
// keeps every entry found.
TEST(LimitCache, ReservedTableTakesItsCountWithoutGrowing) {
    rgb::LimitCache cache;
    for (std::uint32_t k = 0; k < 57; ++k) cache.insert(k, value_of(k));  // the 57th (> 7/8 of 64) starts a growth
    cache.reserve(1000);
    EXPECT_EQ(cache.memory_bytes(), 28u * 1152);
    for (std::uint32_t k = 57; k < 1000; ++k) cache.insert(k, value_of(k));
    EXPECT_EQ(cache.memory_bytes(), 28u * 1152);
    ASSERT_EQ(cache.size(), 1000u);
    for (std::uint32_t k = 0; k < 1000; ++k) ASSERT_EQ(cache.find(k), value_of(k)) << "key " << k;
    cache.reserve(10);  // less than there is: nothing changes
    EXPECT_EQ(cache.memory_bytes(), 28u * 1152);
    cache.insert(1000, value_of(1000));  // 8 x 1001 <= 7 x 1152: the room left is the rounding's
    EXPECT_EQ(cache.memory_bytes(), 28u * 1152);
}

// The table's memory, which the LOD driver faults in ahead, is the whole table; an empty slot is all
// zero bytes (so a new table is untouched fresh memory), and the encoding that makes it so takes
// every vertex id a mesh can have, the highest included (the two ids above it are never vertices).
TEST(LimitCache, TableMemoryIsTheWholeTableAndZeroWhenEmpty) {
    rgb::LimitCache cache;
    cache.reserve(1000);
    const std::span<std::byte> table = cache.table();
    EXPECT_EQ(table.size(), 28u * 1152);
    EXPECT_TRUE(std::all_of(table.begin(), table.end(), [](std::byte b) { return b == std::byte{0}; }));
    const std::uint32_t highest = 0xfffffffdu;
    for (std::uint32_t k : {0u, 1u, highest}) cache.insert(k, value_of(k));
    for (std::uint32_t k : {0u, 1u, highest}) EXPECT_EQ(cache.find(k), value_of(k)) << "key " << k;
    cache.erase(highest);
    cache.erase(0);
    EXPECT_EQ(cache.find(1), value_of(1));
    EXPECT_EQ(cache.size(), 1u);
}

}  // namespace
