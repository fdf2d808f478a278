#pragma once
// Layer rgb/rules (Loop and crease weights and masks, RGB colours): functions of numbers and
// valences; includes only rgb/support. docs/architecture.md draws the layers.
// Loop subdivision with Loop's original vertex weight (spec §4.1, §4.2): the weights, and the few
// formulas every Loop value in the core goes through. The mesh's operators and the hierarchy
// evaluator both use these, so a value computed either way has the same bits. The tests' uniform
// Loop oracle deliberately does not use them: it has its own copy of the formulas.
#include <span>

#include <glm/vec3.hpp>

namespace rgb {

// alpha_n = n * beta_n = 5/8 - (3 + 2 cos(2 pi / n))^2 / 64.
double loop_alpha(int valence);
// Eigenvalue of one Loop step on (centre, ring average): gamma = 5/8 - alpha (interior), 1/4 boundary.
double loop_gamma(int valence, bool boundary);
// Limit weight of the centre's ring: p_inf = (1 - c) p + (c / n) sum(ring), c = 8 alpha / (3 + 8 alpha).
double loop_limit_ring_weight(int valence);

// The odd rule: a new vertex on the interior edge (a, b) with opposite vertices c, d.
glm::dvec3 interior_edge_point(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d);
// The odd rule on a boundary edge: the midpoint.
glm::dvec3 boundary_edge_point(const glm::dvec3& a, const glm::dvec3& b);
// The limit of an interior vertex from its own-level value and its ring's values at that level. The
// ring is summed in sorted order, so the order in which it was gathered cannot change the bits (it
// may be left reordered).
glm::dvec3 interior_limit(const glm::dvec3& centre, std::span<glm::dvec3> ring);
// The limit of a boundary vertex from its two boundary neighbours at its own level.
glm::dvec3 boundary_limit(const glm::dvec3& centre, const glm::dvec3& u, const glm::dvec3& w);
// Spec §4.2: p^(l+j) = gamma^j p^l + (1 - gamma^j) p_inf. Inline: the LOD driver's keys and every
// split's stencil take a few of these each.
inline glm::dvec3 closed_form(const glm::dvec3& own_level, const glm::dvec3& limit, double gamma, int steps) {
    double g = 1.0;
    for (int j = 0; j < steps; ++j) g *= gamma;
    return g * own_level + (1.0 - g) * limit;
}

}  // namespace rgb
