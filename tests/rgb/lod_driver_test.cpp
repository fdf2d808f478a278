// The budget/criterion LOD driver (spec §3.3): it terminates, keeps the invariants, meets the
// criterion where the budget allows, and meets an even budget exactly on a closed mesh (every
// split and every removal changes the triangle count by two).
#include <gtest/gtest.h>

#include "rgb/invariants.h"
#include "rgb/lod_driver.h"
#include "rgb/loop_geometry.h"
#include "rgb/mesh.h"
#include "support/test_meshes.h"

namespace {

using namespace rgb;

// Edges of this level or finer never get split, so they are exempt from the criterion.
constexpr int kMaxLevel = 5;

LodSettings lengths(double wanted_left, double wanted_right, std::size_t budget) {
    LodSettings s;
    s.excess = edge_length_excess([=](const glm::dvec3& p) { return p.x < 0 ? wanted_left : wanted_right; });
    s.max_triangles = budget;
    s.max_level = kMaxLevel;
    return s;
}

TEST(LodDriver, MeetsTheCriterionWithinTheBudget) {
    Mesh mesh = rgbtest::make_rgb_mesh(rgbtest::icosahedron());
    LodDriver driver(mesh, lengths(0.15, 0.6, 1'000'000));
    driver.run();
    EXPECT_TRUE(driver.done());
    EXPECT_TRUE(check_invariants(mesh).ok());
    for (FaceId f : mesh.faces())
        for (int i = 0; i < 3; ++i) {
            const HalfedgeId h = Mesh::halfedge(f, i);
            const EdgeType t = mesh.edge_type(h);
            if (t.colour == Colour::Green && t.level < kMaxLevel) {
                EXPECT_LE(lengths(0.15, 0.6, 0).excess(mesh, h), 0.0) << "edge of level " << t.level;
            }
        }
}

// When every edge of the base mesh is already shorter than wanted, the driver removes everything.
TEST(LodDriver, CoarsensBackToTheBaseWhenNothingNeedsDetail) {
    Mesh mesh = rgbtest::make_rgb_mesh(rgbtest::icosahedron());
    const std::size_t base = mesh.num_faces();
    LodDriver(mesh, lengths(0.15, 0.3, 1'000'000)).run();
    EXPECT_GT(mesh.num_faces(), base);
    LodDriver(mesh, lengths(10.0, 10.0, 1'000'000)).run();
    EXPECT_TRUE(check_invariants(mesh).ok());
    EXPECT_EQ(mesh.num_faces(), base);
    EXPECT_EQ(mesh.max_vertex_level(), 0);
}

TEST(LodDriver, MeetsAnEvenBudgetExactly) {
    Mesh mesh = rgbtest::make_rgb_mesh(rgbtest::icosahedron());
    LodDriver(mesh, lengths(0.0, 0.0, 1000)).run();
    EXPECT_EQ(mesh.num_faces(), 1000u);
    LodDriver(mesh, lengths(0.0, 0.0, 300)).run();
    EXPECT_EQ(mesh.num_faces(), 300u);
    EXPECT_TRUE(check_invariants(mesh).ok());
}

}  // namespace
