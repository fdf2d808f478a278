// The hierarchy evaluator's cache table (rgb/support/key_table.h): every key stored is found with its
// value through growth, a key stored twice keeps its first value, absent keys are not found, and a
// cleared table is empty and usable again, also after growing past the size it keeps.
#include <cstdint>

#include <gtest/gtest.h>

#include "rgb/support/key_table.h"

namespace rgbtest {
namespace {

struct PairKey {
    std::uint32_t a = 0, b = 0;
    friend bool operator==(const PairKey&, const PairKey&) = default;
};
// A poor hash on purpose (every four keys share a home slot), so that the probing is tested too.
struct PoorPairHash {
    std::size_t operator()(const PairKey& k) const noexcept { return static_cast<std::size_t>((k.a / 4) * 0x9e3779b97f4a7c15ull); }
};

TEST(KeyTable, FindsWhatWasStoredThroughGrowthAndClearing) {
    rgb::KeyTable<PairKey, PoorPairHash, double> table;
    EXPECT_EQ(table.find({1, 2}), nullptr);
    const std::uint32_t n = 3 * rgb::KeyTable<PairKey, PoorPairHash, double>::kKeptSlots / 4;  // grows past what clear keeps
    for (int round = 0; round < 2; ++round) {
        for (std::uint32_t i = 0; i < n; ++i) table.insert({i, i ^ 5u}, 0.5 * i);
        for (std::uint32_t i = 0; i < n; i += 7) table.insert({i, i ^ 5u}, -1.0);  // already there: kept
        EXPECT_EQ(table.size(), n);
        for (std::uint32_t i = 0; i < n; ++i) {
            const double* value = table.find({i, i ^ 5u});
            ASSERT_NE(value, nullptr) << i;
            EXPECT_EQ(*value, 0.5 * i);
            EXPECT_EQ(table.find({i, i ^ 6u}), nullptr);
        }
        EXPECT_EQ(table.find({n, n ^ 5u}), nullptr);
        table.clear();
        EXPECT_EQ(table.size(), 0u);
        EXPECT_EQ(table.find({3, 6}), nullptr);
    }
}

}  // namespace
}  // namespace rgbtest
