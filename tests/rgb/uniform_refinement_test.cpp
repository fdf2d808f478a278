// refine_uniform(k) through the RGB operators equals the independent uniform Loop oracle vertex by
// vertex (to 1e-12 of the bounding-box diagonal) and face by face (orientation included), k = 1..4.
#include <gtest/gtest.h>

#include "rgb/lod/refine.h"
#include "support/oracle_checks.h"
#include "support/uniform_loop_oracle.h"

namespace rgbtest {
namespace {

void expect_uniform_levels_match_oracle(const TestMesh& base, int max_level) {
    const UniformLoopOracle oracle(base.positions, base.triangles, max_level);
    rgb::Mesh mesh = make_rgb_mesh(base);
    IdentityTracker ids(mesh, oracle);
    const OracleView view{mesh, ids, oracle_tolerance(base)};
    for (int k = 1; k <= max_level; ++k) {
        SCOPED_TRACE(base.name + " refined uniformly to level " + std::to_string(k));
        rgb::refine_uniform(mesh, k);
        ASSERT_TRUE(invariants_hold(mesh));
        ASSERT_TRUE(equals_uniform(view, k));
    }
}

class UniformRefinement : public testing::TestWithParam<TestMesh> {};

TEST_P(UniformRefinement, EqualsOracleToLevel4) { expect_uniform_levels_match_oracle(GetParam(), 4); }

INSTANTIATE_TEST_SUITE_P(SmallMeshes, UniformRefinement, testing::ValuesIn(small_meshes()),
                         [](const testing::TestParamInfo<TestMesh>& info) { return info.param.name; });

TEST(UniformRefinementBunny, EqualsOracleToLevel3) { expect_uniform_levels_match_oracle(bunny(), 3); }

TEST(UniformLoopOracle, TetrahedronSizesFollowEulerPerLevel) {
    // F_{k+1} = 4 F_k and V_{k+1} = V_k + E_k with E_k = 3 F_k / 2 on a closed mesh (spec §9.4).
    const TestMesh tet = tetrahedron();
    const UniformLoopOracle oracle(tet.positions, tet.triangles, 4);
    std::size_t faces = 4, vertices = 4;
    for (int k = 0; k <= 4; ++k) {
        EXPECT_EQ(oracle.faces(k).size(), faces) << "level " << k;
        EXPECT_EQ(oracle.num_identities(k), vertices) << "level " << k;
        vertices += 3 * faces / 2;
        faces *= 4;
    }
}

}  // namespace
}  // namespace rgbtest
