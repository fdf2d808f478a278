#pragma once
// Disjoint sets over 0..n-1 (path halving), for grouping triangle corners into fans.
#include <cstddef>
#include <numeric>
#include <vector>

namespace rgbio {

class UnionFind {
public:
    explicit UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), std::size_t(0)); }
    std::size_t find(std::size_t x) {
        while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
        return x;
    }
    void unite(std::size_t x, std::size_t y) { parent_[find(x)] = find(y); }

private:
    std::vector<std::size_t> parent_;
};

}  // namespace rgbio
