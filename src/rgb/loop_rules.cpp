#include "rgb/loop_rules.h"

#include <cmath>
#include <numbers>

namespace rgb {

namespace {
// cos(2 pi / n), exact where it is rational, so that the regular weights (valence 6, and 3 and 4) are
// the exact fractions of the spec and not their floating-point neighbours.
double cos_two_pi_over(int n) {
    switch (n) {
        case 3: return -0.5;
        case 4: return 0.0;
        case 6: return 0.5;
        default: return std::cos(2.0 * std::numbers::pi / n);
    }
}
}  // namespace

double loop_alpha(int valence) {
    const double t = 3.0 + 2.0 * cos_two_pi_over(valence);
    return 5.0 / 8.0 - t * t / 64.0;
}

double loop_gamma(int valence, bool boundary) {
    if (boundary) return 0.25;
    return 5.0 / 8.0 - loop_alpha(valence);
}

double loop_limit_ring_weight(int valence) {
    const double a = loop_alpha(valence);
    return 8.0 * a / (3.0 + 8.0 * a);
}

}  // namespace rgb
