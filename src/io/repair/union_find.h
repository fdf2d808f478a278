#pragma once
// Disjoint sets over 0..n-1 (path halving), for grouping triangle corners into fans. 32-bit parents:
// three per triangle, so at 6M triangles 8-byte ones were 150 MB of fresh pages.
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <vector>

namespace rgbio {

class UnionFind {
public:
    explicit UnionFind(std::size_t n) {
        if (n > UINT32_MAX) throw std::length_error("too many triangle corners to group into fans");
        parent_.resize(n);
        std::iota(parent_.begin(), parent_.end(), std::uint32_t(0));
    }
    std::uint32_t find(std::uint32_t x) {
        while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
        return x;
    }
    void unite(std::uint32_t x, std::uint32_t y) { parent_[find(x)] = find(y); }

private:
    std::vector<std::uint32_t> parent_;
};

}  // namespace rgbio
