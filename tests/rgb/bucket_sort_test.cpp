// sorted_by_bucket (rgb/bucket_sort.h): the same order as a full sort of the same records, whatever
// the order they come in, runs that say where each bucket's records are, and a long run (a fan's hub).
#include <algorithm>
#include <cstdint>
#include <functional>
#include <random>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "rgb/bucket_sort.h"

namespace {

using Record = std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>;  // bucket, then the rest

std::vector<Record> shuffled_records(std::uint32_t buckets, std::size_t count, std::uint32_t hub_share, unsigned seed) {
    std::mt19937 random(seed);
    std::vector<Record> records;
    for (std::uint32_t i = 0; i < count; ++i) {
        // Every hub_share-th record in bucket 0, the others spread; equal buckets with equal second
        // values, told apart by the third, as edges of a vertex are by their triangles.
        const std::uint32_t bucket = i % hub_share == 0 ? 0 : static_cast<std::uint32_t>(random() % buckets);
        records.emplace_back(bucket, static_cast<std::uint32_t>(random() % 7), i);
    }
    std::shuffle(records.begin(), records.end(), random);
    return records;
}

rgb::BucketRuns<Record> bucketed(const std::vector<Record>& records, std::uint32_t buckets) {
    return rgb::sorted_by_bucket<Record>(
        buckets,
        [&](auto&& emit) {
            for (const Record& r : records) emit(std::get<0>(r), r);
        },
        std::less<Record>());
}

TEST(BucketSort, GivesTheOrderOfAFullSort) {
    for (unsigned seed : {1u, 2u, 3u}) {
        const std::vector<Record> records = shuffled_records(1000, 20000, 10, seed);
        std::vector<Record> expected = records;
        std::sort(expected.begin(), expected.end());
        EXPECT_EQ(bucketed(records, 1000).items, expected) << "seed " << seed;
    }
}

TEST(BucketSort, RunsHoldEachBucketsRecords) {
    const std::uint32_t buckets = 50;
    const std::vector<Record> records = shuffled_records(buckets, 3000, 4, 7);
    const rgb::BucketRuns<Record> sorted = bucketed(records, buckets);
    ASSERT_EQ(sorted.runs.size(), buckets + 1u);
    EXPECT_EQ(sorted.runs.front(), 0u);
    EXPECT_EQ(sorted.runs.back(), records.size());
    for (std::uint32_t k = 0; k < buckets; ++k) {
        const auto in_bucket = static_cast<std::size_t>(
            std::count_if(records.begin(), records.end(), [k](const Record& r) { return std::get<0>(r) == k; }));
        EXPECT_EQ(sorted.runs[k + 1] - sorted.runs[k], in_bucket) << "bucket " << k;
        for (std::size_t i = sorted.runs[k]; i < sorted.runs[k + 1]; ++i) EXPECT_EQ(std::get<0>(sorted.items[i]), k);
    }
    // A quarter of all the records went to bucket 0, the hub.
    EXPECT_GE(sorted.runs[1], records.size() / 4);
}

TEST(BucketSort, EmptyBucketsAndNoRecords) {
    const rgb::BucketRuns<Record> none = bucketed({}, 3);
    EXPECT_TRUE(none.items.empty());
    EXPECT_EQ(none.runs, (std::vector<std::size_t>{0, 0, 0, 0}));
    const rgb::BucketRuns<Record> last_only = bucketed({{2, 1, 0}, {2, 0, 1}}, 3);
    EXPECT_EQ(last_only.items, (std::vector<Record>{{2, 0, 1}, {2, 1, 0}}));
    EXPECT_EQ(last_only.runs, (std::vector<std::size_t>{0, 0, 0, 2}));
}

}  // namespace
