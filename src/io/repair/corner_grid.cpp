#include "io/repair/corner_grid.h"

#include <cmath>

#include <glm/common.hpp>

namespace rgbio {

CornerGrid::CornerGrid(const std::vector<glm::dvec2>& points, const std::vector<std::uint8_t>& member)
    : next_(points.size(), kEnd), prev_(points.size(), kEnd), in_grid_(member), points_(points) {
    const std::size_t count = static_cast<std::size_t>(std::count(member.begin(), member.end(), 1));
    glm::dvec2 hi(std::numeric_limits<double>::lowest());
    lo_ = glm::dvec2(std::numeric_limits<double>::max());
    for (std::size_t i = 0; i < points.size(); ++i)
        if (member[i]) {
            lo_ = glm::min(lo_, points[i]);
            hi = glm::max(hi, points[i]);
        }
    if (count > 0) {
        const glm::dvec2 extent = glm::max(hi - lo_, glm::dvec2(1e-300));
        const double n = static_cast<double>(count), aspect = extent.x / extent.y;
        columns_ = static_cast<std::uint32_t>(std::clamp(std::sqrt(n * aspect), 1.0, n));
        rows_ = static_cast<std::uint32_t>(std::clamp(std::sqrt(n / aspect), 1.0, n));
        scale_ = glm::dvec2(columns_, rows_) / extent;
    }
    head_.assign(std::size_t(columns_) * rows_, kEnd);
    for (std::uint32_t i = static_cast<std::uint32_t>(points.size()); i-- > 0;)
        if (member[i]) {
            const std::size_t c = cell(points[i]);
            occupied_.insert(c);
            std::uint32_t& head = head_[c];
            next_[i] = head;
            if (head != kEnd) prev_[head] = i;
            head = i;
        }
}

void CornerGrid::remove(std::uint32_t corner) {
    if (!in_grid_[corner]) return;
    in_grid_[corner] = 0;
    const std::size_t c = cell(points_[corner]);
    if (prev_[corner] != kEnd) next_[prev_[corner]] = next_[corner];
    else if ((head_[c] = next_[corner]) == kEnd) occupied_.erase(c);
    if (next_[corner] != kEnd) prev_[next_[corner]] = prev_[corner];
}

std::pair<double, double> CornerGrid::slab_range(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, double y0, double y1) {
    double x_lo = std::numeric_limits<double>::max(), x_hi = std::numeric_limits<double>::lowest();
    for (const auto& [p, q] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}}) {
        // The part of edge pq inside the slab: its ends bound the triangle's x range there.
        const double lo = std::max(y0, std::min(p.y, q.y)), hi = std::min(y1, std::max(p.y, q.y));
        if (lo > hi) continue;
        for (const double y : {lo, hi}) {
            const double x0 = p.y == q.y ? p.x : p.x + (q.x - p.x) * (y - p.y) / (q.y - p.y);
            const double x1 = p.y == q.y ? q.x : x0;
            x_lo = std::min({x_lo, x0, x1});
            x_hi = std::max({x_hi, x0, x1});
        }
    }
    return {x_lo, x_hi};
}

}  // namespace rgbio
