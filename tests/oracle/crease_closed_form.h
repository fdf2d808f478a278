#pragma once
// The closed forms derived in docs/loop-creases.md (section numbers below are that note's), written
// from the derivation for the tests that check them against Far. Test code only, independent of
// src/: the core implements its own version.
#include <vector>

#include <glm/vec3.hpp>

#include "vertex_neighbourhood.h"

namespace osdoracle {

// Loop's original weights (spec §4.1): the centre keeps 1 - alpha_n, each neighbour gets alpha_n / n;
// gamma_n = 5/8 - alpha_n is the second eigenvalue of the smooth rule.
double loop_alpha(int valence);
double loop_gamma(int valence);

// §2: the rule Far applies to the centre when it refines this level, and how many levels it lasts
// before uniform creasing changes it (a large number when it never does).
VertexRule rule_of(const Neighbourhood& n);
int levels_rule_lasts(const Neighbourhood& n);
inline constexpr int rule_lasts_forever = 1 << 20;

// §1: the vertex inserted on the edge {a, b}; `opposite` holds the vertices facing the edge in its
// one or two triangles.
glm::dvec3 edge_point(const glm::dvec3& a, const glm::dvec3& b, const std::vector<glm::dvec3>& opposite,
                      double sharpness);

// §1: the same vertex one level finer, by the rules: its new ring is made of the edge points of its
// edges, its centre moves by its rule, its tags are one level finer. (The one-ring is closed under
// refinement, so this needs nothing outside it.)
Neighbourhood one_level_finer(const Neighbourhood& n);

// §3: p^{a+j} of the centre from level-a data, for 0 <= j <= levels_rule_lasts(n).
glm::dvec3 closed_form(const Neighbourhood& n, int j);
// §3: the limit of the centre if its rule never changed.
glm::dvec3 limit_of_rule(const Neighbourhood& n);

// §4, semi-sharp: p^{a+j} for any j >= 0, one closed form per rule regime; at a transition level t
// the next regime starts from p^t given by the closed form and the ring of level t.
glm::dvec3 piecewise_closed_form(Neighbourhood n, int j);
glm::dvec3 piecewise_limit(Neighbourhood n);
// The rule of the last regime, the one that decides the limit.
VertexRule final_rule(Neighbourhood n);

// §3.4, darts: p^{a+j} = mask[0] p^a + sum_i mask[1 + i] ring[(s + i) % n], where ring[s] is the end
// of the sharp edge; the limit mask is the fixed point of the same iteration.
std::vector<double> dart_mask(int valence, int j);
std::vector<double> dart_limit_mask(int valence);

// §3.5: what PrimvarRefiner::Limit computes at a smooth vertex and also at a dart.
glm::dvec3 smooth_limit_mask_result(const Neighbourhood& n);

}  // namespace osdoracle
