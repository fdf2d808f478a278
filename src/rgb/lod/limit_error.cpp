#include "rgb/lod/limit_error.h"

#include <algorithm>
#include <cmath>
#include <cstring>
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

// A sample in a tile of level l: which sample, its barycentric weights over the tile's nodes, and
// the nodes it does not depend on (bit i for node i: weight 0).
struct TileSample {
    std::size_t sample = 0;
    std::array<double, 3> weights{};
    unsigned unused_nodes = 0;
};
// [tiling][tile]: the samples each tile holds (a sample on a cut in the first).
using SamplePlan = std::array<std::array<InlineVector<TileSample, kSamplesPerTriangle>, 2>, 4>;

std::int64_t cross(const SampleWeights& p, const SampleWeights& q, const SampleWeights& r) {
    const std::int64_t ux = q[1] - p[1], uy = q[2] - p[2], vx = r[1] - p[1], vy = r[2] - p[2];
    return ux * vy - uy * vx;
}

SamplePlan make_plan() {
    SamplePlan plan{};
    for (std::size_t c = 0; c < kTilings.size(); ++c)
        for (std::size_t s = 0; s < kSamplesPerTriangle; ++s) {
            const SampleWeights& q = sample_weights()[s];
            for (std::size_t k = 0; k < kTilings[c].tiles.size(); ++k) {
                const Tile& tile = kTilings[c].tiles[k];
                const SampleWeights &a = kNodeWeights[tile[0]], &b = kNodeWeights[tile[1]], &d = kNodeWeights[tile[2]];
                const std::int64_t area = cross(a, b, d), wa = cross(q, b, d), wb = cross(a, q, d), wd = cross(a, b, q);
                if (wa < 0 || wb < 0 || wd < 0) continue;
                // Dyadic fractions: exact in doubles.
                const unsigned unused = (wa == 0 ? 1u : 0u) | (wb == 0 ? 2u : 0u) | (wd == 0 ? 4u : 0u);
                plan[c][k].push_back({s, {double(wa) / double(area), double(wb) / double(area), double(wd) / double(area)}, unused});
                break;
            }
        }
    return plan;
}

// rotated_samples()[e][s]: the index in sample_weights() of sample s of the plan when its X0, X1, X2
// are the triangle's corners e, e+1, e+2.
using RotatedSamples = std::array<std::array<std::size_t, kSamplesPerTriangle>, 3>;
const RotatedSamples& rotated_samples() {
    static const RotatedSamples table = [] {
        std::array<std::array<std::size_t, 5>, 5> index{};
        for (std::size_t s = 0; s < kSamplesPerTriangle; ++s)
            index[static_cast<std::size_t>(sample_weights()[s][0])][static_cast<std::size_t>(sample_weights()[s][1])] = s;
        RotatedSamples t{};
        for (std::size_t e = 0; e < 3; ++e)
            for (std::size_t s = 0; s < kSamplesPerTriangle; ++s) {
                SampleWeights w{};
                for (std::size_t x = 0; x < 3; ++x) w[(e + x) % 3] = sample_weights()[s][x];
                t[e][s] = index[static_cast<std::size_t>(w[0])][static_cast<std::size_t>(w[1])];
            }
        return t;
    }();
    return table;
}

const SamplePlan& sample_plan() {
    static const SamplePlan plan = make_plan();
    return plan;
}

// A corner of T as the rest of the mesh may show it: at T's level, or as coarse as its own error allows.
struct ShownCorner {
    glm::dvec3 fine, coarse;
    bool coarser = false;  // coarse is not fine, bit for bit (else showing it coarse repeats showing it fine)
};

// `grid`: the corner's base face's (null with detail); `limit`: the corner's limit point (its sample's).
ShownCorner shown_corner(const BaseMesh& base, const SurfacePoint& p, int level, FaceGridLimits* grid, const glm::dvec3& limit,
                         double tolerance) {
    ShownCorner c;
    // A cage with detail shows a vertex at its detail point whatever its display level.
    if (const DetailPositions* detail = base.detail()) {
        c.fine = c.coarse = detail->position(base, p);
        return c;
    }
    c.fine = grid->control_point(p, level);
    c.coarse = c.fine;
    for (int k = p.level; k < level; ++k) {
        const glm::dvec3 at = grid->control_point(p, k);
        if (glm::distance(at, limit) <= tolerance) {
            c.coarse = at;
            break;
        }
    }
    c.coarser = std::memcmp(&c.coarse, &c.fine, sizeof(glm::dvec3)) != 0;
    return c;
}

// What a triangle's tilings are measured with, in the triangle's own corner order.
struct TrianglePoints {
    std::array<ShownCorner, 3> corners;
    std::array<glm::dvec3, 3> midpoints;  // of edge c (corners c, c+1)
    std::array<glm::dvec3, kSamplesPerTriangle> limits;  // of the samples, in sample_weights()'s order
};

// Where node n lies when the plan's X0, X1, X2 are the triangle's corners e, e+1, e+2.
const glm::dvec3& node_position(const TrianglePoints& t, std::size_t e, Node n, bool coarse) {
    switch (n) {
        case M12: return t.midpoints[(e + 1) % 3];
        case M20: return t.midpoints[(e + 2) % 3];
        default: {
            const ShownCorner& c = t.corners[(e + static_cast<std::size_t>(n)) % 3];
            return coarse ? c.coarse : c.fine;
        }
    }
}

// Whether node n, X0 at corner e, has a coarser position than its fine one (a midpoint has none).
bool has_coarser(const TrianglePoints& t, std::size_t e, Node n) {
    return n != M12 && n != M20 && t.corners[(e + static_cast<std::size_t>(n)) % 3].coarser;
}

// The largest distance to the limit surface of tiling c's pieces with X0 at corner e, over their
// samples and every choice of fine or coarse for the corners a sample depends on. A choice that
// repeats another (coarse where the sample does not depend on the node, or where the node has no
// coarser position) is left out: the same bits. Each piece's corners are ordered once per choice, for
// all its samples (the bits of interpolate), and the square root is taken once, of the largest
// square (it is monotone: the same bits as the largest root).
double tiling_error(const TrianglePoints& t, std::size_t c, std::size_t e) {
    double worst_squared = 0.0;
    for (std::size_t k = 0; k < kTilings[c].tiles.size(); ++k) {
        const Tile& tile = kTilings[c].tiles[k];
        unsigned coarser = 0;  // bit i: node i has a coarser position
        for (std::size_t i = 0; i < 3; ++i) coarser |= has_coarser(t, e, tile[i]) ? 1u << i : 0u;
        for (unsigned choice = 0; choice < 8; ++choice) {
            if ((choice & coarser) != choice) continue;
            std::array<glm::dvec3, 3> at;
            for (std::size_t i = 0; i < 3; ++i) at[i] = node_position(t, e, tile[i], (choice >> i) & 1u);
            const std::array<int, 3> order = interpolation_order(at);
            for (const TileSample& in : sample_plan()[c][k]) {
                if (choice & in.unused_nodes) continue;
                const glm::dvec3 d = t.limits[rotated_samples()[e][in.sample]] - interpolate_in_order(at, order, in.weights);
                worst_squared = std::max(worst_squared, glm::dot(d, d));
            }
        }
    }
    return std::sqrt(worst_squared);
}

// Whether interpolation_order puts the corners in one order whichever way they are shown and
// listed: no two different corners at positions it cannot tell apart (equal, or with a NaN).
bool corners_apart(const std::array<ShownCorner, 3>& corners) {
    auto ordered = [](const glm::dvec3& x, const glm::dvec3& y) {
        for (const glm::dvec3* v : {&x, &y})
            if (std::isnan(v->x) || std::isnan(v->y) || std::isnan(v->z)) return false;
        return x.x != y.x || x.y != y.y || x.z != y.z;
    };
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = i + 1; j < 3; ++j)
            for (const glm::dvec3* x : {&corners[i].fine, &corners[i].coarse})
                for (const glm::dvec3* y : {&corners[j].fine, &corners[j].coarse})
                    if (!ordered(*x, *y)) return false;
    return true;
}

// The values of the three edges (edge e: corners e, e+1) from the pieces of level l. Tiling 1 at e
// (edge e+1 split alone) is tiling 2 at e+2, piece for piece and node for node, so each edge split
// alone is measured once; and the unsplit triangle (tiling 0) is the same pieces and samples at every
// e, with the same bits where its corners are apart (interpolate orders tied corners as listed).
std::array<double, 3> edge_values(const TrianglePoints& t, LimitErrorCriterion::Samples samples) {
    std::array<double, 3> values{};
    // Beside the edge: the last tiling's pieces (X1, M12, M20) and (X1, M20, X0), with both other edges split.
    if (samples == LimitErrorCriterion::Samples::BesideTheEdge) {
        for (std::size_t e = 0; e < 3; ++e) values[e] = tiling_error(t, 3, e);
        return values;
    }
    std::array<double, 3> alone{};  // edge j split alone
    for (std::size_t j = 0; j < 3; ++j) alone[j] = tiling_error(t, 1, (j + 2) % 3);
    const double whole = tiling_error(t, 0, 0);
    const bool apart = corners_apart(t.corners);
    for (std::size_t e = 0; e < 3; ++e)
        values[e] = std::max({e == 0 || apart ? whole : tiling_error(t, 0, e), alone[(e + 1) % 3], alone[(e + 2) % 3], tiling_error(t, 3, e)});
    return values;
}

}  // namespace

LimitErrorCriterion::LimitErrorCriterion(std::shared_ptr<const BaseMesh> base, double tolerance, Samples samples)
    : base_(std::move(base)), evaluator_(*base_), grids_(*base_, evaluator_), tolerance_(tolerance), samples_(samples) {
    if (!(tolerance > 0.0) || !std::isfinite(tolerance)) throw std::invalid_argument("the tolerance must be positive and finite");
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
    TrianglePoints points;
    for (std::size_t s = 0; s < kSamplesPerTriangle; ++s) {
        const SurfacePoint sample = t.sample(sample_weights()[s]);
        points.limits[s] = detail ? detail->position(*base_, sample) : grid->limit_position(sample);
    }
    for (int c = 0; c < 3; ++c) {
        // The plan's sample 0, X0 itself, is corner c when X0 is.
        const glm::dvec3& limit = points.limits[rotated_samples()[static_cast<std::size_t>(c)][0]];
        points.corners[static_cast<std::size_t>(c)] = shown_corner(*base_, t.corner(c), t.level, grid, limit, tolerance_);
        SampleWeights w{};
        w[static_cast<std::size_t>(c)] = 2;
        w[static_cast<std::size_t>((c + 1) % 3)] = 2;
        const SurfacePoint midpoint = t.sample(w);
        points.midpoints[static_cast<std::size_t>(c)] =
            detail ? detail->position(*base_, midpoint) : grid->control_point(midpoint, midpoint.level);
    }
    return triangles_.emplace(key, edge_values(points, samples_)).first->second;
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
