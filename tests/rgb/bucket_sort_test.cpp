// rgb/support/bucket_sort.h: the same order as a full sort of the same records, whatever the order they come
// in and however the buckets are cut into blocks; runs that say where each bucket's records are; a
// long run (a fan's hub); every run visited once, sorted.
#include <algorithm>
#include <cstdint>
#include <functional>
#include <random>
#include <span>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "rgb/support/bucket_sort.h"

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

auto emitting(const std::vector<Record>& records) {
    return [&records](const auto& emit) {
        for (const Record& r : records) emit(std::get<0>(r), r);
    };
}

TEST(BucketSort, GivesTheOrderOfAFullSort) {
    // 200k buckets: several blocks on a machine with more than one core.
    for (const auto& [buckets, count] : {std::pair{1000u, 20000u}, std::pair{200000u, 300000u}}) {
        const std::vector<Record> records = shuffled_records(buckets, count, 10, buckets);
        std::vector<Record> expected = records;
        std::sort(expected.begin(), expected.end());
        EXPECT_EQ(rgb::sorted_by_bucket<Record>(buckets, emitting(records), std::less<Record>()), expected) << buckets << " buckets";
    }
}

TEST(BucketSort, RunsHoldEachBucketsRecordsAndEachIsVisitedOnceSorted) {
    const std::uint32_t buckets = 50;
    const std::vector<Record> records = shuffled_records(buckets, 3000, 4, 7);
    const std::vector<std::size_t> runs = rgb::bucket_runs(buckets, emitting(records));
    ASSERT_EQ(runs.size(), buckets + 1u);
    EXPECT_EQ(runs.front(), 0u);
    EXPECT_EQ(runs.back(), records.size());
    std::vector<Record> items(runs.back());
    std::vector<int> visits(buckets, 0);
    rgb::place_in_buckets(std::span<const std::size_t>(runs), emitting(records), std::less<Record>(), items.data(),
                          [&](std::size_t k, std::span<const Record> run) {
                              ++visits[k];
                              EXPECT_EQ(run.data(), items.data() + runs[k]);
                              EXPECT_TRUE(std::is_sorted(run.begin(), run.end()));
                          });
    for (std::uint32_t k = 0; k < buckets; ++k) {
        EXPECT_EQ(visits[k], 1) << "bucket " << k;
        const auto in_bucket = static_cast<std::size_t>(
            std::count_if(records.begin(), records.end(), [k](const Record& r) { return std::get<0>(r) == k; }));
        EXPECT_EQ(runs[k + 1] - runs[k], in_bucket) << "bucket " << k;
        for (std::size_t i = runs[k]; i < runs[k + 1]; ++i) EXPECT_EQ(std::get<0>(items[i]), k);
    }
    // A quarter of all the records went to bucket 0, the hub.
    EXPECT_GE(runs[1], records.size() / 4);
}

TEST(BucketSort, EmptyBucketsAndNoRecords) {
    const std::vector<Record> none;
    EXPECT_TRUE(rgb::sorted_by_bucket<Record>(3, emitting(none), std::less<Record>()).empty());
    EXPECT_EQ(rgb::bucket_runs(3, emitting(none)), (std::vector<std::size_t>{0, 0, 0, 0}));
    const std::vector<Record> last_only{{2, 1, 0}, {2, 0, 1}};
    EXPECT_EQ(rgb::sorted_by_bucket<Record>(3, emitting(last_only), std::less<Record>()), (std::vector<Record>{{2, 0, 1}, {2, 1, 0}}));
    EXPECT_EQ(rgb::bucket_runs(3, emitting(last_only)), (std::vector<std::size_t>{0, 0, 0, 2}));
}

}  // namespace
