#pragma once
// Records whose order starts with a vertex id, made straight into one run per vertex, then each run
// sorted on its own. A comparison sort of millions of records misses the cache at every level, and
// sorting a finished array needs a second one (fresh pages, a fault each); here the source is read
// twice (to count the runs, then to place each record) and the runs are short (a vertex's edges or
// faces), a fan's hub still taking n log n. In parallel blocks of buckets: each block's thread reads
// the whole source and keeps the records of its own buckets, so that the counting and the placing
// (random writes, the slow part) run on all cores and no thread writes where another does.
#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

#include "rgb/support/parallel.h"

namespace rgb {

// Where each bucket's run starts among the records for_each(emit) emits as emit(bucket, record),
// buckets below `buckets`: bucket k's run is [runs[k], runs[k + 1]), and runs.back() counts them all.
// for_each is called from several threads at once and must emit the same records each time.
template <class ForEach>
std::vector<std::size_t> bucket_runs(std::size_t buckets, const ForEach& for_each) {
    std::vector<std::size_t> runs(buckets + 1, 0);
    parallel_blocks_for(buckets, parallel_blocks(buckets, 1 << 16), [&](std::size_t, std::size_t begin, std::size_t end) {
        for_each([&](std::size_t bucket, const auto&) {
            if (bucket - begin < end - begin) ++runs[bucket + 1];
        });
    });
    for (std::size_t k = 0; k < buckets; ++k) runs[k + 1] += runs[k];
    return runs;
}

// The same records placed into `items` (room for runs.back()) by bucket, each run then sorted by
// `less` (a total order of the records); `visit_run(bucket, run)` after each run is sorted.
template <class T, class ForEach, class Less, class VisitRun>
void place_in_buckets(std::span<const std::size_t> runs, const ForEach& for_each, const Less& less, T* items, const VisitRun& visit_run) {
    const std::size_t buckets = runs.size() - 1;
    parallel_blocks_for(buckets, parallel_blocks(buckets, 1 << 16), [&](std::size_t, std::size_t begin, std::size_t end) {
        std::vector<std::size_t> next(runs.begin() + static_cast<std::ptrdiff_t>(begin), runs.begin() + static_cast<std::ptrdiff_t>(end));
        for_each([&](std::size_t bucket, const T& x) {
            if (bucket - begin < end - begin) items[next[bucket - begin]++] = x;
        });
        for (std::size_t k = begin; k < end; ++k) {
            std::sort(items + runs[k], items + runs[k + 1], less);
            visit_run(k, std::span<const T>(items + runs[k], runs[k + 1] - runs[k]));
        }
    });
}

// Both, into a vector.
template <class T, class ForEach, class Less>
std::vector<T> sorted_by_bucket(std::size_t buckets, const ForEach& for_each, const Less& less) {
    const std::vector<std::size_t> runs = bucket_runs(buckets, for_each);
    std::vector<T> items(runs.back());
    place_in_buckets(std::span<const std::size_t>(runs), for_each, less, items.data(), [](std::size_t, std::span<const T>) {});
    return items;
}

}  // namespace rgb
