// The explicit Loop stencils (src/detail/loop_stencils.h) and the cage fit (src/detail/cage_fit.h).
// The stencils are checked against the core as an independent implementation: an rgb::Mesh built
// from the same cage, refined uniformly, its vertices' limits (rgb::limit_position) and control points
// (rgb::control_point), and rgb::HierarchyEvaluator's limits from the vertices' addresses, matched
// to the stencils' rows by base-space position, which this file computes itself (iterated edge
// midpoints in the order loop_stencils.h documents), untagged and with crease and corner tags (the
// core's base mesh gets the same tags). The fits are checked against analytic
// surfaces (sphere, torus, cylinder, and a cube whose edges the cage tags), and the fitted limit
// surface is measured again, densely, through the core's evaluator rather than the stencils; a dense
// cube remeshed with and without --sharp-angle's tags compares the two fits.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
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
#include "detail/remesh.h"
#include "rgb/lod/refine.h"
#include "rgb/mesh/mesh.h"
#include "rgb/mesh/sharp_angle.h"
#include "rgb/values/hierarchy_evaluator.h"
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

// The surface of the cube [-1, 1]^3, each face an m x m grid of squares cut along one diagonal,
// counter-clockwise from outside; vertices shared by position (integer grid coordinates).
Cage cube(int m) {
    Cage c;
    std::map<std::array<int, 3>, std::uint32_t> index;
    auto vertex = [&](std::array<int, 3> g) {
        const auto [it, added] = index.emplace(g, static_cast<std::uint32_t>(c.positions.size()));
        if (added) c.positions.push_back({2.0 * g[0] / m - 1.0, 2.0 * g[1] / m - 1.0, 2.0 * g[2] / m - 1.0});
        return it->second;
    };
    for (int axis = 0; axis < 3; ++axis)
        for (int side : {0, m}) {
            // u along axis + 1, v along axis + 2: (u, v, normal) right-handed, so ccw seen from +axis.
            auto at = [&](int u, int v) {
                std::array<int, 3> g{};
                g[axis] = side;
                g[(axis + 1) % 3] = u;
                g[(axis + 2) % 3] = v;
                return vertex(g);
            };
            for (int u = 0; u < m; ++u)
                for (int v = 0; v < m; ++v) {
                    const std::uint32_t a = at(u, v), b = at(u + 1, v), d = at(u + 1, v + 1), e = at(u, v + 1);
                    if (side == m) {
                        c.triangles.push_back({a, b, d});
                        c.triangles.push_back({a, d, e});
                    } else {
                        c.triangles.push_back({a, d, b});
                        c.triangles.push_back({a, e, d});
                    }
                }
        }
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

// The core's side: the same cage with the same tags as a base mesh.
rgb::Mesh core_mesh(const Cage& cage, const rgb::SharpFeatures& features) {
    return rgb::Mesh(std::make_shared<const rgb::BaseMesh>(cage.positions, cage.triangles, features));
}

void expect_stencils_match_core(const Cage& cage, const rgb::SharpFeatures& features, int max_level) {
    const double scale = scale_of(cage.positions);
    rgbdetail::LoopTopology topology(cage.positions.size(), cage.triangles, features);
    rgbdetail::StencilMatrix product(static_cast<Eigen::Index>(cage.positions.size()),
                                     static_cast<Eigen::Index>(cage.positions.size()));
    product.setIdentity();
    for (int k = 0; k <= max_level; ++k) {
        SCOPED_TRACE("level " + std::to_string(k));
        const Level level = level_of(cage, k);
        const rgbdetail::LoopStencils stencils = rgbdetail::limit_stencils(cage.positions.size(), cage.triangles, features, k);
        ASSERT_EQ(static_cast<std::size_t>(stencils.limit.rows()), level.base_space.size());
        ASSERT_EQ(static_cast<std::size_t>(stencils.limit.cols()), cage.positions.size());
        EXPECT_EQ(stencils.triangles, level.triangles);
        // Affine: every row sums to 1.
        for (Eigen::Index r = 0; r < stencils.limit.rows(); ++r)
            EXPECT_NEAR(stencils.limit.row(r).sum(), 1.0, 1e-14);

        const std::vector<glm::dvec3> limits = evaluate_rows(stencils.limit, cage.positions);
        const std::vector<glm::dvec3> controls = evaluate_rows(product, cage.positions);
        rgb::Mesh mesh = core_mesh(cage, features);
        if (k > 0) rgb::refine_uniform(mesh, k);
        rgb::HierarchyEvaluator evaluator(mesh.base());
        for (const auto& [v, i] : match(mesh, level, scale)) {
            const glm::dvec3 core_limit = rgb::limit_position(mesh, v);
            EXPECT_LE(glm::length(core_limit - limits[i]), 1e-12 * scale) << "vertex " << v.idx << " row " << i;
            const glm::dvec3 evaluator_limit = evaluator.limit_position(mesh.address(v));
            EXPECT_LE(glm::length(evaluator_limit - limits[i]), 1e-12 * scale) << "vertex " << v.idx << " row " << i;
            const glm::dvec3 core_control = rgb::control_point(mesh, v, k);
            EXPECT_LE(glm::length(core_control - controls[i]), 1e-12 * scale) << "vertex " << v.idx << " row " << i;
        }
        if (k < max_level) {
            product = rgbdetail::subdivision_matrix(topology) * product;
            topology = rgbdetail::LoopTopology(level.base_space.size() + topology.edges().size(), topology.refined_triangles(),
                                               topology.refined_features());
        }
    }
}

TEST(LoopStencils, MatchCoreOnClosedMeshes) {
    for (const Cage& cage : {tetrahedron(), octahedron(), icosahedron(), bipyramid(7), icosahedron_with_cone()}) {
        SCOPED_TRACE(cage.positions.size());
        expect_stencils_match_core(cage, {}, 2);
    }
}

TEST(LoopStencils, MatchCoreOnOpenGrids) {
    for (const Cage& cage : {grid(1, 1), grid(3, 2), grid(4, 4), half_cylinder(5, 3, 2.0)}) {
        SCOPED_TRACE(cage.positions.size());
        expect_stencils_match_core(cage, {}, 2);
    }
}

TEST(LoopStencils, MatchCoreOnPerturbedMeshes) {
    unsigned seed = 7;
    for (const Cage& cage : {icosahedron_with_cone(), bipyramid(5), grid(3, 3), torus(5, 4, 2.0, 0.7)}) {
        SCOPED_TRACE(cage.positions.size());
        expect_stencils_match_core(perturbed(cage, 0.2, ++seed), {}, 2);
    }
}

TEST(LoopStencils, SingleTriangleAndBoundaryRows) {
    // A lone triangle: every vertex is a boundary corner of valence 2.
    const Cage cage{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}};
    expect_stencils_match_core(cage, {}, 2);
    const rgbdetail::LoopStencils s = rgbdetail::limit_stencils(3, cage.triangles, {}, 0);
    EXPECT_DOUBLE_EQ(s.limit.coeff(0, 0), 2.0 / 3.0);
    EXPECT_DOUBLE_EQ(s.limit.coeff(0, 1), 1.0 / 6.0);
    EXPECT_DOUBLE_EQ(s.limit.coeff(0, 2), 1.0 / 6.0);
}

TEST(LoopStencils, RefusesNonManifoldInput) {
    // A directed edge twice (two faces with the same orientation on edge 0-1).
    EXPECT_THROW(rgbdetail::LoopTopology(4, std::vector<Triangle>{{0, 1, 2}, {0, 1, 3}}, {}), std::invalid_argument);
    // Two fans at vertex 0 (a bow tie).
    EXPECT_THROW(rgbdetail::LoopTopology(5, std::vector<Triangle>{{0, 1, 2}, {0, 3, 4}}, {}), std::invalid_argument);
    // An unused vertex.
    EXPECT_THROW(rgbdetail::LoopTopology(4, std::vector<Triangle>{{0, 1, 2}}, {}), std::invalid_argument);
    // An index out of range, a repeated corner.
    EXPECT_THROW(rgbdetail::LoopTopology(3, std::vector<Triangle>{{0, 1, 3}}, {}), std::invalid_argument);
    EXPECT_THROW(rgbdetail::LoopTopology(3, std::vector<Triangle>{{0, 1, 1}}, {}), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// Creases and corners: the same comparison with the core, whose tags the stencils must follow
// (docs/loop-creases.md). Every rule occurs: crease vertices on closed loops and open chains, corners
// by three sharp edges and by a tag, darts of valence 4, 5, 7, chains ending on the boundary,
// semi-sharp tags that run out at, before and after the stencils' level, edge-and-corner boundaries.
// ---------------------------------------------------------------------------------------------

using Edges = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

rgb::SharpFeatures creases(const Edges& edges, int sharpness = rgb::kInfiniteSharpness) {
    rgb::SharpFeatures features;
    for (const auto& [a, b] : edges) features.edges.push_back({a, b, sharpness});
    return features;
}

rgb::SharpFeatures with_corner(rgb::SharpFeatures features, std::uint32_t vertex, int sharpness = rgb::kInfiniteSharpness) {
    features.corners.push_back({vertex, sharpness});
    return features;
}

// The icosahedron's edges around vertex 0: a closed loop of five crease vertices of valence 5.
const Edges kIcosahedronLoop{{11, 5}, {5, 1}, {1, 7}, {7, 10}, {10, 11}};

// A horizontal chain of the grid's edges (row j, from column i0 to i1).
Edges grid_row(int nx, int j, int i0, int i1) {
    Edges edges;
    for (int i = i0; i < i1; ++i)
        edges.emplace_back(static_cast<std::uint32_t>(j * (nx + 1) + i), static_cast<std::uint32_t>(j * (nx + 1) + i + 1));
    return edges;
}

TEST(LoopStencilsCreases, CreaseLoops) {
    unsigned seed = 20;
    expect_stencils_match_core(perturbed(icosahedron(), 0.15, ++seed), creases(kIcosahedronLoop), 2);
    // The octahedron's equator: crease vertices of valence 4 between two smooth apexes.
    expect_stencils_match_core(perturbed(octahedron(), 0.15, ++seed), creases({{0, 2}, {2, 1}, {1, 3}, {3, 0}}), 2);
    // A loop around the torus's tube (j = 0), and one along it (i = 0): two loops crossing at a
    // corner of four sharp edges.
    Edges around, along;
    for (std::uint32_t i = 0; i < 5; ++i) around.emplace_back(i * 4, ((i + 1) % 5) * 4);
    for (std::uint32_t j = 0; j < 4; ++j) along.emplace_back(j, (j + 1) % 4);
    expect_stencils_match_core(perturbed(torus(5, 4, 2.0, 0.7), 0.1, ++seed), creases(around), 2);
    Edges both = around;
    both.insert(both.end(), along.begin(), along.end());
    expect_stencils_match_core(perturbed(torus(5, 4, 2.0, 0.7), 0.1, ++seed), creases(both), 2);
}

TEST(LoopStencilsCreases, CornersAndDarts) {
    unsigned seed = 30;
    // Vertex 4 a corner by its three sharp edges, 0, 2 and 1 darts of valence 4.
    expect_stencils_match_core(perturbed(octahedron(), 0.15, ++seed), creases({{4, 0}, {4, 2}, {4, 1}}), 2);
    // One sharp edge: two darts of valence 5; and the apex of a bipyramid, a dart of valence 7.
    expect_stencils_match_core(perturbed(icosahedron(), 0.15, ++seed), creases({{0, 1}}), 2);
    expect_stencils_match_core(perturbed(bipyramid(7), 0.15, ++seed), creases({{7, 0}}), 2);
    // Corners by tag: one on the crease loop, one on a smooth vertex, one at a dart's end.
    const rgb::SharpFeatures loop_and_dart = creases({{11, 5}, {5, 1}, {1, 7}, {7, 10}, {10, 11}, {3, 9}});
    expect_stencils_match_core(perturbed(icosahedron(), 0.15, ++seed), with_corner(with_corner(with_corner(loop_and_dart, 5), 6), 3), 2);
}

TEST(LoopStencilsCreases, CreasesMeetingTheBoundary) {
    unsigned seed = 40;
    auto wavy = [&](Cage c) { return perturbed(c, 0.2, ++seed); };
    // A chain across the grid: its boundary ends have three sharp edges (corners).
    expect_stencils_match_core(wavy(grid(4, 4)), creases(grid_row(4, 2, 0, 4)), 2);
    // A chain beside the boundary, ending inside (darts at both ends), and a single edge from a
    // boundary vertex inwards (a corner on the boundary, a dart inside).
    expect_stencils_match_core(wavy(grid(4, 4)), creases(grid_row(4, 1, 1, 3)), 2);
    expect_stencils_match_core(wavy(grid(4, 4)), creases({{2, 7}}), 2);
    // A crease along the half cylinder, from one open end to the other.
    expect_stencils_match_core(wavy(half_cylinder(5, 3, 2.0)), creases({{2, 8}, {8, 14}, {14, 20}}), 2);
}

TEST(LoopStencilsCreases, SemiSharpTags) {
    unsigned seed = 50;
    // Sharpness 1 runs out at level 1, 2 at the stencils' last level, 3 beyond it: then the limit
    // steps the one-ring on past level 2 (loop-creases.md §5.1).
    for (int sharpness : {1, 2, 3}) {
        SCOPED_TRACE(sharpness);
        expect_stencils_match_core(perturbed(icosahedron(), 0.15, ++seed), creases(kIcosahedronLoop, sharpness), 2);
        expect_stencils_match_core(perturbed(octahedron(), 0.15, ++seed), creases({{4, 0}, {4, 2}, {4, 1}}, sharpness), 2);
        expect_stencils_match_core(perturbed(grid(4, 4), 0.2, ++seed), creases(grid_row(4, 2, 0, 4), sharpness), 2);
        // A semi-sharp corner on an infinite loop, and an infinite corner on a semi-sharp loop.
        expect_stencils_match_core(perturbed(icosahedron(), 0.15, ++seed), with_corner(creases(kIcosahedronLoop), 5, sharpness), 2);
        expect_stencils_match_core(perturbed(icosahedron(), 0.15, ++seed), with_corner(creases(kIcosahedronLoop, sharpness), 5), 2);
    }
    // Mixed: a dart of sharpness 4 ending on a crease of sharpness 2 (a corner, then a crease, then a
    // dart, then smooth).
    rgb::SharpFeatures mixed = creases(kIcosahedronLoop, 2);
    mixed.edges.push_back({5, 4, 4});
    expect_stencils_match_core(perturbed(icosahedron(), 0.15, ++seed), mixed, 2);
}

TEST(LoopStencilsCreases, EdgeAndCornerBoundaries) {
    unsigned seed = 60;
    for (const Cage& cage : {grid(3, 2), half_cylinder(5, 3, 2.0), Cage{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}}}) {
        SCOPED_TRACE(cage.positions.size());
        rgb::SharpFeatures features;
        features.boundary = rgb::BoundaryInterpolation::EdgeAndCorner;
        expect_stencils_match_core(perturbed(cage, 0.1, ++seed), features, 2);
    }
    rgb::SharpFeatures features = creases(grid_row(3, 1, 0, 3));
    features.boundary = rgb::BoundaryInterpolation::EdgeAndCorner;
    expect_stencils_match_core(perturbed(grid(3, 2), 0.1, ++seed), features, 2);
}

TEST(LoopStencilsCreases, RefusesTagsThatAreNotOnTheCage) {
    const Cage cage = octahedron();
    auto topology = [&](const rgb::SharpFeatures& f) { return rgbdetail::LoopTopology(cage.positions.size(), cage.triangles, f); };
    EXPECT_THROW(topology(creases({{0, 1}})), std::invalid_argument);  // opposite vertices: no edge
    EXPECT_THROW(topology(creases({{0, 6}})), std::invalid_argument);  // no vertex 6
    EXPECT_THROW(topology(creases({{0, 2}}, -1)), std::invalid_argument);
    EXPECT_THROW(topology(with_corner({}, 6)), std::invalid_argument);
    EXPECT_THROW(topology(with_corner({}, 0, -2)), std::invalid_argument);
    // As BaseMesh reads tags: the later of two tags of one edge counts, above 10 is 10.
    const rgbdetail::LoopTopology t = topology(creases({{0, 2}, {2, 0}}, 3));
    EXPECT_EQ(t.rule(0), rgb::VertexRule::Dart);
    rgb::SharpFeatures retagged = creases({{0, 2}}, 25);
    retagged.edges.push_back({2, 0, 0});
    EXPECT_EQ(topology(retagged).rule(0), rgb::VertexRule::Smooth);
    EXPECT_EQ(topology(creases({{0, 2}}, 25)).refined_features().edges.front().sharpness, rgb::kInfiniteSharpness);
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
SurfaceError core_limit_error(const Cage& cage, const rgb::SharpFeatures& features, int level, const Distance& distance) {
    rgb::Mesh mesh = core_mesh(cage, features);
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
        const rgbdetail::FitResult r = rgbdetail::fit_cage(cage.positions, cage.triangles, {}, closest_on_unit_sphere, options);
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
        const SurfaceError e = core_limit_error({r.positions, cage.triangles}, {}, 3, sphere_distance);
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
    const rgbdetail::FitResult r = rgbdetail::fit_cage(cage.positions, cage.triangles, {}, closest, {});
    print_history("torus 10x6", r);
    EXPECT_GT(r.distances.front().rms, 0.05);
    // Measured: rms 0.0863 -> 7.2e-3, 5.3e-3, 4.5e-3, 3.9e-3 (max 0.172 -> 0.0117): still going
    // down at the fourth iteration, as the closest points slide along the tube. Bounds with margin
    // (1.5% and 4.5% of the tube's radius).
    EXPECT_LT(r.distances.back().rms, 0.015 * surface.minor);
    EXPECT_LT(r.distances.back().max, 0.045 * surface.minor);
    const SurfaceError e = core_limit_error({r.positions, cage.triangles}, {}, 3, [&](const glm::dvec3& p) { return surface.distance(p); });
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
    const rgbdetail::FitResult r = rgbdetail::fit_cage(cage.positions, cage.triangles, {}, closest, {});
    print_history("half cylinder", r);
    EXPECT_GT(r.distances.front().rms, 0.3);
    // Measured: rms 0.441 -> 3.0e-3 (max 8.9e-3); the core's dense limits rms 2.8e-3.
    EXPECT_LT(r.distances.back().rms, 6e-3);
    EXPECT_LT(r.distances.back().max, 0.02);
    const SurfaceError e = core_limit_error({r.positions, cage.triangles}, {}, 3, [](const glm::dvec3& p) {
        return std::abs(std::hypot(p.x, p.z) - 1.0);
    });
    std::printf("  core limit at level 3: rms %.3g max %.3g\n", e.rms, e.max);
    EXPECT_LT(e.rms, 6e-3);
}

// The cube's surface: the nearest point of the solid box from outside, the nearest face from inside.
glm::dvec3 closest_on_cube(const glm::dvec3& p) {
    const glm::dvec3 clamped = glm::clamp(p, glm::dvec3(-1.0), glm::dvec3(1.0));
    if (clamped != p) return clamped;
    glm::dvec3 q = p;
    int axis = 0;
    for (int i = 1; i < 3; ++i)
        if (std::abs(p[i]) > std::abs(p[axis])) axis = i;
    q[axis] = p[axis] < 0.0 ? -1.0 : 1.0;
    return q;
}

double distance_to_cube(const glm::dvec3& p) { return glm::length(p - closest_on_cube(p)); }

// Tags by the dihedral angle, as remesh --sharp-angle tags its cage.
rgb::SharpFeatures sharper_than(const Cage& cage, double degrees) {
    rgb::SharpFeatures features;
    features.edges = rgb::edges_sharper_than(rgb::BaseMesh(cage.positions, cage.triangles), degrees);
    return features;
}

TEST(CageFit, CreasedCubeCageToCube) {
    // A cube cage of 2 x 2 squares a face, enlarged and perturbed, fitted to the cube: untagged, its
    // limit surface rounds the cube's edges and corners; with the cube's edges tagged (vertices on
    // them crease vertices, the eight corners corner vertices by their three sharp edges) every rule
    // keeps a face's points in the face's plane, so the creased surface can be the cube exactly.
    Cage cage = cube(2);
    for (glm::dvec3& p : cage.positions) p *= 1.3;
    const rgb::SharpFeatures features = sharper_than(cage, 45.0);
    ASSERT_EQ(features.edges.size(), 24u);  // 12 cube edges of two cage edges each
    cage = perturbed(cage, 0.05, 71);
    rgbdetail::FitOptions options;
    options.iterations = 8;
    const rgbdetail::FitResult smooth = rgbdetail::fit_cage(cage.positions, cage.triangles, {}, closest_on_cube, options);
    const rgbdetail::FitResult creased = rgbdetail::fit_cage(cage.positions, cage.triangles, features, closest_on_cube, options);
    print_history("cube, untagged", smooth);
    print_history("cube, edges tagged", creased);
    const SurfaceError smooth_core = core_limit_error({smooth.positions, cage.triangles}, {}, 3, distance_to_cube);
    const SurfaceError creased_core = core_limit_error({creased.positions, cage.triangles}, features, 3, distance_to_cube);
    std::printf("  core limit at level 3: untagged rms %.3g max %.3g, tagged rms %.3g max %.3g\n", smooth_core.rms, smooth_core.max,
                creased_core.rms, creased_core.max);
    // Measured (8 iterations): untagged rms 0.212 -> 0.0259, max 0.313 -> 0.0634, stalled from the
    // fourth on (a smooth surface cannot have the edges); tagged rms 0.331 -> 3.8e-4, max 0.534 ->
    // 1.7e-3, halving at every iteration as the closest points slide. The core's level-3 limits:
    // untagged rms 0.0239, max 0.0634; tagged rms 3.2e-4, max 1.7e-3.
    EXPECT_LT(creased.distances.back().rms, 0.1 * smooth.distances.back().rms);
    EXPECT_LT(creased.distances.back().max, 0.1 * smooth.distances.back().max);
    EXPECT_LT(creased_core.rms, 0.1 * smooth_core.rms);
    EXPECT_LT(creased_core.max, 0.1 * smooth_core.max);
}

TEST(CageFit, RemeshWithSharpAngleFitsTheCreasedSurface) {
    // A dense cube (12 x 12 squares a face) remeshed to a cage of about 100 triangles, once with
    // --sharp-angle's tags and once without; the cage keeps M's vertices, so its edges along the cube's
    // edges are exactly right-angled.
    const Cage dense = cube(12);
    rgbdetail::RemeshOptions options;
    options.cage_triangles = 100;
    const rgbdetail::Remeshed smooth = rgbdetail::remesh(dense.positions, dense.triangles, options);
    options.sharp_angle = 45.0;
    const rgbdetail::Remeshed creased = rgbdetail::remesh(dense.positions, dense.triangles, options);
    const rgbdetail::RemeshReport& a = smooth.report;
    const rgbdetail::RemeshReport& b = creased.report;
    std::printf("dense cube to %zu triangles: untagged rms %.3g -> %.3g, max %.3g -> %.3g; tagged rms %.3g -> %.3g, max %.3g -> %.3g\n",
                b.cage_triangles, a.fit_before.rms, a.fit_after.rms, a.fit_before.max, a.fit_after.max, b.fit_before.rms, b.fit_after.rms,
                b.fit_before.max, b.fit_after.max);
    // Measured: untagged rms 0.0549 -> 0.0251, max 0.229 -> 0.129; tagged rms 1.3e-16 -> 5.5e-4, max
    // 5.1e-16 -> 4.2e-3. The tagged cage starts exactly on M (its faces planar, its creases straight,
    // its corners M's); the smoothing term's bias moves it that little off (cage_fit.h).
    EXPECT_LT(b.fit_after.rms, 0.1 * a.fit_after.rms);
    EXPECT_LT(b.fit_after.max, 0.1 * a.fit_after.max);
    EXPECT_TRUE(smooth.base->sharp_features().edges.empty());
    // The result carries the tags, and they are the cube's twelve edges: all on them, all of their
    // length (2 each), up to how far the fit moved the cage's vertices (its smoothing term's bias:
    // measured 3.5e-3 at most).
    const rgb::BaseMesh& base = *creased.base;
    const double moved = 0.01;
    double tagged_length = 0.0;
    for (const rgb::EdgeSharpness& e : base.sharp_features().edges) {
        EXPECT_EQ(e.sharpness, rgb::kInfiniteSharpness);
        for (const glm::dvec3& p : {base.position(e.a), base.position(e.b)}) {
            const int on_faces = (std::abs(std::abs(p.x) - 1.0) < moved) + (std::abs(std::abs(p.y) - 1.0) < moved) +
                                 (std::abs(std::abs(p.z) - 1.0) < moved);
            EXPECT_GE(on_faces, 2) << "vertex " << p.x << " " << p.y << " " << p.z;
        }
        tagged_length += glm::distance(base.position(e.a), base.position(e.b));
    }
    EXPECT_NEAR(tagged_length, 24.0, 24.0 * moved);
    // The fitted creased limit surface, measured by the core: on the cube.
    const Cage fitted{{base.positions().begin(), base.positions().end()}, {base.faces().begin(), base.faces().end()}};
    const SurfaceError e = core_limit_error(fitted, base.sharp_features(), 3, distance_to_cube);
    std::printf("  core limit at level 3 of the tagged fit: rms %.3g max %.3g\n", e.rms, e.max);
    EXPECT_LT(e.max, 0.1 * a.fit_after.max);
}

TEST(CageFit, Deterministic) {
    const Cage cage = perturbed(icosahedron_with_cone(), 0.1, 11);
    rgbdetail::FitOptions options;
    options.iterations = 3;
    const rgbdetail::FitResult a = rgbdetail::fit_cage(cage.positions, cage.triangles, {}, closest_on_unit_sphere, options);
    const rgbdetail::FitResult b = rgbdetail::fit_cage(cage.positions, cage.triangles, {}, closest_on_unit_sphere, options);
    ASSERT_EQ(a.positions.size(), b.positions.size());
    for (std::size_t i = 0; i < a.positions.size(); ++i) EXPECT_EQ(a.positions[i], b.positions[i]) << i;
    ASSERT_EQ(a.distances.size(), b.distances.size());
    for (std::size_t i = 0; i < a.distances.size(); ++i) {
        EXPECT_EQ(a.distances[i].rms, b.distances[i].rms);
        EXPECT_EQ(a.distances[i].max, b.distances[i].max);
    }
    // Parallel closest-point queries give the same bits (each sample's target is its own).
    options.parallel_targets = true;
    const rgbdetail::FitResult c = rgbdetail::fit_cage(cage.positions, cage.triangles, {}, closest_on_unit_sphere, options);
    for (std::size_t i = 0; i < a.positions.size(); ++i) EXPECT_EQ(a.positions[i], c.positions[i]) << i;
}

TEST(CageFit, ZeroIterationsAndBadInput) {
    const Cage cage = octahedron();
    rgbdetail::FitOptions options;
    options.iterations = 0;
    const rgbdetail::FitResult r = rgbdetail::fit_cage(cage.positions, cage.triangles, {}, closest_on_unit_sphere, options);
    EXPECT_EQ(r.positions, cage.positions);
    EXPECT_EQ(r.distances.size(), 1u);
    std::vector<glm::dvec3> too_few(cage.positions.begin(), cage.positions.end() - 1);
    EXPECT_THROW(rgbdetail::fit_cage(too_few, cage.triangles, {}, closest_on_unit_sphere, {}), std::invalid_argument);
    options.lambda = -1.0;
    EXPECT_THROW(rgbdetail::fit_cage(cage.positions, cage.triangles, {}, closest_on_unit_sphere, options), std::invalid_argument);
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
        const rgbdetail::FitResult r = rgbdetail::fit_cage(cage.positions, cage.triangles, {}, closest, options);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::printf("5k-triangle torus cage, level-%d samples (%zu), 4 iterations: %.3f s, rms %.3g -> %.3g\n",
                    sample_level, r.samples, seconds, r.distances.front().rms, r.distances.back().rms);
        EXPECT_LT(r.distances.back().rms, r.distances.front().rms);
    }
}

}  // namespace fit_test
}  // namespace
