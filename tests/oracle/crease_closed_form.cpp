#include "crease_closed_form.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace osdoracle {
namespace {

using Matrix = std::vector<std::vector<double>>;

int sharp_edge_count(const Neighbourhood& n) {
    return static_cast<int>(std::count_if(n.edge_sharpness.begin(), n.edge_sharpness.end(),
                                          [](double s) { return s > 0.0; }));
}

// Indices in the ring of the ends of the sharp edges, in ring order.
std::vector<std::size_t> sharp_neighbours(const Neighbourhood& n) {
    std::vector<std::size_t> sharp;
    for (std::size_t i = 0; i < n.ring.size(); ++i)
        if (n.edge_sharpness[i] > 0.0) sharp.push_back(i);
    return sharp;
}

glm::dvec3 ring_sum(const Neighbourhood& n) {
    glm::dvec3 sum(0.0);
    for (const glm::dvec3& p : n.ring) sum += p;
    return sum;
}

// §3.1: smooth vertex rule and its limit.
glm::dvec3 smooth_step(const Neighbourhood& n) {
    const int valence = static_cast<int>(n.ring.size());
    const double alpha = loop_alpha(valence);
    return (1.0 - alpha) * n.centre + (alpha / valence) * ring_sum(n);
}

// §3.2: the crease limit, 2/3 p + 1/6 (u + w) over the two sharp neighbours.
glm::dvec3 crease_limit(const Neighbourhood& n) {
    const auto sharp = sharp_neighbours(n);
    return 2.0 / 3.0 * n.centre + 1.0 / 6.0 * (n.ring[sharp[0]] + n.ring[sharp[1]]);
}

// §3.4: the dart's one-ring refinement matrix over (centre, ring[s], ring[s+1], ...), s the sharp edge:
// the centre by the smooth rule, the sharp edge's end by the midpoint, the others by the smooth edge rule.
Matrix dart_matrix(int valence) {
    const int size = valence + 1;
    Matrix m(size, std::vector<double>(size, 0.0));
    const double alpha = loop_alpha(valence);
    m[0][0] = 1.0 - alpha;
    for (int i = 0; i < valence; ++i) m[0][1 + i] = alpha / valence;
    m[1][0] = 0.5;
    m[1][1] = 0.5;
    for (int i = 1; i < valence; ++i) {
        m[1 + i][0] = 3.0 / 8.0;
        m[1 + i][1 + i] += 3.0 / 8.0;
        m[1 + i][1 + (i + valence - 1) % valence] += 1.0 / 8.0;
        m[1 + i][1 + (i + 1) % valence] += 1.0 / 8.0;
    }
    return m;
}

// Solves a x = b by Gaussian elimination with partial pivoting (a is small and well conditioned).
std::vector<double> solve(Matrix a, std::vector<double> b) {
    const std::size_t size = b.size();
    for (std::size_t col = 0; col < size; ++col) {
        std::size_t pivot = col;
        for (std::size_t r = col + 1; r < size; ++r)
            if (std::abs(a[r][col]) > std::abs(a[pivot][col])) pivot = r;
        std::swap(a[col], a[pivot]);
        std::swap(b[col], b[pivot]);
        for (std::size_t r = col + 1; r < size; ++r) {
            const double f = a[r][col] / a[col][col];
            for (std::size_t c = col; c < size; ++c) a[r][c] -= f * a[col][c];
            b[r] -= f * b[col];
        }
    }
    std::vector<double> x(size);
    for (std::size_t r = size; r-- > 0;) {
        double sum = b[r];
        for (std::size_t c = r + 1; c < size; ++c) sum -= a[r][c] * x[c];
        x[r] = sum / a[r][r];
    }
    return x;
}

glm::dvec3 apply_dart_mask(const Neighbourhood& n, const std::vector<double>& mask) {
    const auto sharp = sharp_neighbours(n);
    const std::size_t valence = n.ring.size();
    glm::dvec3 p = mask[0] * n.centre;
    for (std::size_t i = 0; i < valence; ++i) p += mask[1 + i] * n.ring[(sharp[0] + i) % valence];
    return p;
}

}  // namespace

double loop_alpha(int valence) { return 5.0 / 8.0 - loop_gamma(valence); }

double loop_gamma(int valence) {
    const double c = 3.0 + 2.0 * std::cos(2.0 * std::numbers::pi / valence);
    return c * c / 64.0;
}

VertexRule rule_of(const Neighbourhood& n) { return rule_for(n.vertex_sharpness, sharp_edge_count(n)); }

int levels_rule_lasts(const Neighbourhood& n) {
    const VertexRule rule = rule_of(n);
    Neighbourhood later = n;
    for (int j = 1;; ++j) {
        later.vertex_sharpness = sharpness_one_level_finer(later.vertex_sharpness);
        for (double& s : later.edge_sharpness) s = sharpness_one_level_finer(s);
        if (rule_of(later) != rule) return j;
        const auto pending = [](double s) { return s > 0.0 && !is_infinite(s); };
        if (!pending(later.vertex_sharpness) &&
            std::none_of(later.edge_sharpness.begin(), later.edge_sharpness.end(), pending))
            return rule_lasts_forever;
    }
}

glm::dvec3 edge_point(const glm::dvec3& a, const glm::dvec3& b, const std::vector<glm::dvec3>& opposite,
                      double sharpness) {
    if (sharpness > 0.0 || opposite.size() != 2) return 0.5 * (a + b);
    return 3.0 / 8.0 * (a + b) + 1.0 / 8.0 * (opposite[0] + opposite[1]);
}

Neighbourhood one_level_finer(const Neighbourhood& n) {
    Neighbourhood finer;
    const std::size_t valence = n.ring.size();
    for (std::size_t i = 0; i < valence; ++i) {
        std::vector<glm::dvec3> opposite;
        if (!n.boundary || i > 0) opposite.push_back(n.ring[(i + valence - 1) % valence]);
        if (!n.boundary || i + 1 < valence) opposite.push_back(n.ring[(i + 1) % valence]);
        finer.ring.push_back(edge_point(n.centre, n.ring[i], opposite, n.edge_sharpness[i]));
        finer.edge_sharpness.push_back(sharpness_one_level_finer(n.edge_sharpness[i]));
    }
    switch (rule_of(n)) {
    case VertexRule::smooth:
    case VertexRule::dart: finer.centre = smooth_step(n); break;
    case VertexRule::crease: {
        const auto sharp = sharp_neighbours(n);
        finer.centre = 0.75 * n.centre + 0.125 * (n.ring[sharp[0]] + n.ring[sharp[1]]);
        break;
    }
    case VertexRule::corner: finer.centre = n.centre; break;
    }
    finer.vertex_sharpness = sharpness_one_level_finer(n.vertex_sharpness);
    finer.boundary = n.boundary;
    return finer;
}

glm::dvec3 closed_form(const Neighbourhood& n, int j) {
    switch (rule_of(n)) {
    case VertexRule::smooth: {
        const double g = std::pow(loop_gamma(static_cast<int>(n.ring.size())), j);
        return g * n.centre + (1.0 - g) * limit_of_rule(n);
    }
    case VertexRule::crease: {
        const double g = std::pow(0.25, j);
        return g * n.centre + (1.0 - g) * crease_limit(n);
    }
    case VertexRule::corner: return n.centre;
    case VertexRule::dart: return apply_dart_mask(n, dart_mask(static_cast<int>(n.ring.size()), j));
    }
    throw std::logic_error("unknown rule");
}

glm::dvec3 limit_of_rule(const Neighbourhood& n) {
    switch (rule_of(n)) {
    case VertexRule::smooth: return smooth_limit_mask_result(n);
    case VertexRule::crease: return crease_limit(n);
    case VertexRule::corner: return n.centre;
    case VertexRule::dart: return apply_dart_mask(n, dart_limit_mask(static_cast<int>(n.ring.size())));
    }
    throw std::logic_error("unknown rule");
}

glm::dvec3 piecewise_closed_form(Neighbourhood n, int j) {
    for (;;) {
        const int lasts = levels_rule_lasts(n);
        if (j <= lasts) return closed_form(n, j);
        const glm::dvec3 centre_at_transition = closed_form(n, lasts);
        for (int i = 0; i < lasts; ++i) n = one_level_finer(n);
        n.centre = centre_at_transition;
        j -= lasts;
    }
}

namespace {

// The neighbourhood at the start of its last regime.
Neighbourhood last_regime(Neighbourhood n) {
    for (int lasts = levels_rule_lasts(n); lasts != rule_lasts_forever; lasts = levels_rule_lasts(n))
        for (int i = 0; i < lasts; ++i) n = one_level_finer(n);
    return n;
}

}  // namespace

glm::dvec3 piecewise_limit(Neighbourhood n) { return limit_of_rule(last_regime(std::move(n))); }

VertexRule final_rule(Neighbourhood n) { return rule_of(last_regime(std::move(n))); }

std::vector<double> dart_mask(int valence, int j) {
    const Matrix m = dart_matrix(valence);
    std::vector<double> row(valence + 1, 0.0);
    row[0] = 1.0;
    for (int step = 0; step < j; ++step) {
        std::vector<double> next(valence + 1, 0.0);
        for (int r = 0; r <= valence; ++r)
            for (int c = 0; c <= valence; ++c) next[c] += row[r] * m[r][c];
        row = next;
    }
    return row;
}

std::vector<double> dart_limit_mask(int valence) {
    // The limit mask l is the left eigenvector of the dart matrix for eigenvalue 1 with weights summing
    // to 1: (M^T - I) l = 0, one of whose equations is replaced by the normalisation.
    const Matrix m = dart_matrix(valence);
    const std::size_t size = m.size();
    Matrix a(size, std::vector<double>(size, 0.0));
    for (std::size_t r = 0; r < size; ++r)
        for (std::size_t c = 0; c < size; ++c) a[r][c] = m[c][r] - (r == c ? 1.0 : 0.0);
    std::fill(a.back().begin(), a.back().end(), 1.0);
    std::vector<double> b(size, 0.0);
    b.back() = 1.0;
    return solve(a, b);
}

glm::dvec3 smooth_limit_mask_result(const Neighbourhood& n) {
    const int valence = static_cast<int>(n.ring.size());
    const double alpha = loop_alpha(valence);
    const double c = 8.0 * alpha / (3.0 + 8.0 * alpha);
    return (1.0 - c) * n.centre + (c / valence) * ring_sum(n);
}

}  // namespace osdoracle
