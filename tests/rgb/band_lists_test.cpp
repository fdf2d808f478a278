// BandLists against a plain vector per band: random pushes, takes and clears give every band's
// items in the order pushed, and the pool's memory is reused rather than grown.
#include <cstddef>
#include <cstdint>
#include <map>
#include <random>
#include <span>
#include <vector>

#include <gtest/gtest.h>

#include "rgb/lod/band_lists.h"

namespace rgbtest {
namespace {

struct Item {
    std::uint64_t key;
    std::uint32_t a, b;
    bool operator==(const Item&) const = default;
};

TEST(BandLists, MatchesAVectorPerBand) {
    std::mt19937_64 random(11);
    rgb::BandLists<Item> lists(64);
    std::vector<std::vector<Item>> plain(64);
    std::vector<Item> taken;
    for (int round = 0; round < 200; ++round) {
        const int pushes = std::uniform_int_distribution<int>(0, 20000)(random);
        for (int i = 0; i < pushes; ++i) {
            // A few busy bands, as in a driver run, and some stragglers.
            const std::size_t band = random() % 4 ? 30 + random() % 4 : random() % 64;
            const Item item{random(), static_cast<std::uint32_t>(random()), static_cast<std::uint32_t>(i)};
            lists.push(band, item);
            plain[band].push_back(item);
        }
        const std::size_t band = 28 + random() % 8;
        for (std::size_t b = 0; b < 64; ++b) {
            ASSERT_EQ(lists.size(b), plain[b].size());
            ASSERT_EQ(lists.empty(b), plain[b].empty());
        }
        lists.take(band, taken);
        ASSERT_EQ(taken, plain[band]);
        plain[band].clear();
        EXPECT_TRUE(lists.empty(band));
        if (round % 50 == 49) {
            lists.clear();
            for (auto& p : plain) p.clear();
            for (std::size_t b = 0; b < 64; ++b) ASSERT_TRUE(lists.empty(b));
        }
    }
}

// Room reserved for n items takes n pushes into a few bands without more memory; the chunks of a band
// taken serve the next pushes.
TEST(BandLists, ReusesTheChunksOfTakenBands) {
    rgb::BandLists<Item> lists(8);
    const std::span<std::byte> room = lists.reserve(100000);
    EXPECT_GE(room.size(), 100000 * sizeof(Item));
    const std::size_t capacity = lists.capacity();
    EXPECT_EQ(capacity * sizeof(Item), room.size());
    EXPECT_TRUE(lists.reserve(50000).empty());  // there is room already
    // ... which memory() still gives, for a faulting-in that starts again.
    const std::vector<std::span<std::byte>> memory = lists.memory();
    ASSERT_EQ(memory.size(), 1u);
    EXPECT_EQ(memory[0].data(), room.data());
    EXPECT_EQ(memory[0].size(), room.size());
    std::vector<Item> taken;
    for (std::uint32_t round = 0; round < 10; ++round) {
        for (std::uint32_t i = 0; i < 90000; ++i) lists.push(i % 3, Item{round, i, i});
        for (std::size_t b = 0; b < 3; ++b) {
            lists.take(b, taken);
            ASSERT_EQ(taken.size(), 30000u);
            for (std::size_t i = 0; i < taken.size(); ++i) ASSERT_EQ(taken[i], (Item{round, std::uint32_t(3 * i + b), std::uint32_t(3 * i + b)}));
        }
        EXPECT_EQ(lists.capacity(), capacity) << "round " << round;
    }
}

}  // namespace
}  // namespace rgbtest
