#pragma once
// Positions taken from a dense surface for every vertex of the hierarchy (a cage with detail: the
// detail/ layer samples a dense mesh M; the core only stores and looks up the result). A vertex's
// detail position is a function of its address alone, so requests stay canonical: whatever the
// order of work, storage or history, a vertex shows the same point.
//
// Each base face f has a level K_f of its own (where M is denser, finer), each base edge the coarser
// level of its faces, K_e = min(K_f, K_g). Sampled, and stored, are: every base vertex; every point
// of a base edge of level <= K_e; every point inside face f of level <= K_f. A finer point inside a
// face lies in one triangle of Σ_{K_f}'s grid of its face and takes the point of that triangle at
// its barycentric coordinates; a finer point on a base edge the same along the edge, between its
// two neighbouring samples of level K_e (piecewise linear between the sampled points). The edge takes
// the coarser level so that the function is continuous: the coarser face interpolates beyond its level
// inside grid triangles whose edge side is its own samples, which are the edge's; with the finer
// level on the edge (tried first) its interior beyond K_g met the edge's finer samples in a step that
// no refinement closes, and budgets split there to the deepest level.
//
// Storage: per base face the whole grid of its level, its edges' and corners' points included, so
// that a lookup reads one face. A point on a base edge or at a base vertex belongs to several faces'
// grids; one of them *keeps* it: a base vertex the face rgb::canonical names, an edge point the coarser
// face of its edge (whose grid holds the edge to K_e), the smaller index between equals. The other
// grids hold copies of the kept values, and a lookup goes through the keeping face's address, so it
// gives the same bits from any face.
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
    // Bytes a stored point takes in memory: its grid slot (the copies on face borders add 3 * 2^K_f
    // slots per face).
    static constexpr std::size_t kBytesPerPoint = sizeof(glm::dvec3);

    // Grids of the given levels (one per base face, each 0..kMaxLevel) filled from one value per
    // point of grid_points(base, face_levels), in its order. Throws std::invalid_argument for a level
    // out of range, a level count other than the base faces' or a wrong number of values (checked
    // before anything is allocated, so that forged levels cannot exhaust memory).
    DetailPositions(const BaseMesh& base, std::vector<std::uint8_t> face_levels, std::span<const glm::dvec3> values,
                    DetailOrigin origin = {});
    // Every face at one level.
    DetailPositions(const BaseMesh& base, int level, std::span<const glm::dvec3> values, DetailOrigin origin = {});

    // `level` for every face of `base` (std::invalid_argument out of 0..kMaxLevel).
    static std::vector<std::uint8_t> uniform_levels(const BaseMesh& base, int level);
    // The level of the points of the base edge of halfedge h: the coarser of its faces' levels.
    static int edge_level(const BaseMesh& base, std::span<const std::uint8_t> face_levels, std::uint32_t h);
    // The number of stored points, V + Σ_e (2^K_e - 1) + Σ_f (2^K_f - 1)(2^K_f - 2) / 2, counted
    // without listing them.
    static std::size_t num_points(const BaseMesh& base, std::span<const std::uint8_t> face_levels);
    // The stored points, each once by the address its keeping face gives it (reduced), face by face
    // and within a face by (a2, a1): the order in which a sampler's values are given. With one
    // level, every point of Σ_level by its canonical address.
    static std::vector<SurfacePoint> grid_points(const BaseMesh& base, std::span<const std::uint8_t> face_levels);
    static std::vector<SurfacePoint> grid_points(const BaseMesh& base, int level);
    // For every slot of every face's grid (face by face, each grid at its face's level, slots in
    // the order of (a2, a1)), the index in grid_points(base, face_levels) of the point there, or
    // kNotSampled for a point of a finer face's edge beyond the edge's level.
    static constexpr std::uint32_t kNotSampled = 0xffffffffu;
    static std::vector<std::uint32_t> grid_point_indices(const BaseMesh& base, std::span<const std::uint8_t> face_levels);
    // Points of one face's grid: (2^K + 1)(2^K + 2) / 2.
    static std::size_t points_per_face(int level);

    std::span<const std::uint8_t> face_levels() const { return face_levels_; }
    int coarsest_level() const { return coarsest_level_; }
    int finest_level() const { return finest_level_; }
    const DetailOrigin& origin() const { return origin_; }
    // The value of each point of grid_points(base, face_levels()), in its order (what a saved file holds).
    std::vector<glm::dvec3> samples(const BaseMesh& base) const;
    std::size_t num_faces() const { return face_levels_.size(); }
    // Whether the point p (any address) is a sampled one: a base vertex, an edge point of level at
    // most its edge's, an inner point of level at most its face's. Others are interpolated.
    bool is_sampled(const BaseMesh& base, const SurfacePoint& p) const;
    // The detail position of the point p of the hierarchy (any level, given in any of its faces).
    glm::dvec3 position(const BaseMesh& base, const SurfacePoint& p) const;
    std::size_t memory_bytes() const;

    // The slot of grid point (a1, a2) (numerators at `level`) within a face's grid of that level:
    // rows of constant a2, each one point shorter than the one before.
    static std::size_t grid_index(int level, std::uint32_t a1, std::uint32_t a2) {
        const std::size_t n = std::size_t(1) << level;
        return a2 * (n + 1) - a2 * (a2 - std::size_t(1)) / 2 + a1;
    }

private:
    std::vector<std::uint8_t> face_levels_;
    int coarsest_level_ = 0, finest_level_ = 0;
    DetailOrigin origin_;
    // Where each face's grid starts in grid_ (one more entry: the end).
    std::vector<std::size_t> face_offsets_;
    // Per base halfedge: 1 when the face across keeps the points of its edge.
    std::vector<std::uint8_t> kept_across_;
    std::vector<glm::dvec3> grid_;
};

}  // namespace rgb
