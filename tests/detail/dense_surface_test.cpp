// The dense mesh's queries (src/detail/dense_surface.h) against a brute-force oracle of this file's
// own: every triangle tried, in double (Möller–Trumbore for lines, Ericson's region test for the
// closest point, a different algorithm from the library's). Lines that pass within 1e-9 of an edge
// or of the end of the search may be decided either way by two correct implementations; the oracle
// runs twice, strict (barycentrics >= 1e-9) and loose (>= -1e-9), and a hit must lie between them.
// Exact cases (a grid on integer coordinates, rays on dyadic coordinates through its edges and
// corners, rays along the grid's plane) must agree exactly, triangle index included.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <glm/geometric.hpp>

#include "detail/dense_surface.h"

namespace dense_surface_test {

using rgb::Triangle;
using rgbdetail::DenseSurface;
using rgbdetail::SurfaceHit;

struct Soup {
    std::vector<glm::dvec3> positions;
    std::vector<Triangle> triangles;
    double scale = 1.0;  // largest coordinate magnitude, for tolerances
};

// ---------------------------------------------------------------------------------------------
// Generated meshes
// ---------------------------------------------------------------------------------------------

Soup uv_sphere(int rings, int segments, double radius = 1.0) {
    Soup s;
    s.positions.push_back({0, 0, radius});
    for (int i = 1; i < rings; ++i) {
        const double theta = std::numbers::pi * i / rings;
        for (int j = 0; j < segments; ++j) {
            const double phi = 2 * std::numbers::pi * j / segments;
            s.positions.push_back(radius * glm::dvec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                                                      std::cos(theta)));
        }
    }
    s.positions.push_back({0, 0, -radius});
    const auto south = static_cast<std::uint32_t>(s.positions.size() - 1);
    auto at = [&](int i, int j) { return static_cast<std::uint32_t>(1 + (i - 1) * segments + (j % segments)); };
    for (int j = 0; j < segments; ++j) s.triangles.push_back({0, at(1, j), at(1, j + 1)});
    for (int i = 1; i + 1 < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            s.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            s.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    for (int j = 0; j < segments; ++j) s.triangles.push_back({at(rings - 1, j), south, at(rings - 1, j + 1)});
    s.scale = radius;
    return s;
}

glm::dvec3 torus_point(double u, double v, double big, double small) {
    return {(big + small * std::cos(v)) * std::cos(u), (big + small * std::cos(v)) * std::sin(u), small * std::sin(v)};
}

Soup torus(int nu, int nv, double big = 1.0, double small = 0.35) {
    Soup s;
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j)
            s.positions.push_back(torus_point(2 * std::numbers::pi * i / nu, 2 * std::numbers::pi * j / nv, big, small));
    auto at = [&](int i, int j) { return static_cast<std::uint32_t>((i % nu) * nv + (j % nv)); };
    s.triangles.reserve(2 * static_cast<std::size_t>(nu) * static_cast<std::size_t>(nv));
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            s.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            s.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    s.scale = big + small;
    return s;
}

// A flat grid on integer coordinates z = 0, [0, n]^2, diagonals alternating.
Soup flat_grid(int n) {
    Soup s;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) s.positions.push_back({i, j, 0});
    auto at = [&](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            if ((i + j) % 2 == 0) {
                s.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
                s.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
            } else {
                s.triangles.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
                s.triangles.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
            }
        }
    s.scale = n;
    return s;
}

// A height field on a grid whose spacing grows geometrically from 1e-6 at the centre to about 1e3
// at the rim: triangles from 1e-12 to 1e6 in area.
Soup graded_grid() {
    std::vector<double> xs{0.0};
    for (double x = 1e-6; x < 2e3; x *= 1.6) {
        xs.push_back(x);
        xs.insert(xs.begin(), -x);
    }
    const int n = static_cast<int>(xs.size());
    Soup s;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double x = xs[static_cast<std::size_t>(i)], y = xs[static_cast<std::size_t>(j)];
            s.positions.push_back({x, y, 0.3 * std::sin(x + 2 * y) * std::min(1.0, std::abs(x) + std::abs(y))});
        }
    auto at = [&](int i, int j) { return static_cast<std::uint32_t>(j * n + i); };
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i) {
            s.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            s.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    s.scale = xs.back();
    return s;
}

// ---------------------------------------------------------------------------------------------
// The oracle
// ---------------------------------------------------------------------------------------------

struct OracleHit {
    double t = 0.0;  // signed
    std::uint32_t triangle = 0;
    glm::dvec3 point{0.0};
};

// Möller–Trumbore, barycentrics >= -slack (slack < 0: strict); t along the unit direction d.
std::optional<OracleHit> oracle_triangle(const Soup& m, std::uint32_t f, const glm::dvec3& o, const glm::dvec3& d,
                                         double slack) {
    const glm::dvec3 a = m.positions[m.triangles[f][0]], b = m.positions[m.triangles[f][1]],
                     c = m.positions[m.triangles[f][2]];
    const glm::dvec3 e1 = b - a, e2 = c - a;
    const glm::dvec3 pvec = glm::cross(d, e2);
    const double det = glm::dot(e1, pvec);
    if (det == 0.0) return std::nullopt;
    const glm::dvec3 s = o - a;
    const double u = glm::dot(s, pvec) / det;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(d, q) / det;
    const double w = 1.0 - u - v;
    if (u < -slack || v < -slack || w < -slack) return std::nullopt;
    OracleHit h;
    h.t = glm::dot(e2, q) / det;
    h.triangle = f;
    h.point = a + u * e1 + v * e2;
    return h;
}

bool oracle_before(const OracleHit& x, const OracleHit& y) {
    if (std::abs(x.t) != std::abs(y.t)) return std::abs(x.t) < std::abs(y.t);
    if ((x.t < 0) != (y.t < 0)) return x.t >= 0;
    return x.triangle < y.triangle;
}

std::optional<OracleHit> oracle_ray(const Soup& m, const glm::dvec3& o, const glm::dvec3& d, double max_distance,
                                    double slack) {
    std::optional<OracleHit> best;
    const double limit = max_distance * (1.0 + slack) + slack * m.scale;
    for (std::uint32_t f = 0; f < m.triangles.size(); ++f) {
        const std::optional<OracleHit> h = oracle_triangle(m, f, o, d, slack);
        if (!h || std::abs(h->t) > limit) continue;
        if (!best || oracle_before(*h, *best)) best = h;
    }
    return best;
}

struct OraclePoint {
    glm::dvec3 point{0.0};
    double distance = 0.0;
    std::uint32_t triangle = 0;
};

// Ericson, Real-Time Collision Detection §5.1.5.
glm::dvec3 ericson_closest(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return a;
    const glm::dvec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
    const glm::dvec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
    const double denom = 1.0 / (va + vb + vc);
    return a + ab * (vb * denom) + ac * (vc * denom);
}

double distance_to_triangle(const Soup& m, std::uint32_t f, const glm::dvec3& p) {
    return glm::length(p - ericson_closest(p, m.positions[m.triangles[f][0]], m.positions[m.triangles[f][1]],
                                           m.positions[m.triangles[f][2]]));
}

OraclePoint oracle_closest(const Soup& m, const glm::dvec3& p) {
    OraclePoint best;
    best.distance = std::numeric_limits<double>::infinity();
    for (std::uint32_t f = 0; f < m.triangles.size(); ++f) {
        const glm::dvec3 q = ericson_closest(p, m.positions[m.triangles[f][0]], m.positions[m.triangles[f][1]],
                                             m.positions[m.triangles[f][2]]);
        const double dist = glm::length(p - q);
        if (dist < best.distance) best = {q, dist, f};
    }
    return best;
}

// ---------------------------------------------------------------------------------------------
// Checks
// ---------------------------------------------------------------------------------------------

constexpr double kAmbiguity = 1e-9;

double tolerance(const Soup& m, const glm::dvec3& p) { return 1e-9 * std::max(1.0, glm::length(p)) + 1e-12 * m.scale; }

struct RayCase {
    glm::dvec3 origin;
    glm::dvec3 direction;  // any length
    double max_distance;
};

struct Tally {
    int exact = 0;      // strict and loose oracles agreed, and so did the library
    int ambiguous = 0;  // within 1e-9 of an edge or of the search's end
    int misses = 0;
};

// Checks one ray against the oracle; returns whether the case was unambiguous.
void check_ray(const Soup& m, const DenseSurface& surface, const RayCase& c, Tally& tally) {
    const glm::dvec3 d = glm::normalize(c.direction);
    const std::optional<SurfaceHit> got = surface.nearest_ray_hit(c.origin, c.direction, c.max_distance);
    const std::optional<OracleHit> strict = oracle_ray(m, c.origin, d, c.max_distance * (1 - 1e-9), -kAmbiguity);
    const std::optional<OracleHit> loose = oracle_ray(m, c.origin, d, c.max_distance, kAmbiguity);
    const std::string where = "origin (" + std::to_string(c.origin.x) + ", " + std::to_string(c.origin.y) + ", " +
                              std::to_string(c.origin.z) + ") direction (" + std::to_string(c.direction.x) + ", " +
                              std::to_string(c.direction.y) + ", " + std::to_string(c.direction.z) + ")";
    if (!loose) {
        EXPECT_FALSE(got.has_value()) << where;
        ++tally.misses;
        return;
    }
    if (strict) {
        ASSERT_TRUE(got.has_value()) << where;
    }
    if (!got) {
        ++tally.ambiguous;
        return;
    }
    const double tol = tolerance(m, got->point);
    EXPECT_TRUE(got->by_ray);
    EXPECT_LE(got->distance, c.max_distance) << where;
    EXPECT_GE(got->distance, std::abs(loose->t) - tol) << where;
    if (strict) {
        EXPECT_LE(got->distance, std::abs(strict->t) + tol) << where;
    }
    // The library's triangle is hit there (loosely), at its point.
    const std::optional<OracleHit> own = oracle_triangle(m, got->triangle, c.origin, d, kAmbiguity);
    ASSERT_TRUE(own.has_value()) << where;
    EXPECT_NEAR(std::abs(own->t), got->distance, tol) << where;
    EXPECT_LE(glm::length(own->point - got->point), tol) << where;
    // On the triangle: the barycentric combination of its corners.
    const Triangle& t = m.triangles[got->triangle];
    const glm::dvec3 combination = got->barycentric[0] * m.positions[t[0]] + got->barycentric[1] * m.positions[t[1]] +
                                   got->barycentric[2] * m.positions[t[2]];
    EXPECT_LE(glm::length(combination - got->point), 1e-12 * std::max(1.0, glm::length(got->point)) + 1e-15 * m.scale);
    for (double b : got->barycentric) EXPECT_GE(b, 0.0);
    EXPECT_NEAR(got->barycentric[0] + got->barycentric[1] + got->barycentric[2], 1.0, 1e-12);
    // The point is on the line.
    const glm::dvec3 off = got->point - c.origin;
    EXPECT_LE(glm::length(off - glm::dot(off, d) * d), tol) << where;
    if (strict && strict->triangle == loose->triangle && strict->t == loose->t) {
        // Unambiguous: the same triangle, or one the line meets equally near.
        if (got->triangle != strict->triangle) {
            EXPECT_NEAR(std::abs(own->t), std::abs(strict->t), tol) << where;
        }
        EXPECT_LE(glm::length(got->point - strict->point), tol) << where;
        ++tally.exact;
    } else {
        ++tally.ambiguous;
    }
}

void check_closest(const Soup& m, const DenseSurface& surface, const glm::dvec3& p) {
    const SurfaceHit got = surface.closest_point(p);
    const OraclePoint want = oracle_closest(m, p);
    const double tol = tolerance(m, want.point);
    EXPECT_FALSE(got.by_ray);
    EXPECT_NEAR(got.distance, want.distance, 1e-12 * std::max(1.0, glm::length(p)) + 1e-13 * m.scale);
    EXPECT_NEAR(glm::length(p - got.point), got.distance, tol);
    // The library's triangle is an equally near one.
    EXPECT_NEAR(distance_to_triangle(m, got.triangle, p), want.distance, 1e-12 * std::max(1.0, glm::length(p)) + 1e-13 * m.scale);
    if (got.triangle == want.triangle) {
        EXPECT_LE(glm::length(got.point - want.point), tol);
    }
    const Triangle& t = m.triangles[got.triangle];
    const glm::dvec3 combination =
        got.barycentric[0] * m.positions[t[0]] + got.barycentric[1] * m.positions[t[1]] + got.barycentric[2] * m.positions[t[2]];
    EXPECT_LE(glm::length(combination - got.point), 1e-12 * std::max(1.0, glm::length(got.point)) + 1e-15 * m.scale);
}

bool same(const SurfaceHit& a, const SurfaceHit& b) {
    return a.point == b.point && a.triangle == b.triangle && a.barycentric == b.barycentric && a.distance == b.distance &&
           a.by_ray == b.by_ray;
}
bool same(const std::optional<SurfaceHit>& a, const std::optional<SurfaceHit>& b) {
    return a.has_value() == b.has_value() && (!a || same(*a, *b));
}

DenseSurface surface_of(const Soup& m) { return DenseSurface(m.positions, m.triangles); }

glm::dvec3 random_unit(std::mt19937_64& rng) {
    std::normal_distribution<double> n(0.0, 1.0);
    for (;;) {
        const glm::dvec3 v(n(rng), n(rng), n(rng));
        if (glm::length(v) > 1e-3) return glm::normalize(v);
    }
}

// Random lines: through the bounding region, from points near the surface along its rough normal,
// and through the middles and corners of random edges (where a float ray may slip through).
std::vector<RayCase> random_rays(const Soup& m, int count, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<RayCase> rays;
    glm::dvec3 lo(1e300), hi(-1e300);
    for (const glm::dvec3& p : m.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const glm::dvec3 centre = (lo + hi) / 2.0;
    const glm::dvec3 half = (hi - lo) * 0.75 + glm::dvec3(1e-3 * m.scale);
    for (int i = 0; i < count; ++i) {
        const int kind = i % 3;
        RayCase c;
        if (kind == 0) {
            c.origin = centre + glm::dvec3(2 * unit(rng) - 1, 2 * unit(rng) - 1, 2 * unit(rng) - 1) * half;
            c.direction = random_unit(rng) * (0.5 + 3 * unit(rng));
            c.max_distance = (0.05 + 2 * unit(rng)) * m.scale;
        } else {
            const Triangle& t = m.triangles[rng() % m.triangles.size()];
            const glm::dvec3 a = m.positions[t[0]], b = m.positions[t[1]], cc = m.positions[t[2]];
            glm::dvec3 n = glm::cross(b - a, cc - a);
            n = glm::length(n) > 0 ? glm::normalize(n) : random_unit(rng);
            const double size = std::max(glm::length(b - a), 1e-12 * m.scale);
            const glm::dvec3 target = kind == 1 ? a + unit(rng) * (b - a) : (unit(rng) < 0.5 ? a : b);
            const double offset = (unit(rng) - 0.5) * 4 * size;
            c.origin = target + offset * n;
            c.direction = glm::normalize(n + 0.2 * random_unit(rng)) * (unit(rng) < 0.5 ? 1.0 : -1.0);
            c.max_distance = (0.5 + 3 * unit(rng)) * size;
        }
        rays.push_back(c);
    }
    return rays;
}

std::vector<glm::dvec3> random_points(const Soup& m, int count, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    glm::dvec3 lo(1e300), hi(-1e300);
    for (const glm::dvec3& p : m.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const glm::dvec3 centre = (lo + hi) / 2.0;
    const glm::dvec3 half = (hi - lo) * 0.75 + glm::dvec3(1e-3 * m.scale);
    std::vector<glm::dvec3> points;
    for (int i = 0; i < count; ++i) {
        if (i % 2 == 0) {
            points.push_back(centre + glm::dvec3(2 * unit(rng) - 1, 2 * unit(rng) - 1, 2 * unit(rng) - 1) * half);
        } else {
            // Near a random vertex, at about its edges' scale.
            const Triangle& t = m.triangles[rng() % m.triangles.size()];
            const glm::dvec3 a = m.positions[t[0]];
            const double size = std::max(glm::length(m.positions[t[1]] - a), 1e-12 * m.scale);
            points.push_back(a + random_unit(rng) * (2 * size * unit(rng)));
        }
    }
    return points;
}

// Under the sanitizers (test code at -O0) the brute-force oracle of every query was most of the
// sanitizer run of this file; there a quarter of the queries are asked, all of them in Release.
#if defined(__SANITIZE_ADDRESS__)
constexpr int kQueryShare = 4;
#else
constexpr int kQueryShare = 1;
#endif

void check_mesh(const Soup& m, int all_rays, int all_points, std::uint64_t seed) {
    const int rays = all_rays / kQueryShare, points = all_points / kQueryShare;
    const DenseSurface surface = surface_of(m);
    EXPECT_EQ(surface.num_triangles(), m.triangles.size());
    const std::vector<RayCase> cases = random_rays(m, rays, seed);
    Tally tally;
    for (const RayCase& c : cases) {
        check_ray(m, surface, c, tally);
        if (testing::Test::HasFatalFailure()) return;
    }
    std::cout << "[ rays ] " << cases.size() << ": " << tally.exact << " hits as the oracle, " << tally.misses
              << " misses, " << tally.ambiguous << " within 1e-9 of an edge or the end\n";
    EXPECT_GT(tally.exact, rays / 4);
    EXPECT_GT(tally.misses, 0);
    for (const glm::dvec3& p : random_points(m, points, seed + 1)) check_closest(m, surface, p);
    // project: the ray, else the closest point to the origin.
    for (std::size_t i = 0; i < std::min<std::size_t>(cases.size(), 200); ++i) {
        const RayCase& c = cases[i];
        const SurfaceHit p = surface.project(c.origin, c.direction, c.max_distance);
        const std::optional<SurfaceHit> r = surface.nearest_ray_hit(c.origin, c.direction, c.max_distance);
        EXPECT_TRUE(same(p, r ? *r : surface.closest_point(c.origin)));
    }
}

// ---------------------------------------------------------------------------------------------
// Tests
// ---------------------------------------------------------------------------------------------

TEST(DenseSurface, SphereAgreesWithBruteForce) { check_mesh(uv_sphere(24, 48), 3000, 1500, 11); }

TEST(DenseSurface, TorusAgreesWithBruteForce) { check_mesh(torus(64, 32), 3000, 1500, 12); }

TEST(DenseSurface, FlatGridAgreesWithBruteForce) { check_mesh(flat_grid(16), 3000, 1500, 13); }

TEST(DenseSurface, TinyAndHugeTrianglesAgreeWithBruteForce) {
    const Soup m = graded_grid();
    std::cout << "[ mesh ] graded grid: " << m.triangles.size() << " triangles, coordinates to " << m.scale << "\n";
    check_mesh(m, 3000, 1500, 14);
}

// Vertical rays on dyadic coordinates through the grid's faces, edges (interior and boundary) and
// corners: Möller–Trumbore is exact there, so the triangle must be the oracle's (the lowest index of
// those the line meets at the same t), the point exactly the oracle's.
TEST(DenseSurface, FlatGridEdgesAndCornersExactly) {
    const int n = 8;
    const Soup m = flat_grid(n);
    const DenseSurface surface = surface_of(m);
    int on_edges = 0;
    for (int yi = -2; yi <= 4 * n + 2; ++yi)
        for (int xi = -2; xi <= 4 * n + 2; ++xi) {
            const double x = xi * 0.25, y = yi * 0.25;
            for (double sign : {1.0, -1.0}) {
                const glm::dvec3 origin(x, y, sign * 0.75);
                const glm::dvec3 direction(0, 0, sign);  // pointing away: the line's other side hits
                const std::optional<SurfaceHit> got = surface.nearest_ray_hit(origin, direction, 1.0);
                const std::optional<OracleHit> want = oracle_ray(m, origin, glm::normalize(direction), 1.0, 0.0);
                ASSERT_EQ(got.has_value(), want.has_value()) << x << ", " << y;
                if (!got) {
                    EXPECT_TRUE(x < 0 || y < 0 || x > n || y > n) << x << ", " << y;
                    continue;
                }
                EXPECT_EQ(got->triangle, want->triangle) << x << ", " << y;
                EXPECT_EQ(got->point, want->point) << x << ", " << y;
                EXPECT_EQ(got->point, glm::dvec3(x, y, 0));
                EXPECT_EQ(got->distance, 0.75);
                if (xi % 4 == 0 || yi % 4 == 0 || (xi - yi) % 4 == 0 || (xi + yi) % 4 == 0) ++on_edges;
            }
        }
    EXPECT_GT(on_edges, 100);
    // Just beyond the boundary (closer than a float can tell): a miss, then the nearest point.
    const glm::dvec3 outside(-1e-300, 3.5, 1.0);
    EXPECT_FALSE(surface.nearest_ray_hit(outside, {0, 0, -1}, 2.0).has_value());
    const SurfaceHit projected = surface.project(outside, {0, 0, -1}, 2.0);
    EXPECT_FALSE(projected.by_ray);
    EXPECT_EQ(projected.point, glm::dvec3(0, 3.5, 0));
    // Exactly on the boundary: a hit.
    ASSERT_TRUE(surface.nearest_ray_hit({0, 3.5, 1.0}, {0, 0, -1}, 2.0).has_value());
    EXPECT_TRUE(surface.nearest_ray_hit({8, 8, -1.0}, {0, 0, 1}, 2.0).has_value());
    // The search distance is inclusive.
    EXPECT_TRUE(surface.nearest_ray_hit({2.5, 2.5, 1.0}, {0, 0, -1}, 1.0).has_value());
    EXPECT_FALSE(surface.nearest_ray_hit({2.5, 2.5, 1.0}, {0, 0, -1}, std::nextafter(1.0, 0.0)).has_value());
    // Origin on M: distance 0.
    const std::optional<SurfaceHit> zero = surface.nearest_ray_hit({2.5, 1.25, 0.0}, {0.3, 0.1, 1.0}, 0.0);
    ASSERT_TRUE(zero.has_value());
    EXPECT_EQ(zero->distance, 0.0);
}

// Two overlapping sheets 1e-9 apart, closer than floats can tell: the nearer in double wins,
// from either side, and where only one sheet lies under the line, that one.
TEST(DenseSurface, NearlyCoincidentSheetsAreOrderedInDouble) {
    Soup m = flat_grid(4);
    const Soup upper = flat_grid(4);
    const auto base = static_cast<std::uint32_t>(m.positions.size());
    for (const glm::dvec3& p : upper.positions) m.positions.push_back(p + glm::dvec3(0.37, 0.21, 1e-9));
    for (const Triangle& t : upper.triangles) m.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    m.scale = 4.37;
    const DenseSurface surface = surface_of(m);
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int lower = 0, upper_hits = 0;
    for (int i = 0; i < 2000; ++i) {
        const double side = i % 2 == 0 ? 1.0 : -1.0;
        const glm::dvec3 origin(-0.2 + 4.8 * unit(rng), -0.2 + 4.8 * unit(rng), side * (0.1 + unit(rng)));
        const glm::dvec3 direction = glm::dvec3(0.2 * (unit(rng) - 0.5), 0.2 * (unit(rng) - 0.5), -side);
        const std::optional<SurfaceHit> got = surface.nearest_ray_hit(origin, direction, 2.0);
        const std::optional<OracleHit> want = oracle_ray(m, origin, glm::normalize(direction), 2.0, 0.0);
        ASSERT_EQ(got.has_value(), want.has_value()) << i;
        if (!got) continue;
        const bool want_upper = want->triangle >= upper.triangles.size();
        EXPECT_EQ(got->triangle >= upper.triangles.size(), want_upper) << i;
        EXPECT_LE(glm::length(got->point - want->point), 1e-9) << i;
        EXPECT_NEAR(got->point.z, want_upper ? 1e-9 : 0.0, 1e-15) << i;
        (want_upper ? upper_hits : lower) += 1;
    }
    EXPECT_GT(lower, 300);
    EXPECT_GT(upper_hits, 300);
}

// Lines in the grid's plane meet no triangle (parallel): the projection is the nearest point.
TEST(DenseSurface, RaysAlongTheSurfaceFallBackToTheClosestPoint) {
    const Soup m = flat_grid(16);
    const DenseSurface surface = surface_of(m);
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 500; ++i) {
        const glm::dvec3 origin(-4 + 24 * unit(rng), -4 + 24 * unit(rng), 0.0);
        const glm::dvec3 direction(2 * unit(rng) - 1, 2 * unit(rng) - 1, 0.0);
        EXPECT_FALSE(surface.nearest_ray_hit(origin, direction, 100.0).has_value());
        EXPECT_FALSE(oracle_ray(m, origin, glm::normalize(direction), 100.0, 0.0).has_value());
        const SurfaceHit p = surface.project(origin, direction, 100.0);
        EXPECT_FALSE(p.by_ray);
        const glm::dvec3 want(std::clamp(origin.x, 0.0, 16.0), std::clamp(origin.y, 0.0, 16.0), 0.0);
        EXPECT_NEAR(p.point.x, want.x, 1e-12);
        EXPECT_NEAR(p.point.y, want.y, 1e-12);
        EXPECT_EQ(p.point.z, 0.0);
    }
}

// Closest points on vertices and edges shared by several triangles: the lowest triangle index.
TEST(DenseSurface, ClosestPointTiesTakeTheLowestTriangle) {
    const Soup m = flat_grid(4);
    const DenseSurface surface = surface_of(m);
    for (int j = 0; j <= 4; ++j)
        for (int i = 0; i <= 4; ++i) {
            const glm::dvec3 p(i, j, 1.0);
            const SurfaceHit got = surface.closest_point(p);
            std::uint32_t lowest = 0xffffffffu;
            for (std::uint32_t f = 0; f < m.triangles.size(); ++f)
                if (distance_to_triangle(m, f, p) == 1.0) lowest = std::min(lowest, f);
            EXPECT_EQ(got.triangle, lowest) << i << ", " << j;
            EXPECT_EQ(got.point, glm::dvec3(i, j, 0));
            EXPECT_EQ(got.distance, 1.0);
        }
}

TEST(DenseSurface, BatchEqualsSingleAndIsDeterministic) {
    const Soup m = torus(96, 48);
    const DenseSurface surface = surface_of(m);
    const DenseSurface again = surface_of(m);
    const std::vector<RayCase> cases = random_rays(m, 20000, 21);
    std::vector<glm::dvec3> origins, directions;
    for (const RayCase& c : cases) {
        origins.push_back(c.origin);
        directions.push_back(c.direction);
    }
    const double max_distance = 0.3;
    const std::vector<std::optional<SurfaceHit>> hits = surface.nearest_ray_hits(origins, directions, max_distance);
    const std::vector<SurfaceHit> projected = surface.projections(origins, directions, max_distance);
    const std::vector<SurfaceHit> closest = surface.closest_points(origins);
    ASSERT_EQ(hits.size(), cases.size());
    int found = 0;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        ASSERT_TRUE(same(hits[i], surface.nearest_ray_hit(origins[i], directions[i], max_distance))) << i;
        ASSERT_TRUE(same(hits[i], again.nearest_ray_hit(origins[i], directions[i], max_distance))) << i;
        ASSERT_TRUE(same(projected[i], surface.project(origins[i], directions[i], max_distance))) << i;
        ASSERT_TRUE(same(closest[i], surface.closest_point(origins[i]))) << i;
        ASSERT_TRUE(same(closest[i], again.closest_point(origins[i]))) << i;
        found += hits[i].has_value();
    }
    EXPECT_GT(found, 1000);
    EXPECT_LT(found, static_cast<int>(cases.size()));
    // Concurrent batches from several threads: the same answers.
    std::vector<std::vector<SurfaceHit>> results(4);
    std::vector<std::thread> threads;
    for (std::size_t k = 0; k < results.size(); ++k)
        threads.emplace_back([&, k] { results[k] = surface.projections(origins, directions, max_distance); });
    for (std::thread& t : threads) t.join();
    for (const std::vector<SurfaceHit>& r : results) {
        ASSERT_EQ(r.size(), projected.size());
        for (std::size_t i = 0; i < r.size(); ++i) ASSERT_TRUE(same(r[i], projected[i])) << i;
    }
    EXPECT_TRUE(surface.nearest_ray_hits({}, {}, 1.0).empty());
    EXPECT_TRUE(surface.closest_points({}).empty());
}

// Building the search tree tells its progress every 65,536 triangle visits (each level of the tree
// visits every triangle once) and stops when told to, throwing Stopped; the tree built while reporting
// answers as the one built without.
TEST(DenseSurface, BuildingTheTreeReportsItsProgressAndStops) {
    const Soup m = torus(200, 100);  // 40,000 triangles: 15 levels of nodes down to leaves of at most 4
    std::vector<double> shares;
    const DenseSurface reported(m.positions, m.triangles, [&](double share) {
        shares.push_back(share);
        return true;
    });
    // The build's start and end, one before the tree is compacted and one before the triangles'
    // corners are laid out in its order, and while it is built a report within 65,536 + 40,000 (the
    // largest node's) visits of the last: at least 600,000 / 105,536 of them.
    ASSERT_GE(shares.size(), 4u + 600000u / 105536u);
    EXPECT_EQ(shares.front(), 0.0);
    EXPECT_EQ(shares.back(), 1.0);
    for (std::size_t i = 1; i < shares.size(); ++i) EXPECT_GE(shares[i], shares[i - 1]) << i;
    const DenseSurface plain = surface_of(m);
    for (const glm::dvec3& p : {glm::dvec3(1.2, 0.3, 0.1), glm::dvec3(-0.4, 0.9, -0.3), glm::dvec3(0.0, 0.0, 0.0)})
        EXPECT_TRUE(same(reported.closest_point(p), plain.closest_point(p)));
    // A stop at the first report inside the build, the middle one and the last: Stopped, no report after.
    for (const std::size_t stop_at : {std::size_t(1), shares.size() / 2, shares.size() - 2}) {
        std::size_t calls = 0;
        EXPECT_THROW(DenseSurface(m.positions, m.triangles, [&](double) { return ++calls != stop_at + 1; }), rgbdetail::Stopped)
            << stop_at;
        EXPECT_EQ(calls, stop_at + 1);
    }
}

TEST(DenseSurface, RejectsBadInput) {
    const Soup m = flat_grid(2);
    EXPECT_THROW(DenseSurface({}, {}), std::invalid_argument);
    EXPECT_THROW(DenseSurface(m.positions, {}), std::invalid_argument);
    EXPECT_THROW(DenseSurface({{0, 0, 0}, {1, 0, 0}}, {{0, 1, 2}}), std::invalid_argument);
    std::vector<glm::dvec3> bad = m.positions;
    bad[3].y = std::nan("");
    EXPECT_THROW(DenseSurface(bad, m.triangles), std::invalid_argument);
    bad[3].y = std::numeric_limits<double>::infinity();
    EXPECT_THROW(DenseSurface(bad, m.triangles), std::invalid_argument);
    bad[3].y = 1e300;
    EXPECT_THROW(DenseSurface(bad, m.triangles), std::invalid_argument);

    const DenseSurface surface = surface_of(m);
    const double nan = std::nan("");
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_THROW((void)surface.nearest_ray_hit({nan, 0, 0}, {0, 0, 1}, 1.0), std::invalid_argument);
    EXPECT_THROW((void)surface.nearest_ray_hit({0, 0, 0}, {0, inf, 1}, 1.0), std::invalid_argument);
    EXPECT_THROW((void)surface.nearest_ray_hit({0, 0, 0}, {0, 0, 0}, 1.0), std::invalid_argument);
    EXPECT_THROW((void)surface.nearest_ray_hit({0, 0, 0}, {0, 0, 1}, -1.0), std::invalid_argument);
    EXPECT_THROW((void)surface.nearest_ray_hit({0, 0, 0}, {0, 0, 1}, inf), std::invalid_argument);
    EXPECT_THROW((void)surface.nearest_ray_hit({0, 0, 0}, {0, 0, 1}, nan), std::invalid_argument);
    EXPECT_THROW((void)surface.project({0, 0, 0}, {0, 0, 1}, nan), std::invalid_argument);
    EXPECT_THROW((void)surface.closest_point({0, 0, inf}), std::invalid_argument);
    const std::vector<glm::dvec3> two{{0, 0, 0}, {1, 1, 1}};
    const std::vector<glm::dvec3> one{{0, 0, 1}};
    EXPECT_THROW((void)surface.nearest_ray_hits(two, one, 1.0), std::invalid_argument);
    EXPECT_THROW((void)surface.projections(two, std::vector<glm::dvec3>{{0, 0, 1}, {0, 0, 0}}, 1.0), std::invalid_argument);
    EXPECT_THROW((void)surface.closest_points(std::vector<glm::dvec3>{{0, 0, 0}, {nan, 0, 0}}), std::invalid_argument);
    // Tiny and huge directions are normalised.
    const std::optional<SurfaceHit> tiny = surface.nearest_ray_hit({0.5, 0.25, 1}, {0, 0, -1e-300}, 2.0);
    const std::optional<SurfaceHit> huge = surface.nearest_ray_hit({0.5, 0.25, 1}, {0, 0, -1e300}, 2.0);
    ASSERT_TRUE(tiny && huge);
    EXPECT_TRUE(same(*tiny, *huge));
    EXPECT_EQ(tiny->distance, 1.0);
}

}  // namespace dense_surface_test
