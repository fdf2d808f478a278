// A dense mesh in, a cage with its detail out (detail/remesh.h), checked from outside: every displayed
// vertex of random levels, spheres and budgets up to the sampled level lies on the dense mesh M (a
// brute-force closest-point query of this test's own over all of M's triangles); requests stay
// canonical (two orders, one mesh); a save and reload, and level 0, give the same positions; the
// cage has M's topology and its triangle budget.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "detail/remesh.h"
#include "rgb/lod/limit_error.h"
#include "rgb/lod/lod_criteria.h"
#include "rgb/lod/lod_driver.h"
#include "rgb/lod/requests.h"
#include "rgb/mesh/detail_positions.h"
#include "rgb/mesh/mesh.h"
#include "rgb/values/loop_geometry.h"
#include "rgb/values/restore_state.h"
#include "rgb/values/surface_error.h"

namespace remesh_test {

struct Dense {
    std::vector<glm::dvec3> positions;
    std::vector<rgb::Triangle> triangles;
    double diagonal = 0.0;
};

// A bumpy torus: a dense closed surface of genus 1 with detail a cage cannot hold.
Dense bumpy_torus(int around, int tube) {
    Dense m;
    for (int i = 0; i < around; ++i)
        for (int j = 0; j < tube; ++j) {
            const double u = 2 * M_PI * i / around, v = 2 * M_PI * j / tube;
            const double r = 0.35 + 0.02 * std::sin(9 * u) * std::cos(5 * v);
            m.positions.push_back({(1 + r * std::cos(v)) * std::cos(u), (1 + r * std::cos(v)) * std::sin(u), r * std::sin(v)});
        }
    auto at = [&](int i, int j) { return static_cast<std::uint32_t>((i % around) * tube + (j % tube)); };
    for (int i = 0; i < around; ++i)
        for (int j = 0; j < tube; ++j) {
            m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    m.diagonal = glm::distance(glm::dvec3(-1.4, -1.4, -0.4), glm::dvec3(1.4, 1.4, 0.4));
    return m;
}

// The distance from p to the closest point of triangle abc (Ericson's regions), exact in double.
double point_triangle_distance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return glm::distance(p, a);
    const glm::dvec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return glm::distance(p, b);
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return glm::distance(p, a + d1 / (d1 - d3) * ab);
    const glm::dvec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return glm::distance(p, c);
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return glm::distance(p, a + d2 / (d2 - d6) * ac);
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return glm::distance(p, b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b));
    const double denom = 1.0 / (va + vb + vc);
    return glm::distance(p, a + ab * (vb * denom) + ac * (vc * denom));
}

double distance_to(const Dense& m, const glm::dvec3& p) {
    double best = std::numeric_limits<double>::max();
    for (const rgb::Triangle& t : m.triangles)
        best = std::min(best, point_triangle_distance(p, m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]));
    return best;
}

// Every vertex of up to `level` (sampled) of a sample of the mesh's vertices lies on M.
void expect_on_dense(const rgb::Mesh& mesh, const Dense& m, int sampled_level, std::size_t samples) {
    std::vector<rgb::VertexId> candidates;
    for (rgb::VertexId v : mesh.vertices())
        if (mesh.level(v) <= sampled_level) candidates.push_back(v);
    std::mt19937 rng(3);
    std::shuffle(candidates.begin(), candidates.end(), rng);
    candidates.resize(std::min(candidates.size(), samples));
    for (rgb::VertexId v : candidates) ASSERT_LT(distance_to(m, rgb::displayed_position(mesh, v)), 1e-9 * m.diagonal);
}

class Remesh : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        dense_ = new Dense(bumpy_torus(96, 48));  // 9,216 triangles
        rgbdetail::RemeshOptions options;
        options.cage_triangles = 300;
        options.source_name = "bumpy torus";
        remeshed_ = new rgbdetail::Remeshed(rgbdetail::remesh(dense_->positions, dense_->triangles, options));
    }
    static void TearDownTestSuite() {
        delete dense_;
        delete remeshed_;
    }
    static Dense* dense_;
    static rgbdetail::Remeshed* remeshed_;
};
Dense* Remesh::dense_ = nullptr;
rgbdetail::Remeshed* Remesh::remeshed_ = nullptr;

TEST_F(Remesh, TheCageHasTheTopologyAndBudget) {
    const rgb::BaseMesh& base = *remeshed_->base;
    EXPECT_LE(base.num_faces(), 300u);
    EXPECT_GE(base.num_faces(), 100u);
    // A closed genus-1 surface: V - E + F = 0, every edge with two faces.
    std::size_t boundary = 0;
    for (std::uint32_t h = 0; h < 3 * base.num_faces(); ++h) boundary += base.opposite(h) == rgb::BaseMesh::kNone;
    EXPECT_EQ(boundary, 0u);
    const long euler = long(base.num_vertices()) - long(3 * base.num_faces() / 2) + long(base.num_faces());
    EXPECT_EQ(euler, 0);
    const rgbdetail::RemeshReport& r = remeshed_->report;
    EXPECT_LT(r.fit_after.rms, r.fit_before.rms);
    // Σ_K as dense as M: 300 * 4^K >= 9216 first at K = 3 (or 4 for a cage of fewer than 144).
    EXPECT_EQ(r.detail_level, rgbdetail::detail_level_for(base.num_faces(), dense_->triangles.size(), 6));
    EXPECT_GE(base.num_faces() << (2 * r.detail_level), dense_->triangles.size());
    EXPECT_EQ(base.detail()->origin().source, "bumpy torus");
    EXPECT_EQ(base.detail()->origin().source_triangles, dense_->triangles.size());
}

TEST_F(Remesh, EveryDisplayedVertexUpToTheSampledLevelLiesOnTheMesh) {
    const int k = remeshed_->report.detail_level;
    rgb::Mesh level0(remeshed_->base);
    expect_on_dense(level0, *dense_, k, 200);
    rgb::Mesh uniform(remeshed_->base);
    rgb::set_level(uniform, k);
    expect_on_dense(uniform, *dense_, k, 300);
    std::mt19937 rng(5);
    rgb::Mesh spheres(remeshed_->base);
    for (int i = 0; i < 5; ++i) {
        const glm::dvec3 centre = dense_->positions[rng() % dense_->positions.size()];
        rgb::set_level(spheres, 1 + static_cast<int>(rng() % static_cast<unsigned>(k)), rgb::Sphere{centre, 0.3});
    }
    expect_on_dense(spheres, *dense_, k, 300);
}

TEST_F(Remesh, RequestsStayCanonicalAndSurviveARestore) {
    const std::vector<std::pair<int, rgb::Sphere>> requests{{3, {{1, 0, 0}, 0.5}}, {1, {{0, 1, 0}, 0.8}}, {2, {{-1, 0, 0.2}, 0.4}}};
    // Refine requests (one kind) give one mesh in any order (docs/requests.md).
    auto refine = [](rgb::Mesh& mesh, int level, const rgb::Sphere& sphere) {
        rgb::LevelRequest request;
        request.kind = rgb::RequestKind::Refine;
        request.level = level;
        request.sphere = sphere;
        rgb::apply_request(mesh, request);
    };
    rgb::Mesh forward(remeshed_->base), backward(remeshed_->base);
    for (const auto& [level, sphere] : requests) refine(forward, level, sphere);
    for (auto it = requests.rbegin(); it != requests.rend(); ++it) refine(backward, it->first, it->second);
    ASSERT_EQ(forward.num_faces(), backward.num_faces());
    std::vector<glm::dvec3> a, b;
    for (rgb::VertexId v : forward.vertices()) a.push_back(rgb::displayed_position(forward, v));
    for (rgb::VertexId v : backward.vertices()) b.push_back(rgb::displayed_position(backward, v));
    std::sort(a.begin(), a.end(), [](const glm::dvec3& x, const glm::dvec3& y) { return std::tie(x.x, x.y, x.z) < std::tie(y.x, y.y, y.z); });
    std::sort(b.begin(), b.end(), [](const glm::dvec3& x, const glm::dvec3& y) { return std::tie(x.x, x.y, x.z) < std::tie(y.x, y.y, y.z); });
    EXPECT_EQ(a, b);
    rgb::Mesh restored = rgb::restore_state(rgb::capture_state(forward));
    for (rgb::VertexId v : restored.vertices()) ASSERT_EQ(rgb::displayed_position(restored, v), rgb::displayed_position(forward, v));
    // Level 0 again: the cage, its vertices on M.
    rgb::set_level(restored, 0);
    EXPECT_EQ(restored.num_faces(), remeshed_->base->num_faces());
    expect_on_dense(restored, *dense_, 0, 200);
}

// --tolerance on a cage with detail measures the dense surface: a Set over the whole surface leaves
// every sample of every green face (its vertices of Σ(l+2)) within the tolerance of M, checked by the
// brute-force distance to M; the error the core reports is within it too.
TEST_F(Remesh, ToleranceMeasuresTheDenseMesh) {
    const double tolerance = 0.004 * dense_->diagonal;
    rgb::Mesh mesh(remeshed_->base);
    rgb::DetailRequest request;
    request.value = rgb::limit_error_value(remeshed_->base, tolerance);
    request.threshold = tolerance;
    request.max_triangles = 1'000'000;
    rgb::apply_detail_request(mesh, request);
    EXPECT_GT(mesh.num_faces(), remeshed_->base->num_faces());
    EXPECT_LE(rgb::displayed_surface_error(mesh).max_error, tolerance);
    std::size_t checked = 0;
    for (rgb::FaceId f : mesh.faces()) {
        if (mesh.colour(f) != rgb::Colour::Green || checked >= 400) continue;
        ++checked;
        std::array<glm::dvec3, 3> corners;
        for (int c = 0; c < 3; ++c) corners[c] = rgb::displayed_position(mesh, mesh.face_vertices(f)[c]);
        for (int i = 0; i <= 4; ++i)
            for (int j = 0; i + j <= 4; ++j) {
                const glm::dvec3 p = (double(4 - i - j) * corners[0] + double(i) * corners[1] + double(j) * corners[2]) / 4.0;
                ASSERT_LE(distance_to(*dense_, p), tolerance * (1 + 1e-9));
            }
    }
    EXPECT_GT(checked, 100u);
}

// A budget on a cage with detail spends its triangles where the surface departs most from M: at the
// triangle count of a uniform level, its largest error to M is below the uniform level's.
TEST_F(Remesh, BudgetSpendsWhereTheSurfaceDepartsFromTheDenseMesh) {
    rgb::Mesh uniform(remeshed_->base);
    rgb::set_level(uniform, 2);
    rgb::LodSettings settings;
    settings.value = rgb::on_mesh(rgb::detail_error_value(remeshed_->base));
    settings.max_triangles = uniform.num_faces();
    rgb::Mesh budget(remeshed_->base);
    rgb::LodDriver driver(budget, settings);
    driver.run();
    EXPECT_LE(budget.num_faces(), uniform.num_faces());
    EXPECT_LT(rgb::displayed_surface_error(budget).max_error, rgb::displayed_surface_error(uniform).max_error);
}

TEST(RemeshRefusals, BadMeshesAndCagesAreRefusedWithTheReason) {
    const Dense m = bumpy_torus(24, 12);
    rgbdetail::RemeshOptions options;
    options.cage_triangles = 10;  // a torus needs 14
    try {
        rgbdetail::remesh(m.positions, m.triangles, options);
        FAIL() << "a cage below the topology's smallest was made";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("14"), std::string::npos) << e.what();
    }
    options.cage_triangles = 100;
    EXPECT_THROW(rgbdetail::remesh({}, {}, options), std::invalid_argument);
    const std::vector<glm::dvec3> one{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    EXPECT_THROW(rgbdetail::remesh(one, std::vector<rgb::Triangle>{{0, 1, 2}}, options), std::invalid_argument);
    // A cage of another topology (a tetrahedron for a torus).
    options.cage_positions = std::vector<glm::dvec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    options.cage_triangles_given = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
    try {
        rgbdetail::remesh(m.positions, m.triangles, options);
        FAIL() << "a cage of another topology was used";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("topology"), std::string::npos) << e.what();
    }
}

TEST(RemeshStop, AStoppedRemeshThrowsStopped) {
    const Dense m = bumpy_torus(24, 12);
    rgbdetail::RemeshOptions options;
    options.cage_triangles = 100;
    options.progress = [](double share, const char*) { return share < 0.5; };
    EXPECT_THROW(rgbdetail::remesh(m.positions, m.triangles, options), rgbdetail::Stopped);
}

}  // namespace remesh_test
