#include "support/request_oracle.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace rgbtest {

double oracle_distance_to_triangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double nn = glm::dot(n, n);
    if (nn > 0.0) {
        const glm::dvec3 q = p - glm::dot(p - a, n) / nn * n;
        const bool inside = glm::dot(glm::cross(b - a, q - a), n) >= 0.0 && glm::dot(glm::cross(c - b, q - b), n) >= 0.0 &&
                            glm::dot(glm::cross(a - c, q - c), n) >= 0.0;
        if (inside) return glm::distance(p, q);
    }
    auto segment = [&](const glm::dvec3& x, const glm::dvec3& y) {
        const glm::dvec3 d = y - x;
        const double t = std::clamp(glm::dot(p - x, d) / glm::dot(d, d), 0.0, 1.0);
        return glm::distance(p, x + t * d);
    };
    return std::min({segment(a, b), segment(b, c), segment(c, a)});
}

RequestOracle::RequestOracle(const UniformLoopOracle& oracle) : oracle_(oracle) {
    const std::size_t n = oracle.num_identities(oracle.levels());
    base_space_.resize(n);
    parents_.resize(n);
    for (Identity i = 0; i < oracle.num_identities(0); ++i) {
        base_space_[i] = oracle.position(0, i);
        parents_[i] = {i, i};
    }
    edge_faces_.resize(static_cast<std::size_t>(oracle.levels()) + 1);
    for (int l = 0; l <= oracle.levels(); ++l)
        for (const IdentityTriangle& t : oracle.faces(l))
            for (int i = 0; i < 3; ++i)
                edge_faces_[static_cast<std::size_t>(l)][std::minmax(t[i], t[(i + 1) % 3])].push_back(t);
    for (int l = 0; l < oracle.levels(); ++l)
        for (const IdentityTriangle& t : oracle.faces(l))
            for (int i = 0; i < 3; ++i) {
                const Identity x = t[i], y = t[(i + 1) % 3];
                const Identity m = *oracle.midpoint(x, y);
                parents_[m] = {x, y};
                base_space_[m] = 0.5 * (base_space_[x] + base_space_[y]);
            }
}

std::set<Identity> RequestOracle::base() const {
    std::set<Identity> b;
    for (Identity i = 0; i < oracle_.num_identities(0); ++i) b.insert(i);
    return b;
}

bool RequestOracle::meets(const IdentityTriangle& t, const OracleBall& ball) const {
    return oracle_distance_to_triangle(ball.centre, base_space_[t[0]], base_space_[t[1]], base_space_[t[2]]) <= ball.radius;
}

std::vector<IdentityTriangle> RequestOracle::parent_triangles(Identity v) const {
    const auto [x, y] = parents_[v];
    return edge_faces_[static_cast<std::size_t>(oracle_.level(v) - 1)].at(std::minmax(x, y));
}

std::set<Identity> RequestOracle::closure(std::set<Identity> vertices) const {
    std::vector<Identity> work(vertices.begin(), vertices.end());
    while (!work.empty()) {
        const Identity v = work.back();
        work.pop_back();
        if (oracle_.level(v) == 0) continue;
        for (const IdentityTriangle& t : parent_triangles(v))
            for (Identity c : t)
                if (vertices.insert(c).second) work.push_back(c);
    }
    return vertices;
}

std::set<Identity> RequestOracle::refined(const std::set<Identity>& current, int level, const OracleBall& ball) const {
    std::set<Identity> wanted = current;
    for (int j = 0; j < level; ++j)
        for (const IdentityTriangle& t : oracle_.faces(j))
            if (meets(t, ball))
                for (int i = 0; i < 3; ++i) wanted.insert(*oracle_.midpoint(t[i], t[(i + 1) % 3]));
    return closure(wanted);
}

std::set<Identity> RequestOracle::coarsened(const std::set<Identity>& current, int level, const OracleBall& ball) const {
    std::set<Identity> doomed;
    for (Identity v : current) {
        if (oracle_.level(v) <= level) continue;
        for (const IdentityTriangle& t : parent_triangles(v))
            if (meets(t, ball)) doomed.insert(v);
    }
    return without(current, doomed);
}

std::set<Identity> RequestOracle::without(const std::set<Identity>& current, const std::set<Identity>& doomed) const {
    // Whatever needs a doomed vertex goes too: keep exactly the vertices whose closure avoids them.
    std::set<Identity> kept;
    for (Identity v : current) {
        if (doomed.count(v)) continue;
        const std::set<Identity> needs = closure({v});
        if (std::none_of(needs.begin(), needs.end(), [&](Identity w) { return doomed.count(w) > 0; })) kept.insert(v);
    }
    return kept;
}

}  // namespace rgbtest
