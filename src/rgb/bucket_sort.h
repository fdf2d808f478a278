#pragma once
// Records whose order starts with a vertex id, made straight into one run per vertex, then each run
// sorted on its own. A comparison sort of millions of records misses the cache at every level, and
// sorting a finished array needs a second one (fresh pages, a fault each); here the source is read
// twice in order (to count the runs, then to place each record) and the runs are short (a vertex's
// edges or faces), a fan's hub still taking n log n.
#include <algorithm>
#include <cstddef>
#include <vector>

namespace rgb {

template <class T>
struct BucketRuns {
    std::vector<T> items;
    std::vector<std::size_t> runs;  // bucket k holds items [runs[k], runs[k + 1])
};

// The records for_each(emit) emits as emit(bucket, record), buckets below `buckets`, ordered by
// bucket and by `less` within one (a total order that agrees with the buckets'). for_each is called
// twice and must emit the same records both times.
template <class T, class ForEach, class Less>
BucketRuns<T> sorted_by_bucket(std::size_t buckets, ForEach for_each, Less less) {
    BucketRuns<T> out;
    out.runs.assign(buckets + 1, 0);
    for_each([&](std::size_t bucket, const T&) { ++out.runs[bucket + 1]; });
    for (std::size_t k = 0; k < buckets; ++k) out.runs[k + 1] += out.runs[k];
    out.items.resize(out.runs[buckets]);
    std::vector<std::size_t> next(out.runs.begin(), out.runs.end() - 1);
    for_each([&](std::size_t bucket, const T& x) { out.items[next[bucket]++] = x; });
    for (std::size_t k = 0; k < buckets; ++k)
        std::sort(out.items.begin() + static_cast<std::ptrdiff_t>(out.runs[k]),
                  out.items.begin() + static_cast<std::ptrdiff_t>(out.runs[k + 1]), less);
    return out;
}

}  // namespace rgb
