// A dense mesh in, a cage with its detail out (detail/remesh.h), checked from outside: every displayed
// vertex of random levels, spheres and budgets up to the sampled level lies on the dense mesh M (a
// brute-force closest-point query of this test's own over all of M's triangles); requests stay
// canonical (two orders, one mesh); a save and reload, and level 0, give the same positions; the
// cage has M's topology and its triangle budget.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <random>
#include <span>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "detail/remesh.h"
#include "io/mesh_file.h"
#include "io/obj_reader.h"
#include "rgb/lod/limit_error.h"
#include "rgb/lod/lod_criteria.h"
#include "rgb/lod/lod_driver.h"
#include "rgb/lod/requests.h"
#include "rgb/mesh/detail_positions.h"
#include "rgb/mesh/mesh.h"
#include "rgb/values/loop_geometry.h"
#include "rgb/values/restore_state.h"
#include "rgb/values/surface_error.h"
#include "support/detail_sampling.h"
#include "support/set_level.h"

namespace remesh_test {

struct Dense {
    std::vector<glm::dvec3> positions;
    std::vector<rgb::Triangle> triangles;
    double diagonal = 0.0;
};

// A bumpy torus: a dense closed surface of genus 1 with detail a cage cannot hold, its tube circles
// at the given angles around the axis, each of `tube` vertices.
Dense bumpy_torus_at(const std::vector<double>& angles, int tube) {
    Dense m;
    const int around = static_cast<int>(angles.size());
    for (double u : angles)
        for (int j = 0; j < tube; ++j) {
            const double v = 2 * M_PI * j / tube;
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

// Its tube circles evenly spaced.
Dense bumpy_torus(int around, int tube) {
    std::vector<double> angles;
    for (int i = 0; i < around; ++i) angles.push_back(2 * M_PI * i / around);
    return bumpy_torus_at(angles, tube);
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

// Brute-force distances to M for checks that ask whether points lie within a bound of it: the first
// triangle found under the bound answers that, so the scan stops there, and it starts from the
// triangle that answered the last point (the next point asked is usually near it). A scan of every
// triangle for every point was nearly all of these tests' time under the sanitizers (test code at
// -O0); what each check concludes, and the distance a failure prints, are the same.
class DistanceToDense {
public:
    explicit DistanceToDense(const Dense& m) : m_(m) {}
    // The distance from p to M when that is `bound` or more, else the distance to a triangle of M
    // that is under `bound`: under `bound` exactly when p's distance to M is.
    double operator()(const glm::dvec3& p, double bound) {
        double best = std::numeric_limits<double>::max();
        for (std::size_t i = 0; i < m_.triangles.size(); ++i) {
            const std::size_t k = (start_ + i) % m_.triangles.size();
            const rgb::Triangle& t = m_.triangles[k];
            const double distance = point_triangle_distance(p, m_.positions[t[0]], m_.positions[t[1]], m_.positions[t[2]]);
            if (distance < bound) {
                start_ = k;
                return distance;
            }
            best = std::min(best, distance);
        }
        return best;
    }

private:
    const Dense& m_;
    std::size_t start_ = 0;  // the triangle that answered the last point
};

// Every vertex of up to `level` (sampled) of a sample of the mesh's vertices lies on M.
void expect_on_dense(const rgb::Mesh& mesh, const Dense& m, int sampled_level, std::size_t samples) {
    std::vector<rgb::VertexId> candidates;
    for (rgb::VertexId v : mesh.vertices())
        if (mesh.level(v) <= sampled_level) candidates.push_back(v);
    std::mt19937 rng(3);
    std::shuffle(candidates.begin(), candidates.end(), rng);
    candidates.resize(std::min(candidates.size(), samples));
    DistanceToDense distance_to(m);
    for (rgb::VertexId v : candidates) ASSERT_LT(distance_to(rgb::displayed_position(mesh, v), 1e-9 * m.diagonal), 1e-9 * m.diagonal);
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
    rgbtest::set_level(uniform, k);
    expect_on_dense(uniform, *dense_, k, 300);
    std::mt19937 rng(5);
    rgb::Mesh spheres(remeshed_->base);
    for (int i = 0; i < 5; ++i) {
        const glm::dvec3 centre = dense_->positions[rng() % dense_->positions.size()];
        rgbtest::set_level(spheres, 1 + static_cast<int>(rng() % static_cast<unsigned>(k)), rgb::Sphere{centre, 0.3});
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
    rgbtest::set_level(restored, 0);
    EXPECT_EQ(restored.num_faces(), remeshed_->base->num_faces());
    expect_on_dense(restored, *dense_, 0, 200);
}

// --tolerance on a cage with detail measures the dense surface: a Set over the whole surface leaves
// every sample of every green face (its vertices of Σ(l+2)) within the tolerance of M, checked by the
// brute-force distance to M; the error the core reports is within it too.
// The brute-force distance to M of every sample is most of this test's time; under the sanitizers
// (test code at -O0) it checks a quarter of the faces, all 400 in Release.
#if defined(__SANITIZE_ADDRESS__)
constexpr std::size_t kToleranceFacesChecked = 101;
#else
constexpr std::size_t kToleranceFacesChecked = 400;
#endif

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
    DistanceToDense distance_to(*dense_);
    std::size_t checked = 0;
    for (rgb::FaceId f : mesh.faces()) {
        if (mesh.colour(f) != rgb::Colour::Green || checked >= kToleranceFacesChecked) continue;
        ++checked;
        std::array<glm::dvec3, 3> corners;
        for (int c = 0; c < 3; ++c) corners[c] = rgb::displayed_position(mesh, mesh.face_vertices(f)[c]);
        for (int i = 0; i <= 4; ++i)
            for (int j = 0; i + j <= 4; ++j) {
                const glm::dvec3 p = (double(4 - i - j) * corners[0] + double(i) * corners[1] + double(j) * corners[2]) / 4.0;
                ASSERT_LE(distance_to(p, tolerance * (1 + 1e-9)), tolerance * (1 + 1e-9));
            }
    }
    EXPECT_GT(checked, 100u);
}

// A budget on a cage with detail spends its triangles where the surface departs most from M: at the
// triangle count of a uniform level, its largest error to M is below the uniform level's.
TEST_F(Remesh, BudgetSpendsWhereTheSurfaceDepartsFromTheDenseMesh) {
    rgb::Mesh uniform(remeshed_->base);
    rgbtest::set_level(uniform, 2);
    rgb::LodSettings settings;
    settings.value = rgb::on_mesh(rgb::detail_error_value(remeshed_->base));
    settings.max_triangles = uniform.num_faces();
    rgb::Mesh budget(remeshed_->base);
    rgb::LodDriver driver(budget, settings);
    driver.run();
    EXPECT_LE(budget.num_faces(), uniform.num_faces());
    EXPECT_LT(rgb::displayed_surface_error(budget).max_error, rgb::displayed_surface_error(uniform).max_error);
}

// The estimate of M's triangles per cage face against its meaning on a flat cage whose samples are
// its own base-space points (the identity): each face covers its own area, so the estimate is its
// area over the area of M's triangles there. Here M's triangles have area 0.01 for x <= 1 and 0.0025
// (four times as dense) beyond; a grid triangle across both takes the mean area of its corners'.
TEST(DenseTrianglesPerFace, AFaceCoversItsAreaOverTheAreaOfMsTriangles) {
    // A 4 x 2 grid of squares in the plane z = 0, each cut into two triangles.
    std::vector<glm::dvec3> positions;
    for (int j = 0; j <= 2; ++j)
        for (int i = 0; i <= 4; ++i) positions.push_back({0.5 * i, 0.5 * j, 0.0});
    std::vector<rgb::Triangle> triangles;
    for (std::uint32_t j = 0; j < 2; ++j)
        for (std::uint32_t i = 0; i < 4; ++i) {
            const std::uint32_t a = 5 * j + i;
            triangles.push_back({a, a + 1, a + 6});
            triangles.push_back({a, a + 6, a + 5});
        }
    const rgb::BaseMesh cage(positions, triangles);
    for (int level : {0, 2, 3}) {
        std::vector<glm::dvec3> values;
        std::vector<double> hit_areas;
        for (const rgb::SurfacePoint& p : rgb::DetailPositions::grid_points(cage, level)) {
            values.push_back(rgb::base_space_position(cage, p));
            hit_areas.push_back(values.back().x <= 1.0 ? 0.01 : 0.0025);
        }
        const std::vector<double> estimate = rgbdetail::dense_triangles_per_face(cage, level, values, hit_areas);
        ASSERT_EQ(estimate.size(), cage.num_faces());
        for (std::uint32_t f = 0; f < cage.num_faces(); ++f) {
            const glm::dvec3 a = positions[triangles[f][0]], b = positions[triangles[f][1]], c = positions[triangles[f][2]];
            const double area = 0.5 * glm::length(glm::cross(b - a, c - a));  // 0.125
            if (std::max({a.x, b.x, c.x}) <= 1.0) {
                EXPECT_NEAR(estimate[f], area / 0.01, 1e-9) << "face " << f << " level " << level;
            }
            if (std::min({a.x, b.x, c.x}) > 1.0) {
                EXPECT_NEAR(estimate[f], area / 0.0025, 1e-9) << "face " << f << " level " << level;
            }
            EXPECT_GE(estimate[f], area / 0.01 * (1 - 1e-12));
            EXPECT_LE(estimate[f], area / 0.0025 * (1 + 1e-12));
        }
    }
    // Each face's level: the smallest from the first level whose 4^K reaches the estimate, capped.
    const std::vector<double> counts{0.0, 1.0, 1.5, 4.0, 4.5, 16.0, 17.0, 1e9};
    const std::vector<std::uint8_t> from_zero{0, 0, 1, 1, 2, 2, 3, 6}, from_two{2, 2, 2, 2, 2, 2, 3, 6};
    EXPECT_EQ(rgbdetail::face_detail_levels(counts, 0, 6), from_zero);
    EXPECT_EQ(rgbdetail::face_detail_levels(counts, 2, 6), from_two);
}

// A torus whose tube circles crowd four times as densely on the half y > 0 (93 of them there, 23 on
// the other half, 16 vertices each: 3,712 triangles), and the user's cage of 8 x 4 squares over it
// (64 triangles). Σ_K as dense as M overall: K = 3 (4,096 triangles); the dense half's faces cover
// about 93 triangles of M each, more than 4^3, so they take level 4, the sparse half's 23 keep 3.
Dense uneven_torus() {
    constexpr int dense = 93, sparse = 23, tube = 16;
    std::vector<double> angles;
    for (int i = 0; i < dense; ++i) angles.push_back(M_PI * i / dense);
    for (int i = 0; i < sparse; ++i) angles.push_back(M_PI + M_PI * i / sparse);
    return bumpy_torus_at(angles, tube);
}

// The cage's faces 8 i .. 8 i + 7 lie between the circles at angles 2 pi i / 8 and 2 pi (i + 1) / 8.
rgbdetail::RemeshOptions uneven_torus_options() {
    rgbdetail::RemeshOptions options;
    std::vector<glm::dvec3> positions;
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 4; ++j) {
            const double u = 2 * M_PI * i / 8, v = 2 * M_PI * j / 4 + M_PI / 4;
            positions.push_back({(1 + 0.5 * std::cos(v)) * std::cos(u), (1 + 0.5 * std::cos(v)) * std::sin(u), 0.5 * std::sin(v)});
        }
    auto at = [](int i, int j) { return static_cast<std::uint32_t>((i % 8) * 4 + (j % 4)); };
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 4; ++j) {
            options.cage_triangles_given.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            options.cage_triangles_given.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    options.cage_positions = positions;
    options.source_name = "uneven torus";
    return options;
}

// Every displayed vertex the detail sampled lies on M within 1e-6 of its diagonal (the brute-force
// distance); returns how many were checked.
std::size_t expect_sampled_on_dense(const rgb::Mesh& mesh, const Dense& m) {
    const rgb::BaseMesh& base = mesh.base();
    const std::span<const std::uint8_t> levels = base.detail()->face_levels();
    DistanceToDense distance_to(m);
    std::size_t checked = 0;
    for (rgb::VertexId v : mesh.vertices()) {
        if (!rgbtest::sampled_by_definition(base, levels, mesh.address(v))) continue;
        const double distance = distance_to(rgb::displayed_position(mesh, v), 1e-6 * m.diagonal);
        EXPECT_LE(distance, 1e-6 * m.diagonal) << "vertex of level " << mesh.level(v);
        if (distance > 1e-6 * m.diagonal) return checked;
        ++checked;
    }
    return checked;
}

class UnevenRemesh : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        dense_ = new Dense(uneven_torus());
        remeshed_ = new rgbdetail::Remeshed(rgbdetail::remesh(dense_->positions, dense_->triangles, uneven_torus_options()));
    }
    static void TearDownTestSuite() {
        delete dense_;
        delete remeshed_;
    }
    static Dense* dense_;
    static rgbdetail::Remeshed* remeshed_;
};
Dense* UnevenRemesh::dense_ = nullptr;
rgbdetail::Remeshed* UnevenRemesh::remeshed_ = nullptr;

TEST_F(UnevenRemesh, FacesOverTheDenseHalfTakeAFinerLevel) {
    ASSERT_EQ(dense_->triangles.size(), 3712u);
    const rgbdetail::RemeshReport& r = remeshed_->report;
    EXPECT_EQ(r.detail_level, 3);
    EXPECT_EQ(r.finest_detail_level, 4);
    const rgb::DetailPositions& detail = *remeshed_->base->detail();
    const std::span<const std::uint8_t> levels = detail.face_levels();
    ASSERT_EQ(levels.size(), 64u);
    // Columns 1 and 2 lie well inside the dense half, 5 and 6 inside the sparse one; the others
    // border both (their limit surface reaches over the border).
    for (std::uint32_t f = 0; f < 64; ++f) {
        const std::uint32_t column = f / 8;
        if (column == 1 || column == 2) {
            EXPECT_EQ(levels[f], 4) << "face " << f;
        }
        if (column == 5 || column == 6) {
            EXPECT_EQ(levels[f], 3) << "face " << f;
        }
        EXPECT_GE(levels[f], 3);
        EXPECT_LE(levels[f], 4);
    }
    EXPECT_EQ(r.detail_points, rgb::DetailPositions::num_points(*remeshed_->base, levels));
    EXPECT_EQ(detail.origin().nearest_points, r.nearest_points);
}

// The property: from the saved file alone, every level up to the faces' levels, uniform, in
// random spheres and under a budget, has every vertex the detail sampled on M.
TEST_F(UnevenRemesh, EverySampledVertexOfTheReloadedFileLiesOnTheMesh) {
    rgb::Mesh cage(remeshed_->base);
    const std::string text = rgbio::format_obj(cage, {});
    const rgbio::LoadedMesh loaded = rgbio::read_obj_text(text, "uneven_cage.obj");
    ASSERT_TRUE(loaded.adaptive) << (loaded.warnings.empty() ? "" : loaded.warnings.front());
    const std::shared_ptr<const rgb::BaseMesh> base = loaded.adaptive->shared_base();
    ASSERT_NE(base->detail(), nullptr);
    const int finest = base->detail()->finest_level();
    for (int level = 0; level <= finest; ++level) {
        rgb::Mesh uniform(base);
        rgbtest::set_level(uniform, level);
        const std::size_t checked = expect_sampled_on_dense(uniform, *dense_);
        if (level <= base->detail()->coarsest_level()) {
            EXPECT_EQ(checked, uniform.num_vertices()) << "level " << level;
        } else {
            EXPECT_GT(checked, 0u) << "level " << level;
        }
    }
    std::mt19937 rng(29);
    rgb::Mesh spheres(base);
    for (int i = 0; i < 6; ++i) {
        const glm::dvec3 centre = dense_->positions[rng() % dense_->positions.size()];
        rgbtest::set_level(spheres, 1 + static_cast<int>(rng() % static_cast<unsigned>(finest + 1)), rgb::Sphere{centre, 0.4});
    }
    EXPECT_GT(expect_sampled_on_dense(spheres, *dense_), 0u);
    rgb::LodSettings settings;
    settings.value = rgb::on_mesh(rgb::detail_error_value(base));
    settings.max_triangles = 4000;
    rgb::Mesh budget(base);
    rgb::LodDriver(budget, settings).run();
    EXPECT_GT(budget.num_faces(), 1000u);
    EXPECT_GT(expect_sampled_on_dense(budget, *dense_), 0u);
}

// More points than allowed is refused before they are sampled: at the first level, or at the faces'
// levels.
TEST_F(UnevenRemesh, TooManyPointsAreRefused) {
    rgbdetail::RemeshOptions options = uneven_torus_options();
    const std::size_t first = rgb::DetailPositions::num_points(*remeshed_->base, rgb::DetailPositions::uniform_levels(*remeshed_->base, 3));
    for (std::size_t allowed : {first - 1, first}) {
        options.max_detail_points = allowed;
        try {
            rgbdetail::remesh(dense_->positions, dense_->triangles, options);
            FAIL() << "remeshed with " << allowed << " points allowed";
        } catch (const std::invalid_argument& e) {
            const std::string needed = std::to_string(allowed == first ? remeshed_->report.detail_points : first);
            EXPECT_NE(std::string(e.what()).find("would hold " + needed + " points"), std::string::npos) << e.what();
        }
    }
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

// Progress inside the phases: on a mesh of 25,600 triangles to a cage of 300 every phase reports
// many times (the decimation every 1024 collapses, the fit and the detail between chunks of their
// points), the share never decreases from 0 to 1, and a stop at any call throws at once.
struct ProgressCall {
    double share;
    std::string phase;
};

std::vector<ProgressCall> progress_calls(const Dense& m, std::size_t stop_at, bool& stopped) {
    std::vector<ProgressCall> calls;
    rgbdetail::RemeshOptions options;
    options.cage_triangles = 300;
    options.progress = [&](double share, const char* phase) {
        calls.push_back({share, phase});
        return calls.size() != stop_at + 1;
    };
    stopped = false;
    try {
        rgbdetail::remesh(m.positions, m.triangles, options);
    } catch (const rgbdetail::Stopped&) {
        stopped = true;
    }
    return calls;
}

TEST(RemeshProgress, MovesInEveryPhaseAndStopsAtOnce) {
    const Dense m = bumpy_torus(160, 80);
    bool stopped = false;
    const std::vector<ProgressCall> calls = progress_calls(m, std::numeric_limits<std::size_t>::max(), stopped);
    ASSERT_FALSE(stopped);
    ASSERT_GE(calls.size(), 2u);
    EXPECT_EQ(calls.front().share, 0.0);
    EXPECT_EQ(calls.back().share, 1.0);
    EXPECT_EQ(calls.back().phase, "done");
    for (std::size_t i = 1; i < calls.size(); ++i) ASSERT_GE(calls[i].share, calls[i - 1].share) << "call " << i;
    const std::vector<std::string> phases = {"making the cage",   "indexing the dense mesh",    "fitting the cage",
                                             "sampling the detail", "choosing the detail levels", "storing the detail"};
    const std::map<std::string, std::size_t> at_least = {
        // The decimation removes 25,300 faces, 2 a collapse: 12 reports, one every 1024 collapses.
        {"making the cage", 12},
        // M's search tree: the phase's start, the build's start and end, one before its compaction
        // and one before its corners, and one every 65,536 triangle visits while it is built: each of
        // the tree's 14 levels visits the 25,600 triangles once, 358,400 visits, and a report comes
        // within 65,536 + 25,600 (the largest node) of the last.
        {"indexing the dense mesh", 5 + 358400 / (65536 + 25600)},
        // The fit: its start, then the start and end of each of its 5 closest-point passes.
        {"fitting the cage", 11},
        // The detail: its start, then one before each chunk of 8192 points and one at the end of
        // each sampling (the first samples the 38,400 points of Σ4 in 5 chunks).
        {"sampling the detail", 8},
        // Between the samplings: the start and one after each of its four steps; after them, the
        // start and one before and after the detail is stored.
        {"choosing the detail levels", 5},
        {"storing the detail", 3}};
    for (const std::string& phase : phases) {
        std::vector<std::size_t> in_phase;
        for (std::size_t i = 0; i < calls.size(); ++i)
            if (calls[i].phase == phase) in_phase.push_back(i);
        EXPECT_GE(in_phase.size(), at_least.at(phase)) << phase;
        if (in_phase.empty()) continue;
        // A stop at the middle call of the phase: Stopped, and no call after it (so no later phase
        // starts, and remesh gives nothing).
        const std::size_t stop_at = in_phase[in_phase.size() / 2];
        bool stopped_there = false;
        const std::vector<ProgressCall> until_stop = progress_calls(m, stop_at, stopped_there);
        EXPECT_TRUE(stopped_there) << phase;
        EXPECT_EQ(until_stop.size(), stop_at + 1) << phase;
    }
}

}  // namespace remesh_test
