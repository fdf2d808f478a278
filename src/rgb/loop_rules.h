#pragma once
// Loop subdivision weights with Loop's original vertex weight (spec §4.1, §4.2). The tests' uniform
// Loop oracle deliberately does not use these: it has its own copy of the formulas.
namespace rgb {

// alpha_n = n * beta_n = 5/8 - (3 + 2 cos(2 pi / n))^2 / 64.
double loop_alpha(int valence);
// Eigenvalue of one Loop step on (centre, ring average): gamma = 5/8 - alpha (interior), 1/4 boundary.
double loop_gamma(int valence, bool boundary);
// Limit weight of the centre's ring: p_inf = (1 - c) p + (c / n) sum(ring), c = 8 alpha / (3 + 8 alpha).
double loop_limit_ring_weight(int valence);

}  // namespace rgb
