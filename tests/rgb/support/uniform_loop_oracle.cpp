#include "support/uniform_loop_oracle.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include "support/triangle_keys.h"

namespace rgbtest {
namespace {

std::uint64_t edge_key(Identity a, Identity b) {
    return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
}

// Loop's original weight: beta_n = (1/n) (5/8 - (3/8 + 1/4 cos(2 pi / n))^2).
double loop_beta(int n) {
    const double c = 3.0 / 8.0 + 0.25 * std::cos(2.0 * std::numbers::pi / n);
    return (5.0 / 8.0 - c * c) / n;
}

// One edge of Σk with the vertices opposite it in its one or two faces.
struct Edge {
    Identity a, b;
    std::vector<Identity> opposite;
};

std::vector<Edge> edges_of(const std::vector<IdentityTriangle>& faces) {
    struct Side {
        std::uint64_t key;
        Identity a, b, opposite;
    };
    std::vector<Side> sides;
    for (const IdentityTriangle& f : faces)
        for (int i = 0; i < 3; ++i) sides.push_back({edge_key(f[i], f[(i + 1) % 3]), f[i], f[(i + 1) % 3], f[(i + 2) % 3]});
    std::sort(sides.begin(), sides.end(), [](const Side& x, const Side& y) {
        return x.key != y.key ? x.key < y.key : x.opposite < y.opposite;
    });
    std::vector<Edge> edges;
    for (std::size_t i = 0; i < sides.size(); ++i) {
        if (i > 0 && sides[i].key == sides[i - 1].key) {
            edges.back().opposite.push_back(sides[i].opposite);
            if (edges.back().opposite.size() > 2)
                throw std::invalid_argument("oracle: non-manifold edge " + std::to_string(sides[i].a) + "-" +
                                            std::to_string(sides[i].b));
        } else {
            edges.push_back({sides[i].a, sides[i].b, {sides[i].opposite}});
        }
    }
    return edges;
}

}  // namespace

UniformLoopOracle::UniformLoopOracle(std::span<const glm::dvec3> positions, std::span<const rgb::Triangle> triangles,
                                     int levels) {
    Level base;
    base.positions.assign(positions.begin(), positions.end());
    for (const rgb::Triangle& t : triangles) base.faces.push_back(canonical_rotation(IdentityTriangle{t[0], t[1], t[2]}));
    std::sort(base.faces.begin(), base.faces.end());
    identity_level_.assign(positions.size(), 0);
    levels_.push_back(std::move(base));
    for (int k = 0; k < levels; ++k) subdivide_once();
}

bool UniformLoopOracle::has_face(int k, const IdentityTriangle& t) const {
    return std::binary_search(levels_[k].faces.begin(), levels_[k].faces.end(), canonical_rotation(t));
}

std::optional<Identity> UniformLoopOracle::midpoint(Identity a, Identity b) const {
    const auto it = midpoints_.find(edge_key(a, b));
    if (it == midpoints_.end()) return std::nullopt;
    return it->second;
}

Identity UniformLoopOracle::new_midpoint(Identity a, Identity b) {
    const auto id = static_cast<Identity>(identity_level_.size());
    identity_level_.push_back(levels() + 1);  // called while Σ(levels()+1) is being built
    midpoints_.emplace(edge_key(a, b), id);
    return id;
}

void UniformLoopOracle::subdivide_once() {
    const Level& coarse = levels_.back();
    const std::vector<glm::dvec3>& p = coarse.positions;
    const std::vector<Edge> edges = edges_of(coarse.faces);

    // Even vertices: interior rule over all neighbours, boundary rule over the boundary neighbours.
    struct Neighbours {
        glm::dvec3 sum{0.0}, boundary_sum{0.0};
        int count = 0, boundary_count = 0;
    };
    std::vector<Neighbours> around(p.size());
    for (const Edge& e : edges) {
        for (const auto& [centre, other] : {std::pair{e.a, e.b}, std::pair{e.b, e.a}}) {
            around[centre].sum += p[other];
            ++around[centre].count;
            if (e.opposite.size() == 1) {
                around[centre].boundary_sum += p[other];
                ++around[centre].boundary_count;
            }
        }
    }
    Level fine;
    fine.positions.reserve(p.size() + edges.size());
    for (std::size_t v = 0; v < p.size(); ++v) {
        const Neighbours& n = around[v];
        if (n.boundary_count > 0) {
            if (n.boundary_count != 2) throw std::invalid_argument("oracle: vertex on two boundary loops");
            fine.positions.push_back(0.75 * p[v] + 0.125 * n.boundary_sum);
        } else {
            const double beta = loop_beta(n.count);
            fine.positions.push_back((1.0 - n.count * beta) * p[v] + beta * n.sum);
        }
    }
    // Odd vertices, numbered in edge order.
    for (const Edge& e : edges) {
        const Identity m = new_midpoint(e.a, e.b);
        if (e.opposite.size() == 2)
            fine.positions.push_back(3.0 / 8.0 * (p[e.a] + p[e.b]) + 1.0 / 8.0 * (p[e.opposite[0]] + p[e.opposite[1]]));
        else
            fine.positions.push_back(0.5 * (p[e.a] + p[e.b]));
        if (fine.positions.size() != m + 1) throw std::logic_error("oracle: identity numbering out of step");
    }
    for (const IdentityTriangle& f : coarse.faces) {
        const Identity ab = *midpoint(f[0], f[1]), bc = *midpoint(f[1], f[2]), ca = *midpoint(f[2], f[0]);
        for (const IdentityTriangle& t : {IdentityTriangle{f[0], ab, ca}, IdentityTriangle{ab, f[1], bc},
                                          IdentityTriangle{ca, bc, f[2]}, IdentityTriangle{ab, bc, ca}})
            fine.faces.push_back(canonical_rotation(t));
    }
    std::sort(fine.faces.begin(), fine.faces.end());
    levels_.push_back(std::move(fine));
}

}  // namespace rgbtest
