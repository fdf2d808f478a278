#pragma once
// The dense mesh M that `rgbsub remesh` (issue 28) transfers detail from: every vertex of a
// subdivision hierarchy over the cage is put where the line through its limit point along its limit
// normal meets M (the nearest hit within a search distance, in both directions), or, where the line
// finds no M, at the nearest point of M.
//
// A bounding volume hierarchy of ours answers every query in double from M's own positions, with
// conservative (padded) boxes and exact double arithmetic on the triangles (Möller–Trumbore for
// lines, the exact point-triangle distance for closest points), so a result equals what a brute-force
// loop over all triangles in double gives, near edges included. (Embree's float rays served as a first
// guess at first; they gained little over this search, and Embree's thread-local storage crashed
// LeakSanitizer's thread tracer in every process that linked it, so it went.)
//
// Ties are broken by a total order, so every result is deterministic (whatever the traversal order
// or the number of threads): a line's hits by smaller |t|, then positive t first, then lower
// triangle index; closest points by smaller squared distance, then lower triangle index.
//
// A line parallel to a triangle's plane (|sin| of the angle below 1e-14) does not hit that triangle:
// a line running along a flat surface meets it nowhere (it falls back to the closest point).
//
// Queries are const and thread-safe; the batch versions run on all cores (rgb::parallel_for), in a
// spatial order of the queries (neighbours share the BVH's cache lines: on a million triangles the
// searches are bound by cache misses), and return exactly what the single queries return.
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "detail/progress.h"
#include "rgb/mesh/base_mesh.h"

namespace rgbdetail {

struct SurfaceHit {
    glm::dvec3 point{0.0};           // on M's triangle: the barycentric combination of its corners
    std::uint32_t triangle = 0;      // index into the triangles M was built from
    std::array<double, 3> barycentric{};  // weights of the triangle's corners 0, 1, 2 (sum 1, each >= 0)
    // For a ray hit |t|, the distance along the (normalised) line from the origin; for a closest
    // point the Euclidean distance from the query point.
    double distance = 0.0;
    bool by_ray = false;             // found by the line (true) or the closest point (false)
};

class DenseSurface {
public:
    // M's positions and triangles (indices into positions). Throws std::invalid_argument for no
    // triangles, an index out of range, or a position that is not finite or beyond 1e30 in any
    // coordinate. Degenerate (zero-area) triangles are allowed: lines never
    // hit them, closest points may lie on them. Unused vertices and non-manifold meshes are fine.
    // Building the search tree takes about 2 s for a million triangles on a busy 2-core machine:
    // `progress` hears the share built every 65,536 triangle visits (a few milliseconds; about 290
    // times for a million triangles) and before each step after them, and a stop there throws Stopped.
    DenseSurface(std::vector<glm::dvec3> positions, std::vector<rgb::Triangle> triangles, const ProgressFunction& progress = {});
    ~DenseSurface();
    DenseSurface(DenseSurface&&) noexcept;
    DenseSurface& operator=(DenseSurface&&) noexcept;
    DenseSurface(const DenseSurface&) = delete;
    DenseSurface& operator=(const DenseSurface&) = delete;

    std::size_t num_triangles() const;
    std::span<const glm::dvec3> positions() const;
    std::span<const rgb::Triangle> triangles() const;

    // The nearest hit of the line origin + t * normalize(direction), |t| <= max_distance (both
    // directions), or nothing. distance is |t|. Throws std::invalid_argument for a non-finite origin
    // or direction, a zero direction, or a max_distance that is negative or not finite.
    std::optional<SurfaceHit> nearest_ray_hit(const glm::dvec3& origin, const glm::dvec3& direction,
                                              double max_distance) const;

    // The point of M nearest to p (exact in double up to rounding; by_ray false). Throws
    // std::invalid_argument for a non-finite p.
    SurfaceHit closest_point(const glm::dvec3& p) const;

    // nearest_ray_hit, else the closest point of M to origin (by_ray false).
    SurfaceHit project(const glm::dvec3& origin, const glm::dvec3& direction, double max_distance) const;

    // The same, for many queries on all cores: element i is the single query's answer for element i.
    // origins and directions must have the same size (std::invalid_argument otherwise); invalid input
    // throws what the single query would for the lowest such index, before any work.
    std::vector<std::optional<SurfaceHit>> nearest_ray_hits(std::span<const glm::dvec3> origins,
                                                            std::span<const glm::dvec3> directions,
                                                            double max_distance) const;
    std::vector<SurfaceHit> closest_points(std::span<const glm::dvec3> points) const;
    std::vector<SurfaceHit> projections(std::span<const glm::dvec3> origins, std::span<const glm::dvec3> directions,
                                        double max_distance) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace rgbdetail
