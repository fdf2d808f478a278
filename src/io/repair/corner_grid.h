#pragma once
// A uniform grid over some of a polygon's corners (the reflex ones, for ear clipping), about one
// cell per corner, with removal, so that an ear test looks only at the corners near the ear that
// can still block it. Only non-empty cells are visited (an ordered set of them), so a long thin ear
// over a region whose corners are all gone costs a few lookups, not its length in cells.
#include <algorithm>
#include <cstdint>
#include <limits>
#include <set>
#include <vector>

#include <glm/vec2.hpp>

namespace rgbio {

class CornerGrid {
public:
    // Holds the corners i of `points` with member[i] != 0; points must outlive the grid.
    CornerGrid(const std::vector<glm::dvec2>& points, const std::vector<std::uint8_t>& member);

    void remove(std::uint32_t corner);
    bool contains(std::uint32_t corner) const { return in_grid_[corner] != 0; }

    // Calls f(corner) for the corners in the cells the triangle abc overlaps (with one cell of margin
    // each side of every row, against rounding) until f returns true; returns the number of
    // non-empty rows, cells and corners visited.
    template <class F>
    std::uint64_t visit(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, F&& f) const;

private:
    static constexpr std::uint32_t kEnd = UINT32_MAX;
    std::uint32_t column_of(double x) const { return static_cast<std::uint32_t>(std::clamp((x - lo_.x) * scale_.x, 0.0, columns_ - 1.0)); }
    std::uint32_t row_of(double y) const { return static_cast<std::uint32_t>(std::clamp((y - lo_.y) * scale_.y, 0.0, rows_ - 1.0)); }
    std::size_t cell(const glm::dvec2& p) const { return std::size_t(row_of(p.y)) * columns_ + column_of(p.x); }
    // The x range of triangle abc within the horizontal slab [y0, y1] (empty: lo > hi).
    static std::pair<double, double> slab_range(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, double y0, double y1);

    glm::dvec2 lo_{0.0}, scale_{1.0};
    std::uint32_t columns_ = 1, rows_ = 1;
    std::vector<std::uint32_t> head_;        // per cell: first corner, or kEnd
    std::set<std::size_t> occupied_;          // the cells with a corner
    std::vector<std::uint32_t> next_, prev_;  // per corner: neighbours in its cell's list
    std::vector<std::uint8_t> in_grid_;
    const std::vector<glm::dvec2>& points_;
};

template <class F>
std::uint64_t CornerGrid::visit(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, F&& f) const {
    const double y_min = std::min({a.y, b.y, c.y}), y_max = std::max({a.y, b.y, c.y});
    const std::uint32_t last_row = row_of(y_max);
    std::uint64_t work = 0;
    std::uint32_t row = kEnd;
    std::size_t first = 0, last = 0;  // the cells of `row` the triangle overlaps
    for (auto cell = occupied_.lower_bound(std::size_t(row_of(y_min)) * columns_); cell != occupied_.end();) {
        if (*cell / columns_ != row) {
            row = static_cast<std::uint32_t>(*cell / columns_);
            if (row > last_row) break;
            ++work;
            const double slab_lo = std::max(y_min, lo_.y + row / scale_.y), slab_hi = std::min(y_max, lo_.y + (row + 1) / scale_.y);
            auto [x_lo, x_hi] = slab_range(a, b, c, slab_lo, slab_hi);
            if (x_lo > x_hi) x_lo = x_hi = a.x;  // rounding left the slab empty: visit the margin only
            first = std::size_t(row) * columns_ + std::max(column_of(x_lo), 1u) - 1;
            last = std::size_t(row) * columns_ + std::min(column_of(x_hi) + 1, columns_ - 1);
        }
        if (*cell < first) {
            cell = occupied_.lower_bound(first);
            continue;
        }
        if (*cell > last) {
            cell = occupied_.lower_bound(std::size_t(row + 1) * columns_);
            continue;
        }
        for (std::uint32_t i = head_[*cell]; i != kEnd; i = next_[i]) {
            ++work;
            if (f(i)) return work;
        }
        ++cell;
    }
    return work;
}

}  // namespace rgbio
