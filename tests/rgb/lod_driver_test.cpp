// The criterion/budget LOD driver (spec §3.3) and what a run means (lod_driver.h): a criterion run
// gives the closure of the wanted vertices, computed independently on the uniform Loop oracle; budget
// results stay within the budget, are nested as the budget grows, ignore the mesh's history and
// storage, and stop at the level cap saying so; the finest faces of a budget form a few solid patches.
#include <algorithm>
#include <memory>
#include <set>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "rgb/lod/lod_driver.h"
#include "rgb/lod/requests.h"
#include "rgb/mesh/base_mesh.h"
#include "rgb/mesh/invariants.h"
#include "rgb/mesh/mesh.h"
#include "rgb/rules/sharp_features.h"
#include "support/budget_run.h"
#include "support/clear_threshold.h"
#include "support/identity_tracker.h"
#include "support/request_oracle.h"
#include "support/same_mesh.h"
#include "support/test_meshes.h"
#include "support/set_level.h"

namespace rgbtest {
namespace {

constexpr int kDriverOracleLevels = 4;

// The vertices a criterion run with `threshold` on edge lengths wants, by the meaning's own rule on
// oracle identities: a midpoint is wanted if its edge (in the uniform Loop mesh of its level) is
// longer than the threshold and both endpoints are wanted (base vertices are); edges of level `cap`
// and finer are never split.
std::set<Identity> wanted_vertices(const UniformLoopOracle& oracle, double threshold, int cap) {
    std::set<Identity> wanted;
    for (Identity i = 0; i < oracle.num_identities(0); ++i) wanted.insert(i);
    for (int j = 0; j < cap; ++j)
        for (const IdentityTriangle& t : oracle.faces(j))
            for (int i = 0; i < 3; ++i) {
                const Identity x = t[i], y = t[(i + 1) % 3];
                const double length = glm::distance(oracle.position(j, x), oracle.position(j, y));
                if (length > threshold && wanted.count(x) && wanted.count(y)) wanted.insert(*oracle.midpoint(x, y));
            }
    return wanted;
}

class LodDriverMeaning : public testing::TestWithParam<TestMesh> {};

TEST_P(LodDriverMeaning, ACriterionRunIsTheClosureOfTheWantedVertices) {
    const TestMesh& base = GetParam();
    const UniformLoopOracle oracle(base.positions, base.triangles, kDriverOracleLevels);
    const RequestOracle meaning(oracle);
    for (double share : {0.3, 0.6, 0.85}) {
        const double threshold = clear_threshold(oracle, kDriverOracleLevels, share);
        rgb::Mesh mesh = make_rgb_mesh(base);
        IdentityTracker ids(mesh, oracle);
        rgb::LodSettings settings;
        settings.threshold = threshold;
        settings.max_level = kDriverOracleLevels;
        rgb::LodDriver driver(mesh, settings);
        driver.run();
        EXPECT_FALSE(driver.report().budget_bound);
        EXPECT_EQ(ids.live_identities(), meaning.closure(wanted_vertices(oracle, threshold, kDriverOracleLevels))) << "share " << share;
        EXPECT_TRUE(rgb::check_invariants(mesh).ok());
        EXPECT_TRUE(rgb::check_normal_form(mesh).ok());
    }
}

TEST_P(LodDriverMeaning, BudgetsStayWithinAndGrowByAddingVertices) {
    const TestMesh& base = GetParam();
    constexpr int kCap = 5;
    const UniformLoopOracle oracle(base.positions, base.triangles, kCap);
    std::set<Identity> previous;
    for (std::size_t times : {2, 4, 9, 20, 45}) {
        const std::size_t budget = times * base.triangles.size();
        rgb::Mesh mesh = make_rgb_mesh(base);
        IdentityTracker ids(mesh, oracle);
        const rgb::LodReport report = run_budget(mesh, budget, kCap);
        EXPECT_LE(mesh.num_faces(), budget);
        EXPECT_TRUE(report.budget_bound);
        const std::set<Identity> now = ids.live_identities();
        EXPECT_TRUE(std::includes(now.begin(), now.end(), previous.begin(), previous.end())) << "budget " << budget;
        EXPECT_GT(now.size(), previous.size());
        previous = now;
        EXPECT_TRUE(rgb::check_invariants(mesh).ok());
        // The result is its own budget's result: nothing else fits in the triangles it has.
        rgb::Mesh again = make_rgb_mesh(base);
        run_budget(again, mesh.num_faces(), kCap);
        EXPECT_TRUE(same_mesh(mesh, again)) << "budget " << budget;
    }
}

TEST_P(LodDriverMeaning, BudgetResultsIgnoreHistoryAndStorage) {
    const TestMesh& base = GetParam();
    rgb::Mesh fresh = make_rgb_mesh(base);
    run_budget(fresh, 700);
    rgb::Mesh refined = make_rgb_mesh(base);
    rgbtest::set_level(refined, 3, rgb::Sphere{base.positions[0], 0.7 * bounding_box_diagonal(base.positions)});
    run_budget(refined, 700);
    EXPECT_TRUE(same_mesh(fresh, refined));
    rgb::Mesh coarser = make_rgb_mesh(base);
    run_budget(coarser, 300);
    run_budget(coarser, 700);
    EXPECT_TRUE(same_mesh(fresh, coarser));
    for (const TestMesh& stored : {with_rotated_corners(base), with_reversed_faces(base)}) {
        rgb::Mesh other = make_rgb_mesh(stored);
        run_budget(other, 700);
        EXPECT_TRUE(same_mesh(fresh, other)) << stored.name;
    }
}

INSTANTIATE_TEST_SUITE_P(Meshes, LodDriverMeaning,
                         testing::Values(icosahedron(), fan(7), grid(3, 2), perforated_slab(7, 7, 3)),
                         [](const auto& info) { return info.param.name; });

TEST(LodDriver, StopsAtTheLevelCapAndSaysSo) {
    rgb::Mesh mesh = make_rgb_mesh(icosahedron());
    const rgb::LodReport capped = run_budget(mesh, 1'000'000, 2);
    EXPECT_TRUE(capped.level_cap_bound);
    EXPECT_FALSE(capped.budget_bound);
    EXPECT_EQ(mesh.num_faces(), 20u * 16u);  // uniform level 2: every edge is wanted
    EXPECT_EQ(mesh.max_vertex_level(), 2);
    // Room for what the cap allows, not for a budget of a million.
    EXPECT_LT(mesh.reserved_face_slots(), 1000u);
    const rgb::LodReport free = run_budget(mesh, 1000);
    EXPECT_FALSE(free.level_cap_bound);
    EXPECT_TRUE(free.budget_bound);
}

TEST(LodDriver, CoarsensBackToTheBaseWhenNothingIsWanted) {
    rgb::Mesh mesh = make_rgb_mesh(icosahedron());
    const std::size_t base = mesh.num_faces();
    run_budget(mesh, 2000);
    EXPECT_GT(mesh.num_faces(), base);
    rgb::LodSettings settings;
    settings.threshold = 10.0;  // longer than any edge of the unit icosahedron
    rgb::LodDriver driver(mesh, settings);
    driver.run();
    EXPECT_EQ(driver.steps(), 0u);
    EXPECT_GT(driver.report().removals, 0u);
    EXPECT_EQ(mesh.num_faces(), base);
    EXPECT_EQ(mesh.max_vertex_level(), 0);
    EXPECT_TRUE(rgb::check_invariants(mesh).ok());
}

// The faces of the finest level a budget reaches, grouped by shared corners (a transition triangle
// at a patch's rim may touch it at a corner only).
std::vector<std::size_t> finest_patches(const rgb::Mesh& mesh) {
    int finest = 0;
    for (rgb::FaceId f : mesh.faces()) finest = std::max(finest, mesh.level(f));
    std::set<std::uint32_t> seen;
    std::vector<std::size_t> sizes;
    for (rgb::FaceId f : mesh.faces()) {
        if (mesh.level(f) != finest || !seen.insert(f.idx).second) continue;
        std::vector<rgb::FaceId> stack{f};
        std::size_t size = 0;
        while (!stack.empty()) {
            const rgb::FaceId g = stack.back();
            stack.pop_back();
            ++size;
            for (rgb::VertexId v : mesh.face_vertices(g)) {
                const rgb::HalfedgeId start = mesh.vertex_halfedge(v);
                rgb::HalfedgeId h = start;
                do {
                    const rgb::FaceId n = rgb::Mesh::face(h);
                    if (mesh.level(n) == finest && seen.insert(n.idx).second) stack.push_back(n);
                    h = mesh.ccw_rotated(h);
                } while (h.valid() && h != start);
            }
        }
        sizes.push_back(size);
    }
    return sizes;
}

// On a regular mesh every edge of a level is about as long as the next: a budget between two levels
// must still refine solid regions, not a lace of isolated triangles.
TEST(LodDriver, BudgetsBetweenLevelsRefineSolidPatches) {
    for (std::size_t budget : {900, 1500, 3000, 6000, 12000}) {
        rgb::Mesh mesh = make_rgb_mesh(icosahedron());
        run_budget(mesh, budget);
        const std::vector<std::size_t> patches = finest_patches(mesh);
        std::size_t total = 0;
        for (std::size_t s : patches) total += s;
        SCOPED_TRACE("budget " + std::to_string(budget));
        // A lace would be hundreds of patches of one or two splits each.
        EXPECT_LE(patches.size(), 3u);
        EXPECT_GE(*std::max_element(patches.begin(), patches.end()), total * 95 / 100);
        EXPECT_GE(total, mesh.num_faces() / 10);
        // Breadth first: nothing finer than one level past the uniform level the budget holds.
        int uniform = 0;
        while ((std::size_t(20) << (2 * (uniform + 1))) <= budget) ++uniform;
        int finest = 0;
        for (rgb::FaceId f : mesh.faces()) finest = std::max(finest, mesh.level(f));
        EXPECT_LE(finest, uniform + 1);
    }
}

// What a uniform start (LodSettings::uniform_start) must not change: the mesh and the report of the
// ordinary run with the same settings.
void expect_uniform_start_changes_nothing(const TestMesh& base, rgb::LodSettings settings, const rgb::SharpFeatures& features = {}) {
    const auto tagged = std::make_shared<const rgb::BaseMesh>(base.positions, base.triangles, features);
    rgb::Mesh ordinary(tagged), started(tagged);
    settings.uniform_start = false;
    rgb::LodDriver ordinary_run(ordinary, settings);
    ordinary_run.run();
    settings.uniform_start = true;
    rgb::LodDriver started_run(started, settings);
    started_run.run();
    SCOPED_TRACE(base.name + ", budget " + std::to_string(settings.max_triangles));
    EXPECT_TRUE(same_mesh(ordinary, started));
    EXPECT_TRUE(rgb::check_invariants(started).ok());
    EXPECT_TRUE(rgb::check_normal_form(started).ok());
    const rgb::LodReport& a = ordinary_run.report();
    const rgb::LodReport& b = started_run.report();
    EXPECT_EQ(a.splits, b.splits);
    EXPECT_EQ(a.removals, b.removals);
    EXPECT_EQ(a.budget_bound, b.budget_bound);
    EXPECT_EQ(a.level_cap_bound, b.level_cap_bound);
}

// A budget of four times a uniform level starts with that level whole; on a regular mesh the budget
// holds it, on one stretched tenfold the longest edges of finer levels outrank the shortest of the
// coarse one, so the start proves wrong at the budget and the run starts again. Both must give the
// ordinary run's result.
TEST(LodDriver, AUniformStartGivesTheOrdinaryResult) {
    TestMesh stretched = icosahedron();
    stretched.name = "stretched icosahedron";
    for (glm::dvec3& p : stretched.positions) p.x *= 10.0;
    for (const TestMesh& base : {icosahedron(), perforated_slab(7, 7, 3), stretched})
        for (std::size_t times : {4, 5, 16, 23, 64, 100, 300}) {
            rgb::LodSettings settings;
            settings.max_triangles = times * base.triangles.size();
            expect_uniform_start_changes_nothing(base, settings);
        }
    // Large enough that the start's limits and keys are computed on several threads (levels of more
    // than 8192 vertices, more than 16384 edges), where there are several cores.
    for (std::size_t times : {4, 64}) {
        rgb::LodSettings settings;
        settings.max_triangles = times * bunny().triangles.size();
        expect_uniform_start_changes_nothing(bunny(), settings);
    }
}

// With creases (two infinitely sharp edges and a semi-sharp one, so that rules change between levels)
// the keys take the general way and refine_uniform the tagged rules: still the ordinary result.
TEST(LodDriver, AUniformStartOnACreasedMeshGivesTheOrdinaryResult) {
    const TestMesh base = icosahedron();
    const rgb::Triangle& t = base.triangles.front();
    rgb::SharpFeatures features;
    features.edges = {{t[0], t[1], rgb::kInfiniteSharpness}, {t[1], t[2], rgb::kInfiniteSharpness}, {t[2], t[0], 2}};
    for (std::size_t times : {4, 16, 23, 64}) {
        rgb::LodSettings settings;
        settings.max_triangles = times * base.triangles.size();
        expect_uniform_start_changes_nothing(base, settings, features);
    }
}

// A vertex of the uniform levels that is not wanted (its edge's value is not above the threshold:
// here a criterion that wants nothing on one side of the plane x = 0) proves the start wrong at once.
TEST(LodDriver, AUniformStartWithUnwantedVerticesGivesTheOrdinaryResult) {
    rgb::LodSettings settings;
    settings.max_triangles = 64 * 20;
    settings.value = [](const rgb::Mesh& mesh, rgb::VertexId a, rgb::VertexId b, int level) {
        const double x = mesh.base_space_position(a).x + mesh.base_space_position(b).x;
        return x < 0.0 ? 0.0 : rgb::edge_length(mesh, a, b, level);
    };
    expect_uniform_start_changes_nothing(icosahedron(), settings);
}

}  // namespace
}  // namespace rgbtest
