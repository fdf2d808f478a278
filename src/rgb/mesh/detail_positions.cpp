#include "rgb/mesh/detail_positions.h"

#include <array>
#include <stdexcept>
#include <string>
#include <utility>

#include "rgb/mesh/base_mesh.h"

namespace rgb {

namespace {

SurfacePoint grid_point(std::uint32_t face, int level, std::uint32_t a1, std::uint32_t a2) {
    SurfacePoint p;
    p.face = face;
    p.level = level;
    p.a = {(std::uint32_t(1) << level) - a1 - a2, a1, a2};
    return reduced(p);
}

}  // namespace

std::size_t DetailPositions::points_per_face(int level) {
    const std::size_t n = std::size_t(1) << level;
    return (n + 1) * (n + 2) / 2;
}

std::vector<SurfacePoint> DetailPositions::grid_points(const BaseMesh& base, int level) {
    if (level < 0 || level > kMaxLevel) throw std::invalid_argument("detail level " + std::to_string(level) + " is out of 0.." + std::to_string(kMaxLevel));
    const std::uint32_t n = std::uint32_t(1) << level;
    std::vector<SurfacePoint> points;
    for (std::uint32_t f = 0; f < base.num_faces(); ++f)
        for (std::uint32_t a2 = 0; a2 <= n; ++a2)
            for (std::uint32_t a1 = 0; a1 + a2 <= n; ++a1) {
                const SurfacePoint p = grid_point(f, level, a1, a2);
                if (canonical(base, p) == p) points.push_back(p);
            }
    return points;
}

DetailPositions::DetailPositions(const BaseMesh& base, int level, std::span<const glm::dvec3> values, DetailOrigin origin)
    : level_(level), origin_(std::move(origin)), num_faces_(base.num_faces()), per_face_(points_per_face(level)) {
    const std::vector<SurfacePoint> points = grid_points(base, level);
    if (values.size() != points.size())
        throw std::invalid_argument("detail of level " + std::to_string(level) + " needs " + std::to_string(points.size()) +
                                    " positions, not " + std::to_string(values.size()));
    grid_.resize(num_faces_ * per_face_);
    // Each face's own canonical points first, then every other grid point (on a base edge or at a
    // base vertex) copied from the face its canonical address names.
    std::vector<std::uint8_t> filled(grid_.size(), 0);
    for (std::size_t i = 0; i < points.size(); ++i) {
        const auto a = numerators_at(points[i], level);
        const std::size_t slot = points[i].face * per_face_ + grid_index(a[1], a[2]);
        grid_[slot] = values[i];
        filled[slot] = 1;
    }
    const std::uint32_t n = std::uint32_t(1) << level;
    for (std::uint32_t f = 0; f < num_faces_; ++f)
        for (std::uint32_t a2 = 0; a2 <= n; ++a2)
            for (std::uint32_t a1 = 0; a1 + a2 <= n; ++a1) {
                const std::size_t slot = f * per_face_ + grid_index(a1, a2);
                if (filled[slot]) continue;
                const SurfacePoint c = canonical(base, grid_point(f, level, a1, a2));
                const auto a = numerators_at(c, level);
                grid_[slot] = at(c.face, a[1], a[2]);
            }
}

std::vector<glm::dvec3> DetailPositions::samples(const BaseMesh& base) const {
    std::vector<glm::dvec3> values;
    for (const SurfacePoint& p : grid_points(base, level_)) values.push_back(position(base, p));
    return values;
}

glm::dvec3 DetailPositions::position(const BaseMesh& base, const SurfacePoint& p) const {
    const SurfacePoint c = canonical(base, reduced(p));
    if (c.level <= level_) {
        const auto a = numerators_at(c, level_);
        return at(c.face, a[1], a[2]);
    }
    // In the grid triangle of level K that holds c: q its numerators at K rounded down, r/s the rest.
    // An upward triangle has corners q + e_i and weights r_i / s; a downward one corners q + 1 - e_i
    // and weights 1 - r_i / s. The weights are exact (s is a power of two), and the sum runs over the
    // corners in a fixed order, so every address of the point gives the same bits.
    const int shift = c.level - level_;
    const std::uint32_t s = std::uint32_t(1) << shift;
    std::array<std::uint32_t, 3> q{}, r{};
    for (int i = 0; i < 3; ++i) {
        q[i] = c.a[i] >> shift;
        r[i] = c.a[i] & (s - 1);
    }
    const bool upward = r[0] + r[1] + r[2] == s;
    glm::dvec3 sum(0.0);
    for (int i = 0; i < 3; ++i) {
        std::array<std::uint32_t, 3> corner = q;
        double weight = 0.0;
        if (upward) {
            corner[i] += 1;
            weight = double(r[i]) / double(s);
        } else {
            for (int j = 0; j < 3; ++j)
                if (j != i) corner[j] += 1;
            weight = 1.0 - double(r[i]) / double(s);
        }
        sum += weight * at(c.face, corner[1], corner[2]);
    }
    return sum;
}

}  // namespace rgb
