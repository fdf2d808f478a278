// Far without tags against the independent uniform Loop oracle of tests/rgb (spec §4.1, its own
// adjacency and rules): the same vertices, matched by identity through Far's vertex origins, at the
// same positions, and the same faces, levels 0-4, on closed and open meshes of valences 2 to 10.
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "far_by_identity.h"
#include "osd_far.h"
#include "support/test_meshes.h"
#include "test_mesh_input.h"
#include "support/uniform_loop_oracle.h"

namespace osdoracle {
namespace {

constexpr int levels = 4;

class UniformAgreement : public testing::TestWithParam<rgbtest::TestMesh> {};

TEST_P(UniformAgreement, FarEqualsTheIndependentOracleVertexByVertex) {
    const rgbtest::TestMesh& mesh = GetParam();
    const FarRefinement far = refine_uniform(far_input(mesh), levels);
    const rgbtest::UniformLoopOracle oracle(mesh.positions, mesh.triangles, levels);
    const double tolerance = 1e-12 * rgbtest::bounding_box_diagonal(mesh.positions);

    const std::vector<std::vector<rgbtest::Identity>> identities = identities_of(far, oracle);
    for (int k = 0; k <= levels; ++k) {
        const FarLevel& level = far.levels[k];
        const std::vector<rgbtest::Identity>& identity = identities[k];
        ASSERT_EQ(level.positions.size(), oracle.num_identities(k)) << "level " << k;
        double worst = 0.0;
        for (std::size_t v = 0; v < level.positions.size(); ++v)
            worst = std::max(worst, glm::distance(level.positions[v], oracle.position(k, identity[v])));
        EXPECT_LE(worst, tolerance) << "level " << k;
        ASSERT_EQ(level.triangles.size(), oracle.faces(k).size()) << "level " << k;
        for (const auto& t : level.triangles)
            EXPECT_TRUE(oracle.has_face(k, {identity[t[0]], identity[t[1]], identity[t[2]]})) << "level " << k;
    }
}

INSTANTIATE_TEST_SUITE_P(SmallMeshes, UniformAgreement, testing::ValuesIn(rgbtest::small_meshes()),
                         [](const testing::TestParamInfo<rgbtest::TestMesh>& info) { return info.param.name; });

}  // namespace
}  // namespace osdoracle
