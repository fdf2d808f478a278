// The explicit Loop stencils (src/detail/loop_stencils.h) and the cage fit (src/detail/cage_fit.h).
// The stencils are checked against the core as an independent implementation: an rgb::Mesh built
// from the same cage, refined uniformly, its vertices' limits (rgb::limit_position) and control points
// (rgb::control_point) matched to the stencils' rows by base-space position, which this file computes
// itself (iterated edge midpoints in the order loop_stencils.h documents). The fits are checked
// against analytic surfaces (sphere, torus, cylinder), and the fitted limit surface is measured
// again, densely, through the core's evaluator rather than the stencils.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "detail/cage_fit.h"
#include "detail/loop_stencils.h"
#include "rgb/lod/refine.h"
#include "rgb/mesh/mesh.h"
#include "rgb/values/loop_geometry.h"

// Named inside the anonymous namespace: the unity build compiles this file with cage_test.cpp.
namespace {
namespace fit_test {

using rgb::Triangle;

struct Cage {
    std::vector<glm::dvec3> positions;
    std::vector<Triangle> triangles;
};

// ---------------------------------------------------------------------------------------------
// Test cages
// ---------------------------------------------------------------------------------------------

Cage tetrahedron() {
    return {{{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}}, {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}}};
}

Cage octahedron() {
    return {{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}},
            {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}}};
}

Cage icosahedron() {
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    Cage c;
    c.positions = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                   {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    for (glm::dvec3& p : c.positions) p = glm::normalize(p);
    c.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                   {11, 10, 2}, {10, 7, 6}, {7, 1, 8},   {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                   {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    return c;
}

// A bipyramid over an n-gon: apexes of valence n, equator vertices of valence 4.
Cage bipyramid(int n) {
    Cage c;
    for (int i = 0; i < n; ++i) {
        const double a = 2.0 * std::numbers::pi * i / n;
        c.positions.push_back({std::cos(a), std::sin(a), 0.0});
    }
    c.positions.push_back({0, 0, 1.3});
    c.positions.push_back({0, 0, -0.8});
    const auto top = static_cast<std::uint32_t>(n), bottom = static_cast<std::uint32_t>(n + 1);
    for (int i = 0; i < n; ++i) {
        const auto a = static_cast<std::uint32_t>(i), b = static_cast<std::uint32_t>((i + 1) % n);
        c.triangles.push_back({a, b, top});
        c.triangles.push_back({b, a, bottom});
    }
    return c;
}

// Icosahedron with one face split into three (a vertex of valence 3, three of valence 6): closed, with
// valences 3, 5, 6 together.
Cage icosahedron_with_cone() {
    Cage c = icosahedron();
    const Triangle f = c.triangles[0];
    const glm::dvec3 centre = 1.2 * glm::normalize(c.positions[f[0]] + c.positions[f[1]] + c.positions[f[2]]);
    c.positions.push_back(centre);
    const auto m = static_cast<std::uint32_t>(c.positions.size() - 1);
    c.triangles[0] = {f[0], f[1], m};
    c.triangles.push_back({f[1], f[2], m});
    c.triangles.push_back({f[2], f[0], m});
    return c;
}

// An open (nx x ny)-square grid in the plane z = 0, every square cut along the same diagonal: two
// corners of valence 2, two of valence 3, boundary vertices of valence 3 and 4.
Cage grid(int nx, int ny) {
    Cage c;
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) c.positions.push_back({static_cast<double>(i), static_cast<double>(j), 0.0});
    auto id = [&](int i, int j) { return static_cast<std::uint32_t>(j * (nx + 1) + i); };
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            c.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            c.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    return c;
}

// A torus cage, nu around the axis z, nv around the tube, vertices on the torus (major R, minor r).
Cage torus(int nu, int nv, double major, double minor) {
    Cage c;
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            const double u = 2.0 * std::numbers::pi * i / nu, v = 2.0 * std::numbers::pi * j / nv;
            const double rho = major + minor * std::cos(v);
            c.positions.push_back({rho * std::cos(u), rho * std::sin(u), minor * std::sin(v)});
        }
    auto id = [&](int i, int j) { return static_cast<std::uint32_t>((i % nu) * nv + j % nv); };
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            c.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            c.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    return c;
}

// A half cylinder strip (axis y, radius `radius`), open: nx squares around, ny along.
Cage half_cylinder(int nx, int ny, double radius) {
    Cage c = grid(nx, ny);
    for (glm::dvec3& p : c.positions) {
        const double a = std::numbers::pi * p.x / nx;
        p = {radius * std::cos(a), p.y * 0.5, radius * std::sin(a)};
    }
    return c;
}

Cage perturbed(Cage c, double amount, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> d(-amount, amount);
    for (glm::dvec3& p : c.positions) p += glm::dvec3(d(random), d(random), d(random));
    return c;
}

// ---------------------------------------------------------------------------------------------
// This file's own bookkeeping of the stencils' vertex order: iterated midpoints, edges in order of
// first appearance in the faces.
// ---------------------------------------------------------------------------------------------

struct Level {
    std::vector<glm::dvec3> base_space;  // base-space position of each vertex of the level
    std::vector<Triangle> triangles;
};

Level next_level(const Level& level) {
    Level out;
    out.base_space = level.base_space;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> middle;
    auto mid = [&](std::uint32_t a, std::uint32_t b) {
        const auto key = std::minmax(a, b);
        const auto it = middle.find(key);
        if (it != middle.end()) return it->second;
        out.base_space.push_back(0.5 * (level.base_space[a] + level.base_space[b]));
        const auto v = static_cast<std::uint32_t>(out.base_space.size() - 1);
        middle.emplace(key, v);
        return v;
    };
    for (const Triangle& f : level.triangles) {
        const std::uint32_t ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
        out.triangles.push_back({f[0], ab, ca});
        out.triangles.push_back({ab, f[1], bc});
        out.triangles.push_back({ca, bc, f[2]});
        out.triangles.push_back({ab, bc, ca});
    }
    return out;
}

Level level_of(const Cage& cage, int k) {
    Level level{cage.positions, cage.triangles};
    for (int i = 0; i < k; ++i) level = next_level(level);
    return level;
}

double scale_of(const std::vector<glm::dvec3>& positions) {
    double s = 0.0;
    for (const glm::dvec3& p : positions) s = std::max({s, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    return s;
}

std::vector<glm::dvec3> evaluate_rows(const rgbdetail::StencilMatrix& m, const std::vector<glm::dvec3>& positions) {
    std::vector<glm::dvec3> out(static_cast<std::size_t>(m.rows()), glm::dvec3(0.0));
    for (Eigen::Index r = 0; r < m.outerSize(); ++r)
        for (rgbdetail::StencilMatrix::InnerIterator it(m, r); it; ++it)
            out[static_cast<std::size_t>(r)] += it.value() * positions[static_cast<std::size_t>(it.col())];
    return out;
}

// For each live vertex of the core's mesh, the index of the vertex of `level` at its base-space
// position (nearest; asserts that the match is a bijection and exact to rounding).
std::vector<std::pair<rgb::VertexId, std::size_t>> match(const rgb::Mesh& mesh, const Level& level, double scale) {
    std::vector<std::pair<rgb::VertexId, std::size_t>> out;
    std::vector<int> used(level.base_space.size(), 0);
    for (rgb::VertexId v : mesh.vertices()) {
        const glm::dvec3 b = mesh.base_space_position(v);
        std::size_t best = 0;
        double best_distance = INFINITY;
        for (std::size_t i = 0; i < level.base_space.size(); ++i) {
            const double d = glm::length(level.base_space[i] - b);
            if (d < best_distance) best_distance = d, best = i;
        }
        EXPECT_LE(best_distance, 1e-12 * scale) << "vertex " << v.idx;
        ++used[best];
        out.emplace_back(v, best);
    }
    EXPECT_EQ(out.size(), level.base_space.size());
    for (std::size_t i = 0; i < used.size(); ++i) EXPECT_EQ(used[i], 1) << "stencil vertex " << i;
    return out;
}

void expect_stencils_match_core(const Cage& cage, int max_level) {
    const double scale = scale_of(cage.positions);
    std::vector<rgbdetail::StencilMatrix> steps;  // the products S_(k-1) ... S_0
    rgbdetail::LoopTopology topology(cage.positions.size(), cage.triangles);
    rgbdetail::StencilMatrix product(static_cast<Eigen::Index>(cage.positions.size()),
                                     static_cast<Eigen::Index>(cage.positions.size()));
    product.setIdentity();
    for (int k = 0; k <= max_level; ++k) {
        SCOPED_TRACE("level " + std::to_string(k));
        const Level level = level_of(cage, k);
        const rgbdetail::LoopStencils stencils = rgbdetail::limit_stencils(cage.positions.size(), cage.triangles, k);
        ASSERT_EQ(static_cast<std::size_t>(stencils.limit.rows()), level.base_space.size());
        ASSERT_EQ(static_cast<std::size_t>(stencils.limit.cols()), cage.positions.size());
        EXPECT_EQ(stencils.triangles, level.triangles);
        // Affine: every row sums to 1.
        for (Eigen::Index r = 0; r < stencils.limit.rows(); ++r)
            EXPECT_NEAR(stencils.limit.row(r).sum(), 1.0, 1e-14);

        const std::vector<glm::dvec3> limits = evaluate_rows(stencils.limit, cage.positions);
        const std::vector<glm::dvec3> controls = evaluate_rows(product, cage.positions);
        rgb::Mesh mesh(cage.positions, cage.triangles);
        if (k > 0) rgb::refine_uniform(mesh, k);
        for (const auto& [v, i] : match(mesh, level, scale)) {
            const glm::dvec3 core_limit = rgb::limit_position(mesh, v);
            EXPECT_LE(glm::length(core_limit - limits[i]), 1e-12 * scale) << "vertex " << v.idx << " row " << i;
            const glm::dvec3 core_control = rgb::control_point(mesh, v, k);
            EXPECT_LE(glm::length(core_control - controls[i]), 1e-12 * scale) << "vertex " << v.idx << " row " << i;
        }
        if (k < max_level) {
            product = rgbdetail::subdivision_matrix(topology) * product;
            topology = rgbdetail::LoopTopology(level.base_space.size() + topology.edges().size(), topology.refined_triangles());
        }
    }
}

TEST(LoopStencils, MatchCoreOnClosedMeshes) {
    for (const Cage& cage : {tetrahedron(), octahedron(), icosahedron(), bipyramid(7), icosahedron_with_cone()}) {
        SCOPED_TRACE(cage.positions.size());
        expect_stencils_match_core(cage, 2);
    }
}

TEST(LoopStencils, MatchCoreOnOpenGrids) {
    for (const Cage& cage : {grid(1, 1), grid(3, 2), grid(4, 4), half_cylinder(5, 3, 2.0)}) {
        SCOPED_TRACE(cage.positions.size());
        expect_stencils_match_core(cage, 2);
    }
}

TEST(LoopStencils, MatchCoreOnPerturbedMeshes) {
    unsigned seed = 7;
    for (const Cage& cage : {icosahedron_with_cone(), bipyramid(5), grid(3, 3), torus(5, 4, 2.0, 0.7)}) {
        SCOPED_TRACE(cage.positions.size());
        expect_stencils_match_core(perturbed(cage, 0.2, ++seed), 2);
    }
}

TEST(LoopStencils, SingleTriangleAndBoundaryRows) {
    // A lone triangle: every vertex is a boundary corner of valence 2.
    const Cage cage{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}};
    expect_stencils_match_core(cage, 2);
    const rgbdetail::LoopStencils s = rgbdetail::limit_stencils(3, cage.triangles, 0);
    EXPECT_DOUBLE_EQ(s.limit.coeff(0, 0), 2.0 / 3.0);
    EXPECT_DOUBLE_EQ(s.limit.coeff(0, 1), 1.0 / 6.0);
    EXPECT_DOUBLE_EQ(s.limit.coeff(0, 2), 1.0 / 6.0);
}

TEST(LoopStencils, RefusesNonManifoldInput) {
    // A directed edge twice (two faces with the same orientation on edge 0-1).
    EXPECT_THROW(rgbdetail::LoopTopology(4, std::vector<Triangle>{{0, 1, 2}, {0, 1, 3}}), std::invalid_argument);
    // Two fans at vertex 0 (a bow tie).
    EXPECT_THROW(rgbdetail::LoopTopology(5, std::vector<Triangle>{{0, 1, 2}, {0, 3, 4}}), std::invalid_argument);
    // An unused vertex.
    EXPECT_THROW(rgbdetail::LoopTopology(4, std::vector<Triangle>{{0, 1, 2}}), std::invalid_argument);
    // An index out of range, a repeated corner.
    EXPECT_THROW(rgbdetail::LoopTopology(3, std::vector<Triangle>{{0, 1, 3}}), std::invalid_argument);
    EXPECT_THROW(rgbdetail::LoopTopology(3, std::vector<Triangle>{{0, 1, 1}}), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// Fitting
// ---------------------------------------------------------------------------------------------

glm::dvec3 closest_on_unit_sphere(const glm::dvec3& p) { return glm::normalize(p); }

struct TorusSurface {
    double major, minor;
    glm::dvec3 closest(const glm::dvec3& p) const {
        const glm::dvec3 c = major * glm::normalize(glm::dvec3(p.x, p.y, 0.0));
        return c + minor * glm::normalize(p - c);
    }
    double distance(const glm::dvec3& p) const { return glm::length(p - closest(p)); }
};

struct SurfaceError {
    double rms = 0.0, max = 0.0;
};

// The fitted cage's limit surface measured by the core, not the stencils: the limits of every vertex
// of uniform level `level`, distance to the analytic surface.
template <class Distance>
SurfaceError core_limit_error(const Cage& cage, int level, const Distance& distance) {
    rgb::Mesh mesh(cage.positions, cage.triangles);
    rgb::refine_uniform(mesh, level);
    SurfaceError e;
    std::size_t count = 0;
    for (rgb::VertexId v : mesh.vertices()) {
        const double d = distance(rgb::limit_position(mesh, v));
        e.rms += d * d;
        e.max = std::max(e.max, d);
        ++count;
    }
    e.rms = std::sqrt(e.rms / static_cast<double>(count));
    return e;
}

void print_history(const char* name, const rgbdetail::FitResult& r) {
    std::printf("%s (%zu samples):", name, r.samples);
    for (const rgbdetail::FitDistances& d : r.distances) std::printf(" [rms %.3g max %.3g]", d.rms, d.max);
    std::printf("\n");
}

TEST(CageFit, IcosahedronToSphere) {
    const Cage cage = icosahedron();
    const auto sphere_distance = [](const glm::dvec3& p) { return std::abs(glm::length(p) - 1.0); };
    for (int sample_level : {1, 2}) {
        SCOPED_TRACE(sample_level);
        rgbdetail::FitOptions options;
        options.sample_level = sample_level;
        const rgbdetail::FitResult r = rgbdetail::fit_cage(cage.positions, cage.triangles, closest_on_unit_sphere, options);
        print_history(sample_level == 1 ? "sphere, level-1 samples" : "sphere, level-2 samples", r);
        ASSERT_EQ(r.distances.size(), 5u);
        // Loop shrinks: the icosahedron's own limit surface is well inside the sphere.
        EXPECT_GT(r.distances.front().rms, 0.1);
        // Measured (g++ 12 Release): rms 4.40e-3, max 6.25e-3 (level 1); rms 3.28e-3, max 6.92e-3
        // (level 2), reached after the first solve (the sphere's closest point is radial, and the
        // icosahedron's symmetry leaves only a scale to find). What remains is the distance of an
        // icosahedral Loop surface from a sphere (lambda = 0 gives 4.36e-3 and 3.22e-3). Bounds
        // with margin, well below the 1% of the radius the issue asks for.
        EXPECT_LT(r.distances.back().rms, 6e-3);
        EXPECT_LT(r.distances.back().max, 9e-3);
        for (std::size_t i = 1; i < r.distances.size(); ++i)
            EXPECT_LE(r.distances[i].rms, r.distances[i - 1].rms * 1.0001);
        // The whole limit surface, densely, by the core's evaluator.
        const SurfaceError e = core_limit_error({r.positions, cage.triangles}, 3, sphere_distance);
        std::printf("  core limit at level 3: rms %.3g max %.3g\n", e.rms, e.max);
        // Measured: rms 3.42e-3, max 6.25e-3 (level 1); rms 3.21e-3, max 6.92e-3 (level 2).
        EXPECT_LT(e.rms, 5e-3);
        EXPECT_LT(e.max, 9e-3);
    }
}

TEST(CageFit, TorusCageToTorus) {
    const TorusSurface surface{1.0, 0.4};
    // A coarse cage, its vertices on the torus (so its limit surface shrinks off it) and perturbed.
    const Cage cage = perturbed(torus(10, 6, 1.0, 0.4), 0.03, 3);
    const auto closest = [&](const glm::dvec3& p) { return surface.closest(p); };
    const rgbdetail::FitResult r = rgbdetail::fit_cage(cage.positions, cage.triangles, closest, {});
    print_history("torus 10x6", r);
    EXPECT_GT(r.distances.front().rms, 0.05);
    // Measured: rms 0.0863 -> 7.2e-3, 5.3e-3, 4.5e-3, 3.9e-3 (max 0.172 -> 0.0117): still going
    // down at the fourth iteration, as the closest points slide along the tube. Bounds with margin
    // (1.5% and 4.5% of the tube's radius).
    EXPECT_LT(r.distances.back().rms, 0.015 * surface.minor);
    EXPECT_LT(r.distances.back().max, 0.045 * surface.minor);
    const SurfaceError e = core_limit_error({r.positions, cage.triangles}, 3, [&](const glm::dvec3& p) { return surface.distance(p); });
    std::printf("  core limit at level 3: rms %.3g max %.3g\n", e.rms, e.max);
    // Measured: rms 3.9e-3, max 0.0117.
    EXPECT_LT(e.rms, 0.015 * surface.minor);
    EXPECT_LT(e.max, 0.05 * surface.minor);
}

TEST(CageFit, OpenStripToCylinder) {
    // A half-cylinder strip of radius 1.5 fitted to the cylinder of radius 1 (axis y): boundary rows
    // included. The closest point keeps y; open edges can only slide along the cylinder.
    const Cage cage = half_cylinder(6, 4, 1.5);
    const auto closest = [](const glm::dvec3& p) {
        const glm::dvec2 xz = glm::normalize(glm::dvec2(p.x, p.z));
        return glm::dvec3(xz.x, p.y, xz.y);
    };
    const rgbdetail::FitResult r = rgbdetail::fit_cage(cage.positions, cage.triangles, closest, {});
    print_history("half cylinder", r);
    EXPECT_GT(r.distances.front().rms, 0.3);
    // Measured: rms 0.441 -> 3.0e-3 (max 8.9e-3); the core's dense limits rms 2.8e-3.
    EXPECT_LT(r.distances.back().rms, 6e-3);
    EXPECT_LT(r.distances.back().max, 0.02);
    const SurfaceError e = core_limit_error({r.positions, cage.triangles}, 3, [](const glm::dvec3& p) {
        return std::abs(std::hypot(p.x, p.z) - 1.0);
    });
    std::printf("  core limit at level 3: rms %.3g max %.3g\n", e.rms, e.max);
    EXPECT_LT(e.rms, 6e-3);
}

TEST(CageFit, Deterministic) {
    const Cage cage = perturbed(icosahedron_with_cone(), 0.1, 11);
    rgbdetail::FitOptions options;
    options.iterations = 3;
    const rgbdetail::FitResult a = rgbdetail::fit_cage(cage.positions, cage.triangles, closest_on_unit_sphere, options);
    const rgbdetail::FitResult b = rgbdetail::fit_cage(cage.positions, cage.triangles, closest_on_unit_sphere, options);
    ASSERT_EQ(a.positions.size(), b.positions.size());
    for (std::size_t i = 0; i < a.positions.size(); ++i) EXPECT_EQ(a.positions[i], b.positions[i]) << i;
    ASSERT_EQ(a.distances.size(), b.distances.size());
    for (std::size_t i = 0; i < a.distances.size(); ++i) {
        EXPECT_EQ(a.distances[i].rms, b.distances[i].rms);
        EXPECT_EQ(a.distances[i].max, b.distances[i].max);
    }
    // Parallel closest-point queries give the same bits (each sample's target is its own).
    options.parallel_targets = true;
    const rgbdetail::FitResult c = rgbdetail::fit_cage(cage.positions, cage.triangles, closest_on_unit_sphere, options);
    for (std::size_t i = 0; i < a.positions.size(); ++i) EXPECT_EQ(a.positions[i], c.positions[i]) << i;
}

TEST(CageFit, ZeroIterationsAndBadInput) {
    const Cage cage = octahedron();
    rgbdetail::FitOptions options;
    options.iterations = 0;
    const rgbdetail::FitResult r = rgbdetail::fit_cage(cage.positions, cage.triangles, closest_on_unit_sphere, options);
    EXPECT_EQ(r.positions, cage.positions);
    EXPECT_EQ(r.distances.size(), 1u);
    std::vector<glm::dvec3> too_few(cage.positions.begin(), cage.positions.end() - 1);
    EXPECT_THROW(rgbdetail::fit_cage(too_few, cage.triangles, closest_on_unit_sphere, {}), std::invalid_argument);
    options.lambda = -1.0;
    EXPECT_THROW(rgbdetail::fit_cage(cage.positions, cage.triangles, closest_on_unit_sphere, options), std::invalid_argument);
}

TEST(CageFit, SpeedOfA5kTriangleTorusCage) {
    // Not an assertion: the time of 4 iterations on a 50 x 50 torus cage (5,000 triangles).
    const TorusSurface surface{1.0, 0.35};
    const Cage cage = perturbed(torus(50, 50, 1.0, 0.35), 0.005, 5);
    const auto closest = [&](const glm::dvec3& p) { return surface.closest(p); };
    for (int sample_level : {1, 2}) {
        rgbdetail::FitOptions options;
        options.sample_level = sample_level;
        const auto start = std::chrono::steady_clock::now();
        const rgbdetail::FitResult r = rgbdetail::fit_cage(cage.positions, cage.triangles, closest, options);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::printf("5k-triangle torus cage, level-%d samples (%zu), 4 iterations: %.3f s, rms %.3g -> %.3g\n",
                    sample_level, r.samples, seconds, r.distances.front().rms, r.distances.back().rms);
        EXPECT_LT(r.distances.back().rms, r.distances.front().rms);
    }
}

}  // namespace fit_test
}  // namespace
