#include "rgb/lod/limit_error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "rgb/mesh/base_mesh.h"
#include "rgb/mesh/detail_positions.h"
#include "rgb/values/hierarchy_triangle.h"

namespace rgb {

namespace {

// The nodes a triangle T = (X0, X1, X2) of Σl can be shown with while its edge X0X1 is unsplit: its
// corners and the midpoints M12, M20 of the other two edges, as barycentric weights over 4.
enum Node { X0, X1, X2, M12, M20 };
constexpr std::array<SampleWeights, 5> kNodeWeights{{{4, 0, 0}, {0, 4, 0}, {0, 0, 4}, {0, 2, 2}, {2, 0, 2}}};

using Tile = std::array<Node, 3>;
struct Tiling {
    InlineVector<Tile, 2> tiles;  // the pieces of level l (spec §1.3), counter-clockwise
};
// Which of X1X2 and X2X0 are split. With both split, the corner triangle (M12, X2, M20) is a face of
// level l+1 judged by its own edges; the quadrilateral left is cut by the normal form's diagonal
// (spec §3.5: the red triangle's red edge enters its top vertex), from X1 to M20.
const std::array<Tiling, 4> kTilings{{
    {{{X0, X1, X2}}},
    {{{M12, X2, X0}, {M12, X0, X1}}},
    {{{M20, X0, X1}, {M20, X1, X2}}},
    {{{X1, M12, M20}, {X1, M20, X0}}},
}};

// A sample in a tile: the tile's nodes and the sample's barycentric weights over them.
struct Interpolation {
    bool covered = false;  // the sample lies in a tile of level l
    Tile nodes{};
    std::array<double, 3> weights{};
};
using SamplePlan = std::array<std::array<Interpolation, kSamplesPerTriangle>, 4>;

std::int64_t cross(const SampleWeights& p, const SampleWeights& q, const SampleWeights& r) {
    const std::int64_t ux = q[1] - p[1], uy = q[2] - p[2], vx = r[1] - p[1], vy = r[2] - p[2];
    return ux * vy - uy * vx;
}

SamplePlan make_plan() {
    SamplePlan plan{};
    for (std::size_t c = 0; c < kTilings.size(); ++c)
        for (std::size_t s = 0; s < kSamplesPerTriangle; ++s) {
            const SampleWeights& q = sample_weights()[s];
            for (const Tile& tile : kTilings[c].tiles) {
                const SampleWeights &a = kNodeWeights[tile[0]], &b = kNodeWeights[tile[1]], &d = kNodeWeights[tile[2]];
                const std::int64_t area = cross(a, b, d), wa = cross(q, b, d), wb = cross(a, q, d), wd = cross(a, b, q);
                if (wa < 0 || wb < 0 || wd < 0) continue;
                // Dyadic fractions: exact in doubles.
                plan[c][s] = {true, tile, {double(wa) / double(area), double(wb) / double(area), double(wd) / double(area)}};
                break;
            }
        }
    return plan;
}

// The index in sample_weights() of the sample with weights w.
std::size_t sample_index(const SampleWeights& w) {
    static const auto table = [] {
        std::array<std::array<std::size_t, 5>, 5> t{};
        for (std::size_t s = 0; s < kSamplesPerTriangle; ++s)
            t[static_cast<std::size_t>(sample_weights()[s][0])][static_cast<std::size_t>(sample_weights()[s][1])] = s;
        return t;
    }();
    return table[static_cast<std::size_t>(w[0])][static_cast<std::size_t>(w[1])];
}

const SamplePlan& sample_plan() {
    static const SamplePlan plan = make_plan();
    return plan;
}

}  // namespace

// A corner of T as the rest of the mesh may show it: at T's level, or as coarse as its own error allows.
struct LimitErrorCriterion::Corner {
    glm::dvec3 fine, coarse;
};

LimitErrorCriterion::LimitErrorCriterion(std::shared_ptr<const BaseMesh> base, double tolerance, Samples samples)
    : base_(std::move(base)), evaluator_(*base_), grids_(*base_, evaluator_), tolerance_(tolerance), samples_(samples) {
    if (!(tolerance > 0.0) || !std::isfinite(tolerance)) throw std::invalid_argument("the tolerance must be positive and finite");
}

LimitErrorCriterion::Corner LimitErrorCriterion::corner(const SurfacePoint& p, int level, FaceGridLimits* grid) {
    Corner c;
    // A cage with detail shows a vertex at its detail point whatever its display level.
    if (const DetailPositions* detail = base_->detail()) {
        c.fine = c.coarse = detail->position(*base_, p);
        return c;
    }
    const glm::dvec3 limit = grid->limit_position(p);
    c.fine = grid->control_point(p, level);
    c.coarse = c.fine;
    for (int k = p.level; k < level; ++k) {
        const glm::dvec3 at = grid->control_point(p, k);
        if (glm::distance(at, limit) <= tolerance_) {
            c.coarse = at;
            break;
        }
    }
    return c;
}

std::size_t LimitErrorCriterion::TriangleKeyHash::operator()(const TriangleKey& k) const noexcept {
    std::uint64_t h = (std::uint64_t(k.face) << 8) ^ static_cast<std::uint64_t>(k.level);
    for (std::uint32_t x : {k.sum[0], k.sum[1], k.first[0], k.first[1]}) h = (h ^ x) * 0x9e3779b97f4a7c15ull;
    return static_cast<std::size_t>(h ^ (h >> 31));
}

const std::array<double, 3>& LimitErrorCriterion::triangle_values(const HierarchyTriangle& t) {
    TriangleKey key{t.face, t.level, t.corners[0], {}};
    for (std::size_t i = 0; i < 3; ++i) key.sum[i] = t.corners[0][i] + t.corners[1][i] + t.corners[2][i];
    if (const auto it = triangles_.find(key); it != triangles_.end()) return it->second;

    // Without detail the limit points come from a grid of t's base face (the evaluator's bits, as
    // target_position gives them).
    const DetailPositions* detail = base_->detail();
    FaceGridLimits* grid = detail ? nullptr : &grids_.grid(t.face, t.level + 2);
    std::array<Corner, 3> corners;
    std::array<glm::dvec3, 3> midpoints;  // of edge i
    for (int c = 0; c < 3; ++c) {
        corners[static_cast<std::size_t>(c)] = corner(t.corner(c), t.level, grid);
        SampleWeights w{};
        w[static_cast<std::size_t>(c)] = 2;
        w[static_cast<std::size_t>((c + 1) % 3)] = 2;
        const SurfacePoint midpoint = t.sample(w);
        midpoints[static_cast<std::size_t>(c)] =
            detail ? detail->position(*base_, midpoint) : grid->control_point(midpoint, midpoint.level);
    }
    std::array<glm::dvec3, kSamplesPerTriangle> limits;
    for (std::size_t s = 0; s < kSamplesPerTriangle; ++s) {
        const SurfacePoint sample = t.sample(sample_weights()[s]);
        limits[s] = detail ? detail->position(*base_, sample) : grid->limit_position(sample);
    }

    std::array<double, 3> values{};
    for (std::size_t e = 0; e < 3; ++e) {
        // The plan's X0, X1, X2 are t's corners e, e+1, e+2.
        auto original = [&](std::size_t x) { return (e + x) % 3; };
        auto node_position = [&](Node n, bool coarse) {
            switch (n) {
                case M12: return midpoints[original(1)];
                case M20: return midpoints[original(2)];
                default: {
                    const Corner& c = corners[original(static_cast<std::size_t>(n))];
                    return coarse ? c.coarse : c.fine;
                }
            }
        };
        double worst = 0.0;
        // Beside the edge: the last tiling's pieces (X1, M12, M20) and (X1, M20, X0), with both other edges split.
        const std::size_t first_tiling = samples_ == Samples::BesideTheEdge ? kTilings.size() - 1 : 0;
        for (const auto& tiling : std::span(sample_plan()).subspan(first_tiling))
            for (std::size_t s = 0; s < kSamplesPerTriangle; ++s) {
                const Interpolation& in = tiling[s];
                if (!in.covered) continue;
                SampleWeights w{};
                for (std::size_t x = 0; x < 3; ++x) w[original(x)] = sample_weights()[s][x];
                const glm::dvec3& limit = limits[sample_index(w)];
                // Every choice of fine or coarse for the corners the sample depends on.
                for (int choice = 0; choice < 8; ++choice) {
                    std::array<glm::dvec3, 3> at;
                    bool repeated = false;
                    for (std::size_t i = 0; i < 3; ++i) {
                        const bool coarse = (choice >> i) & 1;
                        if (coarse && (in.nodes[i] == M12 || in.nodes[i] == M20 || in.weights[i] == 0.0)) repeated = true;
                        at[i] = node_position(in.nodes[i], coarse);
                    }
                    if (repeated) continue;
                    worst = std::max(worst, glm::distance(interpolate(at, in.weights), limit));
                }
            }
        values[e] = worst;
    }
    return triangles_.emplace(key, values).first->second;
}

double LimitErrorCriterion::value(const SurfacePoint& a, const SurfacePoint& b) {
    double worst = 0.0;
    for (HierarchyTriangle t : triangles_beside(*base_, a, b)) {
        // The edge runs from corner 0 to corner 1; rotate the smallest corner first, as the cache keys it.
        std::size_t first = 0;
        for (std::size_t c = 1; c < 3; ++c)
            if (t.corners[c] < t.corners[first]) first = c;
        std::rotate(t.corners.begin(), t.corners.begin() + static_cast<std::ptrdiff_t>(first), t.corners.end());
        worst = std::max(worst, triangle_values(t)[(3 - first) % 3]);
    }
    return worst;
}

namespace {

EdgeValue owning_value(std::shared_ptr<LimitErrorCriterion> criterion) {
    return [criterion = std::move(criterion)](const SurfacePoint& a, const SurfacePoint& b) { return criterion->value(a, b); };
}

}  // namespace

EdgeValue detail_error_value(const std::shared_ptr<const BaseMesh>& base) {
    if (!base->detail()) throw std::invalid_argument("detail_error_value: the base mesh has no detail");
    // With detail no corner depends on the tolerance (corner()), so any positive one gives the values.
    return owning_value(std::make_shared<LimitErrorCriterion>(base, std::numeric_limits<double>::max(),
                                                              LimitErrorCriterion::Samples::BesideTheEdge));
}

EdgeValue limit_error_value(const std::shared_ptr<const BaseMesh>& base, double tolerance) {
    return owning_value(std::make_shared<LimitErrorCriterion>(base, tolerance));
}

}  // namespace rgb
