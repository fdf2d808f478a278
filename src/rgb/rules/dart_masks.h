#pragma once
// Masks of a dart vertex (one sharp edge; docs/loop-creases.md §4.4). The vertex moves by the smooth
// rule, but the edge point on its sharp edge is a midpoint, so its value after j steps is a fixed
// combination of its whole ring, not of two terms as for the other rules. Weights over
// x = (centre, ring[s], ring[s+1], ..., ring[s+n-1]), ring[s] the end of the sharp edge, the ring
// counter-clockwise; they depend only on the valence n and j. Kept apart from any value type, so
// positions and any other per-vertex data go through the same masks (apply_dart_mask).
#include <span>
#include <vector>

#include <glm/vec3.hpp>

namespace rgb {

// p^(t+j) of a dart from its data at level t: the first row of D_n^j, D_n the one-step matrix.
std::vector<double> dart_mask(int valence, int steps);
// Its limit: the left eigenvector of D_n for the eigenvalue 1, weights summing to 1.
std::vector<double> dart_limit_mask(int valence);

// mask[0] centre + sum_i mask[1 + i] ring[(sharp + i) % n].
glm::dvec3 apply_dart_mask(std::span<const double> mask, const glm::dvec3& centre, std::span<const glm::dvec3> ring,
                           std::size_t sharp);

}  // namespace rgb
