// The dense mesh M: a double-precision BVH of ours for every answer (dense_surface.h says why and how);
// this file searches it, surface_tree.cpp builds it.
#include "detail/dense_surface.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include <glm/geometric.hpp>

#include "detail/surface_tree.h"
#include "rgb/support/parallel.h"

namespace rgbdetail {

namespace dense_surface_internal {

constexpr double kCoordinateLimit = 1e30;
// A line counts as parallel to a triangle when |sin| of its angle with the plane is below this.
constexpr double kParallelSine = 1e-14;

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The line's hits in the order dense_surface.h gives: smaller |t|, positive first, lower triangle.
bool line_before(double ta, std::uint32_t ia, double tb, std::uint32_t ib) {
    const double aa = std::abs(ta), ab = std::abs(tb);
    if (aa != ab) return aa < ab;
    const bool na = ta < 0.0, nb = tb < 0.0;
    if (na != nb) return !na;
    return ia < ib;
}

// Möller–Trumbore in double for the line o + t d (d unit), both directions, edges and corners
// included; no hit where the line is parallel to the plane (or the triangle degenerate).
bool intersect_line(const glm::dvec3& o, const glm::dvec3& d, const Corners& c, double& t, double& u, double& v) {
    const glm::dvec3 e1 = c.p1 - c.p0;
    const glm::dvec3 e2 = c.p2 - c.p0;
    const glm::dvec3 pvec = glm::cross(d, e2);
    const double det = glm::dot(e1, pvec);
    const glm::dvec3 n = glm::cross(e1, e2);
    if (!(det * det > kParallelSine * kParallelSine * glm::dot(n, n))) return false;
    const double inv = 1.0 / det;
    const glm::dvec3 s = o - c.p0;
    u = glm::dot(s, pvec) * inv;
    if (u < 0.0 || u > 1.0) return false;
    const glm::dvec3 qvec = glm::cross(s, e1);
    v = glm::dot(d, qvec) * inv;
    if (v < 0.0 || u + v > 1.0) return false;
    t = glm::dot(e2, qvec) * inv;
    return std::isfinite(t);
}

struct PointOnTriangle {
    glm::dvec3 point{0.0};
    std::array<double, 3> barycentric{};
    double d2 = std::numeric_limits<double>::infinity();
};

// The exact closest point of a triangle: the projection onto its plane when that falls inside, else
// the nearest point of the three (clamped) edges; degenerate triangles take the edge path. Written to
// stay accurate for slivers (aspect ratios of 1e9): the normal is the cross product of the two
// shortest edges, and each inside test measures from the edge's nearer end.
PointOnTriangle closest_on_triangle(const glm::dvec3& p, const Corners& c) {
    PointOnTriangle best;
    const glm::dvec3 corner[3] = {c.p0, c.p1, c.p2};
    const glm::dvec3 edge[3] = {c.p1 - c.p0, c.p2 - c.p1, c.p0 - c.p2};  // edge k runs from corner k to k + 1
    const double len2[3] = {glm::dot(edge[0], edge[0]), glm::dot(edge[1], edge[1]), glm::dot(edge[2], edge[2])};
    int longest = 0;
    if (len2[1] > len2[longest]) longest = 1;
    if (len2[2] > len2[longest]) longest = 2;
    // The two other edges meet at the corner opposite the longest one.
    const glm::dvec3 n = glm::cross(edge[(longest + 1) % 3], edge[(longest + 2) % 3]);
    const double nn = glm::dot(n, n);
    if (nn > 0.0 && std::isfinite(nn)) {
        double side[3];
        bool inside = true;
        for (int k = 0; k < 3 && inside; ++k) {
            const glm::dvec3 from_start = p - corner[k];
            const glm::dvec3 from_end = p - corner[(k + 1) % 3];
            const glm::dvec3 r = glm::dot(from_start, from_start) <= glm::dot(from_end, from_end) ? from_start : from_end;
            side[k] = glm::dot(glm::cross(edge[k], r), n);
            inside = side[k] >= 0.0;
        }
        if (inside) {
            // The weight of corner k is the side of the edge opposite it (edge k + 1).
            const double sum = side[0] + side[1] + side[2];
            if (sum > 0.0) {
                best.barycentric = {side[1] / sum, side[2] / sum, side[0] / sum};
                best.point = best.barycentric[0] * c.p0 + best.barycentric[1] * c.p1 + best.barycentric[2] * c.p2;
                const glm::dvec3 r = p - best.point;
                best.d2 = glm::dot(r, r);
                return best;
            }
        }
    }
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        const glm::dvec3& a = corner[i];
        const glm::dvec3& ab = edge[i];
        double s = len2[i] > 0.0 ? glm::dot(p - a, ab) / len2[i] : 0.0;
        s = std::clamp(s, 0.0, 1.0);
        const glm::dvec3 q = s == 1.0 ? corner[j] : a + s * ab;
        const glm::dvec3 r = p - q;
        const double d2 = glm::dot(r, r);
        if (d2 < best.d2) {
            best.d2 = d2;
            best.point = q;
            best.barycentric = {0.0, 0.0, 0.0};
            best.barycentric[static_cast<std::size_t>(i)] = 1.0 - s;
            best.barycentric[static_cast<std::size_t>(j)] = s;
        }
    }
    return best;
}

struct LineBest {
    bool found = false;
    double t = 0.0;
    std::uint32_t triangle = 0;  // original index
    std::uint32_t slot = 0;      // reordered index
    double u = 0.0, v = 0.0;
};

struct StackEntry {
    std::uint32_t index;
    std::uint8_t kind;
    std::uint8_t count;
    double key;
};

struct Engine {
    std::vector<glm::dvec3> positions;
    std::vector<rgb::Triangle> triangles;
    SurfaceTree tree;
    double box_pad = 0.0;
    double scale = 0.0;                    // largest coordinate magnitude of M (at least its extent / 2)
    glm::dvec3 lo{0.0}, hi{0.0};           // M's bounding box

    Engine() = default;
    Engine(const Engine&) = delete;
    Engine& operator=(const Engine&) = delete;
    ~Engine() = default;

    void line_search(const glm::dvec3& o, const glm::dvec3& d, double bound, LineBest& best) const;
    bool line_box(const glm::dvec3& box_lo, const glm::dvec3& box_hi, const glm::dvec3& o, const glm::dvec3& inv,
                  const bool zero[3], double lim, double& key) const;
    std::optional<SurfaceHit> ray(const glm::dvec3& o, const glm::dvec3& d, double max_distance) const;
    SurfaceHit closest(const glm::dvec3& p) const;
};

// The line's interval through the (padded) box, if it meets |t| <= lim; key is the smallest |t| in it.
bool Engine::line_box(const glm::dvec3& box_lo, const glm::dvec3& box_hi, const glm::dvec3& o, const glm::dvec3& inv,
                      const bool zero[3], double lim, double& key) const {
    double tmin = -std::numeric_limits<double>::infinity();
    double tmax = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
        if (zero[a]) {
            if (o[a] < box_lo[a] || o[a] > box_hi[a]) return false;
            continue;
        }
        double t1 = (box_lo[a] - o[a]) * inv[a];
        double t2 = (box_hi[a] - o[a]) * inv[a];
        if (t1 > t2) std::swap(t1, t2);
        tmin = std::max(tmin, t1);
        tmax = std::min(tmax, t2);
    }
    const double slack = 1e-12 * (std::abs(tmin) + std::abs(tmax));
    if (tmin > tmax + slack) return false;
    const double l = lim * (1.0 + 1e-9) + box_pad;
    if (tmin > l || tmax < -l) return false;
    key = tmin > 0.0 ? tmin : (tmax < 0.0 ? -tmax : 0.0);
    return true;
}

// The best hit (line_before order) with |t| <= bound, searching the double BVH.
void Engine::line_search(const glm::dvec3& o, const glm::dvec3& d, double bound, LineBest& best) const {
    best = LineBest{};
    glm::dvec3 inv(0.0);
    bool zero[3];
    for (int a = 0; a < 3; ++a) {
        zero[a] = d[a] == 0.0;
        inv[a] = zero[a] ? 0.0 : 1.0 / d[a];
    }
    StackEntry stack[128];
    int top = 0;
    stack[top++] = {0, kInnerChild, 0, 0.0};
    while (top > 0) {
        const StackEntry entry = stack[--top];
        double lim = best.found ? std::abs(best.t) : bound;
        if (entry.key > lim * (1.0 + 1e-9) + box_pad) continue;
        if (entry.kind == kLeafChild) {
            for (std::uint32_t s = entry.index; s < entry.index + entry.count; ++s) {
                double t, u, v;
                if (!intersect_line(o, d, tree.corners[s], t, u, v)) continue;
                if (std::abs(t) > bound) continue;
                const std::uint32_t tri = tree.original[s];
                if (!best.found || line_before(t, tri, best.t, best.triangle)) best = {true, t, tri, s, u, v};
            }
            continue;
        }
        const Node& node = tree.nodes[entry.index];
        lim = best.found ? std::abs(best.t) : bound;
        double keys[2];
        bool hit[2];
        for (int c = 0; c < 2; ++c)
            hit[c] = node.kind[c] != kNoChild && line_box(node.box_lo(c), node.box_hi(c), o, inv, zero, lim, keys[c]);
        // The nearer child is popped first.
        const int first = (hit[0] && hit[1] && keys[1] < keys[0]) ? 1 : 0;
        const int order[2] = {1 - first, first};
        for (int c : order)
            if (hit[c]) stack[top++] = {node.index[c], node.kind[c], node.count[c], keys[c]};
    }
}

std::optional<SurfaceHit> Engine::ray(const glm::dvec3& o, const glm::dvec3& d, double max_distance) const {
    LineBest best;
    line_search(o, d, max_distance, best);
    if (!best.found) return std::nullopt;
    const Corners& c = tree.corners[best.slot];
    SurfaceHit hit;
    hit.point = c.p0 + best.u * (c.p1 - c.p0) + best.v * (c.p2 - c.p0);
    hit.triangle = best.triangle;
    hit.barycentric = {1.0 - (best.u + best.v), best.u, best.v};
    hit.distance = std::abs(best.t);
    hit.by_ray = true;
    return hit;
}

SurfaceHit Engine::closest(const glm::dvec3& p) const {
    auto box_d2 = [&](const Node& node, int c) {
        const glm::dvec3 q = glm::clamp(p, node.box_lo(c), node.box_hi(c));
        const glm::dvec3 r = p - q;
        return glm::dot(r, r);
    };
    PointOnTriangle best;
    std::uint32_t best_triangle = std::numeric_limits<std::uint32_t>::max();
    StackEntry stack[128];
    int top = 0;
    stack[top++] = {0, kInnerChild, 0, 0.0};
    while (top > 0) {
        const StackEntry entry = stack[--top];
        if (entry.key > best.d2 * (1.0 + 1e-12)) continue;
        if (entry.kind == kLeafChild) {
            for (std::uint32_t s = entry.index; s < entry.index + entry.count; ++s) {
                // The triangle's own (padded) box first: most of a leaf's triangles are farther than
                // the best.
                const Corners& c = tree.corners[s];
                const glm::dvec3 q = glm::clamp(p, glm::min(glm::min(c.p0, c.p1), c.p2) - box_pad,
                                                glm::max(glm::max(c.p0, c.p1), c.p2) + box_pad);
                const glm::dvec3 r = p - q;
                if (glm::dot(r, r) > best.d2 * (1.0 + 1e-12)) continue;
                const PointOnTriangle candidate = closest_on_triangle(p, c);
                const std::uint32_t tri = tree.original[s];
                if (candidate.d2 < best.d2 || (candidate.d2 == best.d2 && tri < best_triangle)) {
                    best = candidate;
                    best_triangle = tri;
                }
            }
            continue;
        }
        const Node& node = tree.nodes[entry.index];
        double keys[2];
        for (int c = 0; c < 2; ++c)
            keys[c] = node.kind[c] == kNoChild ? std::numeric_limits<double>::infinity() : box_d2(node, c);
        const int first = keys[1] < keys[0] ? 1 : 0;
        const int order[2] = {1 - first, first};
        for (int c : order)
            if (node.kind[c] != kNoChild && keys[c] <= best.d2 * (1.0 + 1e-12)) stack[top++] = {node.index[c], node.kind[c], node.count[c], keys[c]};
    }
    SurfaceHit hit;
    hit.point = best.point;
    hit.triangle = best_triangle;
    hit.barycentric = best.barycentric;
    hit.distance = std::sqrt(best.d2);
    hit.by_ray = false;
    return hit;
}

void check_ray(const glm::dvec3& origin, const glm::dvec3& direction, double max_distance) {
    if (!finite(origin)) throw std::invalid_argument("DenseSurface: the ray's origin is not finite");
    if (!finite(direction)) throw std::invalid_argument("DenseSurface: the ray's direction is not finite");
    if (direction == glm::dvec3(0.0)) throw std::invalid_argument("DenseSurface: the ray's direction is zero");
    if (!std::isfinite(max_distance) || max_distance < 0.0)
        throw std::invalid_argument("DenseSurface: the search distance must be finite and non-negative");
}

void check_point(const glm::dvec3& p) {
    if (!finite(p)) throw std::invalid_argument("DenseSurface: the query point is not finite");
}

// The unit direction; a direction whose length overflows or underflows is scaled first.
glm::dvec3 unit(const glm::dvec3& d) {
    const double m = std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
    const glm::dvec3 s = d / m;
    return s / glm::length(s);
}

void check_sizes(std::size_t a, std::size_t b) {
    if (a != b) throw std::invalid_argument("DenseSurface: origins and directions differ in number");
}

constexpr std::size_t kMinBlock = 256;

// Spreads the low 6 bits of x to every third bit.
std::uint32_t spread_bits(std::uint32_t x) {
    std::uint32_t r = 0;
    for (int b = 0; b < 6; ++b) r |= ((x >> b) & 1u) << (3 * b);
    return r;
}

// The queries in a spatial order: by the Morton code of a 64^3 grid over M's bounding box (points
// outside it clamped to it), the input order within a cell; a counting sort, so linear. Neighbouring
// queries then walk the same BVH nodes and triangles: a batch of a million random points on a
// million triangles otherwise misses the cache at almost every node. Results do not depend on it.
std::vector<std::uint32_t> spatial_order(std::span<const glm::dvec3> points, const glm::dvec3& lo, const glm::dvec3& hi) {
    constexpr std::uint32_t kCells = 1u << 18;
    const glm::dvec3 extent = glm::max(hi - lo, glm::dvec3(std::numeric_limits<double>::min()));
    std::vector<std::uint32_t> cell(points.size());
    std::vector<std::uint32_t> start(kCells + 1, 0);
    for (std::size_t i = 0; i < points.size(); ++i) {
        std::uint32_t code = 0;
        for (int a = 0; a < 3; ++a) {
            const double f = std::clamp((points[i][a] - lo[a]) / extent[a], 0.0, 1.0);
            const auto q = static_cast<std::uint32_t>(std::min(63.0, f * 64.0));
            code |= spread_bits(q) << a;
        }
        cell[i] = code;
        ++start[code + 1];
    }
    for (std::uint32_t k = 0; k < kCells; ++k) start[k + 1] += start[k];
    std::vector<std::uint32_t> order(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) order[start[cell[i]]++] = static_cast<std::uint32_t>(i);
    return order;
}

// Calls body(i) for every i in [0, n) on all cores, in spatial_order of points when the batch is
// large enough to gain from it.
template <class Body>
void for_each_query(std::span<const glm::dvec3> points, const glm::dvec3& lo, const glm::dvec3& hi, const Body& body) {
    const std::size_t n = points.size();
    if (n < 4 * kMinBlock) {
        rgb::parallel_for(n, kMinBlock, [&](std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) body(i);
        });
        return;
    }
    const std::vector<std::uint32_t> order = spatial_order(points, lo, hi);
    rgb::parallel_for(n, kMinBlock, [&](std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k) body(order[k]);
    });
}

}  // namespace dense_surface_internal

namespace dsi = dense_surface_internal;

struct DenseSurface::Impl : dsi::Engine {};

DenseSurface::DenseSurface(std::vector<glm::dvec3> positions, std::vector<rgb::Triangle> triangles, const ProgressFunction& progress)
    : impl_(std::make_unique<Impl>()) {
    report_share(progress, 0.0);
    if (triangles.empty()) throw std::invalid_argument("DenseSurface: the mesh has no triangles");
    if (triangles.size() >= std::numeric_limits<std::uint32_t>::max())
        throw std::invalid_argument("DenseSurface: the mesh has too many triangles");
    for (std::size_t v = 0; v < positions.size(); ++v) {
        const glm::dvec3& p = positions[v];
        if (!dsi::finite(p) || std::abs(p.x) > dsi::kCoordinateLimit || std::abs(p.y) > dsi::kCoordinateLimit ||
            std::abs(p.z) > dsi::kCoordinateLimit)
            throw std::invalid_argument("DenseSurface: position " + std::to_string(v) +
                                        " is not finite or beyond 1e30");
    }
    for (std::size_t f = 0; f < triangles.size(); ++f)
        for (std::uint32_t v : triangles[f])
            if (v >= positions.size())
                throw std::invalid_argument("DenseSurface: triangle " + std::to_string(f) +
                                            " has a vertex index out of range");
    Impl& m = *impl_;
    m.positions = std::move(positions);
    m.triangles = std::move(triangles);
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (const rgb::Triangle& t : m.triangles)
        for (std::uint32_t v : t) {
            lo = glm::min(lo, m.positions[v]);
            hi = glm::max(hi, m.positions[v]);
        }
    m.lo = lo;
    m.hi = hi;
    m.scale = std::max({std::abs(lo.x), std::abs(lo.y), std::abs(lo.z), std::abs(hi.x), std::abs(hi.y),
                        std::abs(hi.z), glm::length(hi - lo)});
    // Rounding in a triangle's intersection or closest point is far below this.
    m.box_pad = 1e-10 * m.scale + std::numeric_limits<double>::denorm_min();
    m.tree = dsi::build_surface_tree(m.positions, m.triangles, m.box_pad, progress);
    report_share(progress, 1.0);
}

DenseSurface::~DenseSurface() = default;
DenseSurface::DenseSurface(DenseSurface&&) noexcept = default;
DenseSurface& DenseSurface::operator=(DenseSurface&&) noexcept = default;

std::size_t DenseSurface::num_triangles() const { return impl_->triangles.size(); }
std::span<const glm::dvec3> DenseSurface::positions() const { return impl_->positions; }
std::span<const rgb::Triangle> DenseSurface::triangles() const { return impl_->triangles; }

std::optional<SurfaceHit> DenseSurface::nearest_ray_hit(const glm::dvec3& origin, const glm::dvec3& direction,
                                                        double max_distance) const {
    dsi::check_ray(origin, direction, max_distance);
    return impl_->ray(origin, dsi::unit(direction), max_distance);
}

SurfaceHit DenseSurface::closest_point(const glm::dvec3& p) const {
    dsi::check_point(p);
    return impl_->closest(p);
}

SurfaceHit DenseSurface::project(const glm::dvec3& origin, const glm::dvec3& direction, double max_distance) const {
    dsi::check_ray(origin, direction, max_distance);
    if (std::optional<SurfaceHit> hit = impl_->ray(origin, dsi::unit(direction), max_distance)) return *hit;
    return impl_->closest(origin);
}

std::vector<std::optional<SurfaceHit>> DenseSurface::nearest_ray_hits(std::span<const glm::dvec3> origins,
                                                                      std::span<const glm::dvec3> directions,
                                                                      double max_distance) const {
    dsi::check_sizes(origins.size(), directions.size());
    for (std::size_t i = 0; i < origins.size(); ++i) dsi::check_ray(origins[i], directions[i], max_distance);
    std::vector<std::optional<SurfaceHit>> out(origins.size());
    dsi::for_each_query(origins, impl_->lo, impl_->hi,
                        [&](std::size_t i) { out[i] = impl_->ray(origins[i], dsi::unit(directions[i]), max_distance); });
    return out;
}

std::vector<SurfaceHit> DenseSurface::closest_points(std::span<const glm::dvec3> points) const {
    for (const glm::dvec3& p : points) dsi::check_point(p);
    std::vector<SurfaceHit> out(points.size());
    dsi::for_each_query(points, impl_->lo, impl_->hi, [&](std::size_t i) { out[i] = impl_->closest(points[i]); });
    return out;
}

std::vector<SurfaceHit> DenseSurface::projections(std::span<const glm::dvec3> origins,
                                                  std::span<const glm::dvec3> directions, double max_distance) const {
    dsi::check_sizes(origins.size(), directions.size());
    for (std::size_t i = 0; i < origins.size(); ++i) dsi::check_ray(origins[i], directions[i], max_distance);
    std::vector<SurfaceHit> out(origins.size());
    dsi::for_each_query(origins, impl_->lo, impl_->hi, [&](std::size_t i) {
        if (std::optional<SurfaceHit> hit = impl_->ray(origins[i], dsi::unit(directions[i]), max_distance)) out[i] = *hit;
        else out[i] = impl_->closest(origins[i]);
    });
    return out;
}

}  // namespace rgbdetail
