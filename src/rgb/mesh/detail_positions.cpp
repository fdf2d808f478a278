#include "rgb/mesh/detail_positions.h"

#include <algorithm>
#include <array>
#include <limits>
#include <optional>
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

void check_levels(const BaseMesh& base, std::span<const std::uint8_t> face_levels) {
    if (face_levels.size() != base.num_faces())
        throw std::invalid_argument("detail levels for " + std::to_string(face_levels.size()) + " faces, the base mesh has " +
                                    std::to_string(base.num_faces()));
    for (std::size_t f = 0; f < face_levels.size(); ++f)
        if (face_levels[f] > DetailPositions::kMaxLevel)
            throw std::invalid_argument("detail level " + std::to_string(face_levels[f]) + " of face " + std::to_string(f) +
                                        " is out of 0.." + std::to_string(DetailPositions::kMaxLevel));
}

// Per base halfedge, whether the face across it keeps the points of its edge: the coarser face (the
// edge's level is its level), the smaller index between equals (as rgb::canonical chooses).
std::vector<std::uint8_t> kept_across_table(const BaseMesh& base, std::span<const std::uint8_t> face_levels) {
    std::vector<std::uint8_t> across(3 * base.num_faces(), 0);
    for (std::uint32_t h = 0; h < across.size(); ++h) {
        const std::uint32_t o = base.opposite(h);
        if (o == BaseMesh::kNone) continue;
        const std::uint32_t f = h / 3, g = o / 3;
        across[h] = face_levels[g] < face_levels[f] || (face_levels[g] == face_levels[f] && g < f);
    }
    return across;
}

// The address of the reduced point p in the face that keeps it (see the header).
SurfacePoint keeping_address(const BaseMesh& base, std::span<const std::uint8_t> kept_across, const SurfacePoint& p) {
    if (p.level == 0) return canonical(base, p);
    const std::optional<std::uint32_t> h = base_edge_of(p);
    if (!h || !kept_across[*h]) return p;
    return *in_face(base, p, base.opposite(*h) / 3);
}

// Where each face's grid starts in the slots of all grids, and (last) their number.
std::vector<std::size_t> face_offsets(std::span<const std::uint8_t> face_levels) {
    std::vector<std::size_t> offsets(face_levels.size() + 1, 0);
    for (std::size_t f = 0; f < face_levels.size(); ++f) offsets[f + 1] = offsets[f] + DetailPositions::points_per_face(face_levels[f]);
    return offsets;
}

// Calls visit(face, a1, a2) for every slot of every face's grid, face by face, in slot order.
template <class Visit>
void for_each_slot(std::span<const std::uint8_t> face_levels, Visit visit) {
    for (std::uint32_t f = 0; f < face_levels.size(); ++f) {
        const std::uint32_t n = std::uint32_t(1) << face_levels[f];
        for (std::uint32_t a2 = 0; a2 <= n; ++a2)
            for (std::uint32_t a1 = 0; a1 + a2 <= n; ++a1) visit(f, a1, a2);
    }
}

// Calls visit(slot, face, a1, a2) for the slots whose face keeps their point (see the header), in
// slot order. A slot inside its face (no coordinate 0) is kept without a look-up: keeping_address
// returns such a point as it is (its coordinates stay positive when it is reduced). Most slots are
// inside (465 of 561 at level 5), and loading a saved file, saving it and storing a remesh's detail
// each walk a million of them.
template <class Visit>
void for_each_kept_slot(const BaseMesh& base, std::span<const std::uint8_t> kept_across, std::span<const std::uint8_t> face_levels,
                        Visit visit) {
    std::size_t slot = 0;
    for_each_slot(face_levels, [&](std::uint32_t f, std::uint32_t a1, std::uint32_t a2) {
        const bool inside = a1 > 0 && a2 > 0 && a1 + a2 < (std::uint32_t(1) << face_levels[f]);
        if (inside) {
            visit(slot, f, a1, a2);
        } else {
            const SurfacePoint p = grid_point(f, face_levels[f], a1, a2);
            if (keeping_address(base, kept_across, p) == p) visit(slot, f, a1, a2);
        }
        ++slot;
    });
}

}  // namespace

std::size_t DetailPositions::points_per_face(int level) {
    const std::size_t n = std::size_t(1) << level;
    return (n + 1) * (n + 2) / 2;
}

std::vector<std::uint8_t> DetailPositions::uniform_levels(const BaseMesh& base, int level) {
    if (level < 0 || level > kMaxLevel) throw std::invalid_argument("detail level " + std::to_string(level) + " is out of 0.." + std::to_string(kMaxLevel));
    return std::vector<std::uint8_t>(base.num_faces(), static_cast<std::uint8_t>(level));
}

int DetailPositions::edge_level(const BaseMesh& base, std::span<const std::uint8_t> face_levels, std::uint32_t h) {
    const std::uint32_t o = base.opposite(h);
    return o == BaseMesh::kNone ? face_levels[h / 3] : std::min(face_levels[h / 3], face_levels[o / 3]);
}

std::size_t DetailPositions::num_points(const BaseMesh& base, std::span<const std::uint8_t> face_levels) {
    check_levels(base, face_levels);
    std::size_t points = base.num_vertices();
    for (std::uint32_t h = 0; h < 3 * base.num_faces(); ++h) {
        const std::uint32_t o = base.opposite(h);
        if (o == BaseMesh::kNone || o > h) points += (std::size_t(1) << edge_level(base, face_levels, h)) - 1;
    }
    for (std::uint8_t level : face_levels) {
        const std::size_t n = std::size_t(1) << level;
        points += (n - 1) * (n - 2) / 2;
    }
    return points;
}

std::vector<SurfacePoint> DetailPositions::grid_points(const BaseMesh& base, std::span<const std::uint8_t> face_levels) {
    check_levels(base, face_levels);
    const std::vector<std::uint8_t> across = kept_across_table(base, face_levels);
    std::vector<SurfacePoint> points;
    points.reserve(num_points(base, face_levels));
    for_each_kept_slot(base, across, face_levels, [&](std::size_t, std::uint32_t f, std::uint32_t a1, std::uint32_t a2) {
        points.push_back(grid_point(f, face_levels[f], a1, a2));
    });
    return points;
}

std::vector<SurfacePoint> DetailPositions::grid_points(const BaseMesh& base, int level) {
    return grid_points(base, uniform_levels(base, level));
}

std::vector<std::uint32_t> DetailPositions::grid_point_indices(const BaseMesh& base, std::span<const std::uint8_t> face_levels) {
    if (num_points(base, face_levels) > std::numeric_limits<std::uint32_t>::max())
        throw std::invalid_argument("detail of more than 2^32 points");
    const std::vector<std::uint8_t> across = kept_across_table(base, face_levels);
    const std::vector<std::size_t> offsets = face_offsets(face_levels);
    std::vector<std::uint32_t> indices(offsets.back(), kNotSampled);
    // The kept points first, numbered in the order of grid_points; then every other slot takes its
    // keeper's index where the keeping face's grid holds the point, and stays kNotSampled where the
    // point is finer than the keeper's level (a point of a finer face's edge beyond the edge's level).
    std::uint32_t next = 0;
    for_each_kept_slot(base, across, face_levels,
                       [&](std::size_t slot, std::uint32_t, std::uint32_t, std::uint32_t) { indices[slot] = next++; });
    std::size_t slot = 0;
    for_each_slot(face_levels, [&](std::uint32_t f, std::uint32_t a1, std::uint32_t a2) {
        if (indices[slot] == kNotSampled) {
            const SurfacePoint k = keeping_address(base, across, grid_point(f, face_levels[f], a1, a2));
            const int level = face_levels[k.face];
            if (k.level <= level) {
                const auto a = numerators_at(k, level);
                indices[slot] = indices[offsets[k.face] + grid_index(level, a[1], a[2])];
            }
        }
        ++slot;
    });
    return indices;
}

DetailPositions::DetailPositions(const BaseMesh& base, std::vector<std::uint8_t> face_levels, std::span<const glm::dvec3> values,
                                 DetailOrigin origin)
    : face_levels_(std::move(face_levels)), origin_(std::move(origin)) {
    const std::size_t needed = num_points(base, face_levels_);
    if (values.size() != needed)
        throw std::invalid_argument("detail of levels " + std::to_string(*std::min_element(face_levels_.begin(), face_levels_.end())) +
                                    ".." + std::to_string(*std::max_element(face_levels_.begin(), face_levels_.end())) + " needs " +
                                    std::to_string(needed) + " positions, not " + std::to_string(values.size()));
    if (!face_levels_.empty()) {
        coarsest_level_ = *std::min_element(face_levels_.begin(), face_levels_.end());
        finest_level_ = *std::max_element(face_levels_.begin(), face_levels_.end());
    }
    face_offsets_ = face_offsets(face_levels_);
    kept_across_ = kept_across_table(base, face_levels_);
    const std::vector<std::uint32_t> indices = grid_point_indices(base, face_levels_);
    grid_.resize(indices.size());
    for (std::size_t slot = 0; slot < indices.size(); ++slot)
        if (indices[slot] != kNotSampled) grid_[slot] = values[indices[slot]];
    // The slots of a finer face's edge beyond the edge's level: between their neighbours on the edge
    // in the keeper's grid, whose slots at its own level are all filled now.
    std::size_t slot = 0;
    for_each_slot(face_levels_, [&](std::uint32_t f, std::uint32_t a1, std::uint32_t a2) {
        if (indices[slot] == kNotSampled) grid_[slot] = position(base, grid_point(f, face_levels_[f], a1, a2));
        ++slot;
    });
}

DetailPositions::DetailPositions(const BaseMesh& base, int level, std::span<const glm::dvec3> values, DetailOrigin origin)
    : DetailPositions(base, uniform_levels(base, level), values, std::move(origin)) {}

std::vector<glm::dvec3> DetailPositions::samples(const BaseMesh& base) const {
    // The slots of the points each face keeps, in slot order (grid_points' order), hold their values:
    // read from there, not looked up by address (a saved file's million points are read while it is
    // written).
    std::vector<glm::dvec3> values;
    values.reserve(num_points(base, face_levels_));
    for_each_kept_slot(base, kept_across_, face_levels_,
                       [&](std::size_t slot, std::uint32_t, std::uint32_t, std::uint32_t) { values.push_back(grid_[slot]); });
    return values;
}

std::size_t DetailPositions::memory_bytes() const {
    return grid_.capacity() * sizeof(glm::dvec3) + face_offsets_.capacity() * sizeof(std::size_t) + face_levels_.capacity() +
           kept_across_.capacity();
}

bool DetailPositions::is_sampled(const BaseMesh& base, const SurfacePoint& p) const {
    const SurfacePoint k = keeping_address(base, kept_across_, reduced(p));
    return k.level <= face_levels_[k.face];
}

glm::dvec3 DetailPositions::position(const BaseMesh& base, const SurfacePoint& p) const {
    const SurfacePoint c = keeping_address(base, kept_across_, reduced(p));
    const int level = face_levels_[c.face];
    const glm::dvec3* grid = grid_.data() + face_offsets_[c.face];
    if (c.level <= level) {
        const auto a = numerators_at(c, level);
        return grid[grid_index(level, a[1], a[2])];
    }
    // In the grid triangle of the face's level K that holds c: q its numerators at K rounded down,
    // r/s the rest. An upward triangle has corners q + e_i and weights r_i / s; a downward one corners
    // q + 1 - e_i and weights 1 - r_i / s. The weights are exact (s is a power of two), and the sum
    // runs over the corners in a fixed order in the one face that keeps c, so every address of the
    // point gives the same bits. A point on a base edge (kept by the edge's coarser face, whose K is
    // the edge's) has r = 0 across the edge: an upward triangle, weight 0 on the corner off the edge,
    // so it lies between its two neighbouring samples on the edge.
    const int shift = c.level - level;
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
        sum += weight * grid[grid_index(level, corner[1], corner[2])];
    }
    return sum;
}

}  // namespace rgb
