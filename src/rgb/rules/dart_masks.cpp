#include "rgb/rules/dart_masks.h"

#include "rgb/rules/loop_rules.h"

namespace rgb {

namespace {

// row * D_n for the one-step matrix of docs/loop-creases.md §4.4 (entry 0 the centre, entry 1 the
// end of the sharp edge, then the ring counter-clockwise):
//   centre:     (1 - alpha_n) centre + alpha_n / n sum(ring)
//   sharp end:  1/2 centre + 1/2 ring[0]
//   others:     3/8 centre + 3/8 ring[i] + 1/8 (ring[i-1] + ring[i+1])
std::vector<double> times_step(const std::vector<double>& row, int n) {
    const double alpha = loop_alpha(n);
    std::vector<double> out(row.size(), 0.0);
    auto ring = [n](int i) { return 1 + (i % n + n) % n; };
    out[0] += row[0] * (1.0 - alpha);
    for (int i = 0; i < n; ++i) out[ring(i)] += row[0] * alpha / n;
    out[0] += row[ring(0)] * 0.5;
    out[ring(0)] += row[ring(0)] * 0.5;
    for (int i = 1; i < n; ++i) {
        const double w = row[ring(i)];
        out[0] += w * 0.375;
        out[ring(i)] += w * 0.375;
        out[ring(i - 1)] += w * 0.125;
        out[ring(i + 1)] += w * 0.125;
    }
    return out;
}

}  // namespace

std::vector<double> dart_mask(int valence, int steps) {
    std::vector<double> row(static_cast<std::size_t>(valence) + 1, 0.0);
    row[0] = 1.0;
    for (int j = 0; j < steps; ++j) row = times_step(row, valence);
    return row;
}

std::vector<double> dart_limit_mask(int valence) {
    // The rows of D_n^j converge to the limit mask (every other eigenvalue is below 0.6 in modulus),
    // so iterate until a step changes nothing; 400 steps are far more than double precision needs.
    std::vector<double> row = dart_mask(valence, 0);
    for (int j = 0; j < 400; ++j) {
        std::vector<double> next = times_step(row, valence);
        if (next == row) break;
        row = std::move(next);
    }
    return row;
}

glm::dvec3 apply_dart_mask(std::span<const double> mask, const glm::dvec3& centre, std::span<const glm::dvec3> ring,
                           std::size_t sharp) {
    const std::size_t n = ring.size();
    glm::dvec3 sum = mask[0] * centre;
    for (std::size_t i = 0; i < n; ++i) sum += mask[1 + i] * ring[(sharp + i) % n];
    return sum;
}

}  // namespace rgb
