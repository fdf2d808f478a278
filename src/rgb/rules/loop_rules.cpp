#include "rgb/rules/loop_rules.h"

#include <algorithm>
#include <array>
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

bool lexicographic_less(const glm::dvec3& a, const glm::dvec3& b) {
    if (a.x != b.x) return a.x < b.x;
    if (a.y != b.y) return a.y < b.y;
    return a.z < b.z;
}

// The sum of a regular vertex's six ring points in sorted order, sorted by 12 compare-exchanges of
// pointers (an optimal sorting network, checked on every 0-1 input) instead of std::sort moving the
// points. Points that compare equal have equal coordinates (at most zeros of either sign, which add
// alike), so any correct sort gives the same sum.
glm::dvec3 sorted_sum_of_six(std::span<const glm::dvec3> ring) {
    std::array<const glm::dvec3*, 6> order{&ring[0], &ring[1], &ring[2], &ring[3], &ring[4], &ring[5]};
    // Written out rather than looped over a table, so that the pointers stay in registers.
    const auto exchange = [&order](std::size_t i, std::size_t j) {
        if (lexicographic_less(*order[j], *order[i])) std::swap(order[i], order[j]);
    };
    // The network's five layers.
    exchange(0, 5), exchange(1, 3), exchange(2, 4);
    exchange(1, 2), exchange(3, 4);
    exchange(0, 3), exchange(2, 5);
    exchange(0, 1), exchange(2, 3), exchange(4, 5);
    exchange(1, 2), exchange(3, 4);
    glm::dvec3 sum(0.0);
    for (const glm::dvec3* p : order) sum += *p;
    return sum;
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

glm::dvec3 interior_edge_point(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d) {
    return 0.375 * (a + b) + 0.125 * (c + d);
}

glm::dvec3 boundary_edge_point(const glm::dvec3& a, const glm::dvec3& b) { return 0.5 * (a + b); }

glm::dvec3 interior_limit(const glm::dvec3& centre, std::span<glm::dvec3> ring) {
    glm::dvec3 sum(0.0);
    if (ring.size() == 6) {
        sum = sorted_sum_of_six(ring);
    } else {
        std::sort(ring.begin(), ring.end(), lexicographic_less);
        for (const glm::dvec3& p : ring) sum += p;
    }
    const int n = static_cast<int>(ring.size());
    static const double regular = loop_limit_ring_weight(6);
    const double c = n == 6 ? regular : loop_limit_ring_weight(n);
    return (1.0 - c) * centre + (c / n) * sum;
}

glm::dvec3 boundary_limit(const glm::dvec3& centre, const glm::dvec3& u, const glm::dvec3& w) {
    return (2.0 / 3.0) * centre + (1.0 / 6.0) * (u + w);
}

}  // namespace rgb
