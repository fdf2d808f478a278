#pragma once
// Triangles of the uniform hierarchy Σl named by the addresses of their corners (surface_point.h),
// whether or not the adaptive mesh holds them, and their sample points: the 15 vertices of Σ(l+2)
// that lie in a triangle of Σl (corners, edge midpoints, quarter points of the edges, and three
// interior points). Criteria that judge an edge by the surface next to it (lod_criteria.h) and the
// measure of a displayed surface (surface_error.h) use them, so both sample the same points.
#include <array>
#include <cstdint>

#include <glm/vec3.hpp>

#include "rgb/mesh/surface_point.h"
#include "rgb/support/inline_vector.h"

namespace rgb {

class BaseMesh;

// Barycentric weights (i, j, k) / 4 of the sample points over a triangle's corners, i + j + k = 4.
inline constexpr int kSamplesPerTriangle = 15;
using SampleWeights = std::array<int, 3>;
const std::array<SampleWeights, kSamplesPerTriangle>& sample_weights();

struct HierarchyTriangle {
    std::uint32_t face = 0;  // the base face that contains it
    int level = 0;
    // Counter-clockwise corners, as numerators over 2^level in `face`.
    std::array<std::array<std::uint32_t, 3>, 3> corners{};

    SurfacePoint corner(int c) const;
    // The point sum(w_c * corner c) / 4: a vertex of Σ(level + 2) (reduced to its own level).
    SurfacePoint sample(const SampleWeights& w) const;
    // The same point as numerators over 2^(level + 2), not reduced.
    SurfacePoint sample_at_level(const SampleWeights& w) const;
};

// The triangles of Σl on either side of the edge (a, b) of Σl (one on the boundary), each rotated so
// that the edge runs from corner 0 to corner 1 counter-clockwise (so corner 2 is the vertex opposite
// the edge).
InlineVector<HierarchyTriangle, 2> triangles_beside(const BaseMesh& base, const SurfacePoint& a, const SurfacePoint& b);

// The point with the given barycentric weights on the flat triangle over `corners`, summed in an order
// that depends only on the corners' positions, so that a sample shared by two tiles, or seen from a
// criterion and from a measure, gets the same bits.
glm::dvec3 interpolate(const std::array<glm::dvec3, 3>& corners, const std::array<double, 3>& weights);
// interpolate in two steps, for many points on one triangle: the order of its corners once, then per
// point the sum in that order (the same bits as interpolate).
std::array<int, 3> interpolation_order(const std::array<glm::dvec3, 3>& corners);
inline glm::dvec3 interpolate_in_order(const std::array<glm::dvec3, 3>& corners, const std::array<int, 3>& order,
                                       const std::array<double, 3>& weights) {
    glm::dvec3 sum(0.0);
    for (int i : order) sum += weights[static_cast<std::size_t>(i)] * corners[static_cast<std::size_t>(i)];
    return sum;
}

}  // namespace rgb
