#pragma once
// Positions taken from a dense surface for every vertex of the hierarchy (a cage with detail: the
// detail/ layer samples a dense mesh M; the core only stores and looks up the result). A vertex's
// detail position is a function of its address alone, so requests stay canonical: whatever the
// order of work, storage or history, a vertex shows the same point.
//
// Stored per base face on the dyadic grid of a finest level K: every vertex of Σk, k <= K, is a
// grid point, whose value was sampled. A vertex of a finer level (k > K) lies in one triangle of
// Σ_K's grid of its face and takes the point of that triangle at its barycentric coordinates
// (piecewise linear between the sampled points). Points on a base edge or at a base vertex belong to
// several faces' grids, with the same value; a lookup goes through the canonical address, so it gives
// the same bits from any face.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "rgb/mesh/surface_point.h"

namespace rgb {

class BaseMesh;

// Where the detail came from, for reports (`rgbsub info`): the dense surface's name and size, and
// how many grid points took its nearest point because the line along the limit normal missed it.
struct DetailOrigin {
    std::string source;
    std::size_t source_triangles = 0;
    std::size_t nearest_points = 0;
};

class DetailPositions {
public:
    // The finest level a grid may have: 2^K + 1 points along a base edge, numerators of 32 bits.
    static constexpr int kMaxLevel = 12;

    // Grids of `level` filled from one value per point of grid_points(base, level), in its order.
    // Throws std::invalid_argument for a level out of 0..kMaxLevel or a wrong number of values.
    DetailPositions(const BaseMesh& base, int level, std::span<const glm::dvec3> values, DetailOrigin origin = {});

    // The distinct points of Σ_level, each once by its canonical address (reduced), face by face and
    // within a face by (a2, a1): the order in which a sampler's values are given.
    static std::vector<SurfacePoint> grid_points(const BaseMesh& base, int level);
    // Points of one face's grid: (2^K + 1)(2^K + 2) / 2.
    static std::size_t points_per_face(int level);

    int level() const { return level_; }
    const DetailOrigin& origin() const { return origin_; }
    // The value of each point of grid_points(base, level()), in its order (what a saved file holds).
    std::vector<glm::dvec3> samples(const BaseMesh& base) const;
    std::size_t num_faces() const { return num_faces_; }
    // The value at each face's grid point, face by face (for saving; the order of grid_index).
    std::span<const glm::dvec3> grid() const { return grid_; }
    // The detail position of the point p of the hierarchy (any level, given in any of its faces).
    glm::dvec3 position(const BaseMesh& base, const SurfacePoint& p) const;
    std::size_t memory_bytes() const { return grid_.capacity() * sizeof(glm::dvec3); }

private:
    // Index of grid point (a1, a2) (numerators at level_) within a face's grid.
    std::size_t grid_index(std::uint32_t a1, std::uint32_t a2) const {
        const std::size_t n = std::size_t(1) << level_;
        return a2 * (n + 1) - a2 * (a2 - std::size_t(1)) / 2 + a1;
    }
    const glm::dvec3& at(std::uint32_t face, std::uint32_t a1, std::uint32_t a2) const {
        return grid_[face * per_face_ + grid_index(a1, a2)];
    }

    int level_ = 0;
    DetailOrigin origin_;
    std::size_t num_faces_ = 0, per_face_ = 0;
    std::vector<glm::dvec3> grid_;
};

}  // namespace rgb
