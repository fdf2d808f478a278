// The core's crease and corner rules (issue 13) against OpenSubdiv Far on the tagged meshes of
// crease_meshes.cpp (crease loops, chains ending in corners and darts, creases meeting the boundary
// under both boundary options, darts of valences 3-8, semi-sharp 1-3): uniform refinement equals
// Far's levels vertex by vertex, every vertex of random adaptive meshes equals Far's vertex of its
// level, limits equal the piecewise closed forms of docs/loop-creases.md computed by the tests' own
// code, and requests stay order independent and reversible with tags.
#include <cstdio>
#include <numeric>
#include <random>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "crease_closed_form.h"
#include "crease_meshes.h"
#include "far_by_identity.h"
#include "random_requests.h"
#include "rgb/lod/refine.h"
#include "rgb/lod/requests.h"
#include "rgb/mesh/invariants.h"
#include "rgb/values/loop_geometry.h"
#include "rgb/values/restore_state.h"
#include "support/oracle_checks.h"
#include "support/same_mesh.h"
#include "vertex_neighbourhood.h"
#include "support/set_level.h"

namespace osdoracle {
namespace {

constexpr int kFarLevels = 4;

// The largest error seen over every case, reported once at the end of the suite.
double worst_uniform = 0.0, worst_adaptive = 0.0;

class SharpRefinement : public testing::TestWithParam<CreaseCase> {
protected:
    static void TearDownTestSuite() {
        std::printf("[ far ] largest distance to Far: uniform %.3g, adaptive %.3g (the tolerance is 1e-12 of each "
                    "case's bounding-box diagonal)\n",
                    worst_uniform, worst_adaptive);
    }
    const FarInput& input = GetParam().input;
    const FarByIdentity far{input, kFarLevels};
    rgb::Mesh fresh() const { return rgb::Mesh(tagged_base(input)); }
};

TEST_P(SharpRefinement, UniformRefinementEqualsFarAtEveryLevel) {
    rgb::Mesh mesh = fresh();
    rgbtest::IdentityTracker ids(mesh, far.oracle());
    for (int k = 1; k <= kFarLevels; ++k) {
        rgb::refine_uniform(mesh, k);
        ASSERT_EQ(mesh.num_vertices(), far.oracle().num_identities(k)) << "level " << k;
        for (rgb::VertexId v : mesh.vertices()) ASSERT_EQ(rgb::display_level(mesh, v), k);
        ASSERT_TRUE(agrees_with_far(mesh, ids, far, &worst_uniform)) << "level " << k;
    }
}

TEST_P(SharpRefinement, LimitsEqualThePiecewiseClosedFormsFromEachVertexsOwnLevel) {
    // docs/loop-creases.md §4-§6 as the tests' own code computes it (crease_closed_form.cpp) from Far's
    // neighbourhood at the vertex's level: exact for darts and semi-sharp vertices too, where Far's own
    // limit masks are not.
    const std::vector<LevelTags> tags = tags_per_level(input, far.refinement());
    rgb::Mesh mesh = fresh();
    rgbtest::IdentityTracker ids(mesh, far.oracle());
    rgb::refine_uniform(mesh, kFarLevels - 1);
    for (rgb::VertexId v : mesh.vertices()) {
        const int l = mesh.level(v);
        const Neighbourhood n = gather_neighbourhood(far.refinement().levels[l], tags[l], far.far_index(l, ids.identity(v)));
        EXPECT_LE(glm::distance(rgb::limit_position(mesh, v), piecewise_limit(n)), far.tolerance())
            << "vertex " << v.idx << " of level " << l;
    }
}

TEST_P(SharpRefinement, EveryVertexOfRandomAdaptiveMeshesEqualsFarsVertexOfItsLevel) {
    std::mt19937 rng(131);
    for (int trial = 0; trial < 5; ++trial) {
        rgb::Mesh mesh = fresh();
        rgbtest::IdentityTracker ids(mesh, far.oracle());
        for (const rgb::LevelRequest& r : random_requests(input, rng, 6, -1)) {
            rgb::apply_request(mesh, r);
            ASSERT_TRUE(rgbtest::invariants_hold(mesh)) << "trial " << trial;
            ASSERT_TRUE(agrees_with_far(mesh, ids, far, &worst_adaptive)) << "trial " << trial;
        }
        // Reversible: level 0 gives the base mesh back, bit for bit.
        rgbtest::set_level(mesh, 0);
        ASSERT_EQ(mesh.num_vertices(), input.positions.size());
        for (rgb::VertexId v : mesh.vertices())
            ASSERT_EQ(rgb::displayed_position(mesh, v), input.positions[v.idx]) << "trial " << trial;
    }
}

TEST_P(SharpRefinement, RequestsOfOneKindGiveTheIdenticalMeshInEveryOrder) {
    std::mt19937 rng(132);
    for (int kind : {0, 1}) {
        const std::vector<rgb::LevelRequest> requests = random_requests(input, rng, 4, kind);
        std::vector<std::size_t> order(requests.size());
        std::iota(order.begin(), order.end(), 0);
        auto apply_in = [&](const std::vector<std::size_t>& o) {
            rgb::Mesh m = fresh();
            for (std::size_t i : o) {
                rgb::LevelRequest r = requests[i];
                if (kind == 1) r.level = 2;  // Set requests commute for one level
                rgb::apply_request(m, r);
            }
            return m;
        };
        const rgb::Mesh first = apply_in(order);
        while (std::next_permutation(order.begin(), order.end()))
            ASSERT_TRUE(rgbtest::same_mesh(first, apply_in(order))) << "kind " << kind;
    }
}

TEST_P(SharpRefinement, SavedStateKeepsTheTagsAndRestoresTheSameMesh) {
    std::mt19937 rng(133);
    rgb::Mesh mesh = fresh();
    for (const rgb::LevelRequest& r : random_requests(input, rng, 4, -1)) rgb::apply_request(mesh, r);
    const rgb::MeshState state = rgb::capture_state(mesh);
    EXPECT_EQ(state.sharp_features, tagged_base(input)->sharp_features());
    const rgb::Mesh restored = rgb::restore_state(state);
    EXPECT_TRUE(rgbtest::same_mesh(mesh, restored));
}

INSTANTIATE_TEST_SUITE_P(TaggedMeshes, SharpRefinement, testing::ValuesIn(crease_cases()),
                         [](const testing::TestParamInfo<CreaseCase>& info) { return info.param.name; });

// Deep small regions at tagged vertices (a dart, a semi-sharp chain's end, a crease meeting an
// edge-and-corner boundary): every vertex down to level 6 equals Far's.
TEST(SharpRefinementDeep, SmallRegionsAtTaggedVerticesEqualFarToLevelSix) {
    constexpr int deep = 6;
    for (const CreaseCase& c : crease_cases()) {
        if (c.name != "chain_ending_in_darts" && c.name != "semi_sharp_chain_1_3_2_and_corner_2" &&
            c.name != "creases_meeting_boundary_edge_and_corner")
            continue;
        const FarByIdentity far(c.input, deep);
        rgb::Mesh mesh(tagged_base(c.input));
        rgbtest::IdentityTracker ids(mesh, far.oracle());
        const glm::dvec3 a = c.input.positions[c.input.creases.front().a], b = c.input.positions[c.input.creases.front().b];
        for (const glm::dvec3& centre : {a, b, 0.5 * (a + b)}) {
            rgbtest::set_level(mesh, deep, rgb::Sphere{centre, 0.05 * glm::distance(a, b)});
            ASSERT_TRUE(rgbtest::invariants_hold(mesh)) << c.name;
            ASSERT_TRUE(agrees_with_far(mesh, ids, far, &worst_adaptive)) << c.name;
        }
        int finest = 0;
        for (rgb::FaceId f : mesh.faces()) finest = std::max(finest, mesh.level(f));
        EXPECT_EQ(finest, deep) << c.name;
    }
}

// Without tags, with only zero-sharpness tags, or with edge-and-corner boundaries on a mesh that has
// no boundary vertex with a single face, the base mesh has no sharp features: every value is the
// untagged one, bit for bit.
TEST(SharpFeaturesAbsent, ZeroTagsAndHarmlessOptionsChangeNothing) {
    const rgbtest::TestMesh fan = rgbtest::fan(6);
    rgb::SharpFeatures zero;
    zero.edges = {{0, 1, 0}};
    zero.corners = {{0, 0}};
    zero.boundary = rgb::BoundaryInterpolation::EdgeAndCorner;  // the fan's boundary vertices have two faces
    const auto base = std::make_shared<const rgb::BaseMesh>(fan.positions, fan.triangles, zero);
    EXPECT_FALSE(base->has_sharp_features());
    rgb::Mesh tagged(base), plain = rgbtest::make_rgb_mesh(fan);
    rgb::refine_uniform(tagged, 3);
    rgb::refine_uniform(plain, 3);
    EXPECT_TRUE(rgbtest::same_mesh(tagged, plain));
}

}  // namespace
}  // namespace osdoracle
