#include "io/formats/exact_weld.h"

#include "io/formats/exact_index.h"
#include "rgb/support/parallel.h"

namespace rgbio {

namespace {

// Buckets by the hash's top bits (ExactIndex's table takes the low ones); small inputs take one.
constexpr int kBucketBits = 8;
constexpr std::size_t kMinPointsPerBucket = 4096;

std::array<double, 3> exact_point(const glm::dvec3& p) { return {p.x, p.y, p.z}; }

}  // namespace

std::vector<std::uint32_t> first_equal_points(std::span<const glm::dvec3> points, std::span<const std::uint8_t> used) {
    const std::size_t n = points.size();
    const int bits = n >= (kMinPointsPerBucket << kBucketBits) ? kBucketBits : n >= 2 * kMinPointsPerBucket ? 4 : 0;
    const std::size_t buckets = std::size_t(1) << bits;
    std::vector<std::uint8_t> bucket(n, 0);  // kBucketBits <= 8
    if (bits > 0)
        rgb::parallel_for(n, std::size_t(1) << 15, [&](std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i)
                bucket[i] = static_cast<std::uint8_t>(exact_hash<3>(exact_point(points[i])) >> (64 - bits));
        });
    // The used points of each bucket, in index order (a counting sort).
    std::vector<std::uint32_t> start(buckets + 1, 0), order;
    for (std::size_t i = 0; i < n; ++i) start[bucket[i] + 1] += used[i] != 0;
    for (std::size_t b = 0; b < buckets; ++b) start[b + 1] += start[b];
    order.resize(start[buckets]);
    std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < n; ++i)
        if (used[i]) order[next[bucket[i]]++] = static_cast<std::uint32_t>(i);
    std::vector<std::uint32_t> first(n, UINT32_MAX);
    rgb::parallel_for(buckets, 1, [&](std::size_t begin, std::size_t end) {
        std::vector<std::uint32_t> first_of_number;
        for (std::size_t b = begin; b < end; ++b) {
            ExactIndex<3> index(start[b + 1] - start[b]);
            first_of_number.clear();
            for (std::uint32_t k = start[b]; k < start[b + 1]; ++k) {
                const std::uint32_t i = order[k];
                bool added = false;
                const std::uint32_t number = index.number(exact_point(points[i]), added);
                if (added) first_of_number.push_back(i);
                first[i] = first_of_number[number];
            }
        }
    });
    return first;
}

}  // namespace rgbio
