// Test vectors of spec §9.4 on the tetrahedron of §9.3, derived here from the Loop rules rather than
// copied: every base vertex has valence 3 and the base vertices sum to zero, so
//   level 1:  v_i -> (1 - alpha_3) v_i + beta_3 (sum of the others) = v_i / 4,
//             M(v_i, v_j) -> 3/8 (v_i + v_j) + 1/8 (v_k + v_l) = (v_i + v_j) / 4,
//   limits:   p_inf(v_i) = (1 - c_3) v_i + c_3 / 3 (-v_i) = v_i / 5 (c_3 = 3/5), and a level-1 vertex
//             has p_inf = 1/2 p^1 + 1/12 (sum of its level-1 ring),
//   later:    p^{l+j} = gamma^j p^l + (1 - gamma^j) p_inf, gamma_3 = 1/16, gamma_6 = 1/4.
// The level-3 values of level-2 vertices are checked against the oracle and against the six digits
// the spec prints.
#include <cmath>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "rgb/lod/refine.h"
#include "rgb/values/loop_geometry.h"
#include "support/identity_tracker.h"
#include "support/test_meshes.h"

namespace rgbtest {
namespace {

constexpr double kExact = 1e-15;

class TetrahedronVectors : public testing::Test {
protected:
    TestMesh tet = tetrahedron();
    UniformLoopOracle oracle{tet.positions, tet.triangles, 3};
    rgb::Mesh mesh = make_rgb_mesh(tet);
    IdentityTracker ids{mesh, oracle};
    void SetUp() override { rgb::refine_uniform(mesh, 3); }

    glm::dvec3 v(int i) const { return tet.positions[i]; }
    rgb::VertexId midpoint(rgb::VertexId a, rgb::VertexId b) const {
        return ids.vertex_of(*oracle.midpoint(ids.identity(a), ids.identity(b)));
    }
    // Level-1 positions from the derivation above.
    glm::dvec3 base_at_1(int i) const { return v(i) / 4.0; }
    glm::dvec3 mid_at_1(int i, int j) const { return (v(i) + v(j)) / 4.0; }
};

void expect_near(const glm::dvec3& got, const glm::dvec3& want, double tolerance, const std::string& what) {
    EXPECT_LE(glm::distance(got, want), tolerance)
        << what << ": (" << got.x << ", " << got.y << ", " << got.z << ") vs (" << want.x << ", " << want.y << ", " << want.z << ")";
}

TEST_F(TetrahedronVectors, BaseVertexFollowsGammaOneSixteenth) {
    const rgb::VertexId v0(0);
    expect_near(rgb::limit_position(mesh, v0), v(0) / 5.0, kExact, "p_inf(v0)");
    for (int j = 0; j <= 3; ++j) {
        const double c = 0.2 + 0.8 / std::pow(16.0, j);
        expect_near(rgb::control_point(mesh, v0, j), glm::dvec3(c), kExact, "p^" + std::to_string(j) + "(v0)");
    }
    expect_near(rgb::displayed_position(mesh, v0), glm::dvec3(0.2 + 0.8 / 4096.0), kExact, "displayed v0");
}

TEST_F(TetrahedronVectors, FirstMidpointFollowsGammaOneQuarter) {
    const rgb::VertexId m01 = midpoint(rgb::VertexId(0), rgb::VertexId(1));
    ASSERT_TRUE(m01.valid());
    const glm::dvec3 p1 = mid_at_1(0, 1);
    expect_near(p1, {0.5, 0, 0}, 0.0, "derivation of M(v0,v1) at level 1");
    expect_near(mesh.insertion_position(m01), p1, kExact, "M(v0,v1) at level 1");
    // Its level-1 ring: v0, v1 and the four midpoints of the other edges at v0 or v1.
    const glm::dvec3 ring = base_at_1(0) + base_at_1(1) + mid_at_1(0, 2) + mid_at_1(0, 3) + mid_at_1(1, 2) + mid_at_1(1, 3);
    const glm::dvec3 limit = 0.5 * p1 + ring / 12.0;
    expect_near(rgb::limit_position(mesh, m01), limit, kExact, "p_inf(M(v0,v1))");
    for (int j = 0; j <= 2; ++j) {
        const double g = std::pow(0.25, j);
        expect_near(rgb::control_point(mesh, m01, 1 + j), g * p1 + (1 - g) * limit, kExact, "p^" + std::to_string(1 + j));
    }
    expect_near(rgb::control_point(mesh, m01, 2), {0.34375, 0, 0}, kExact, "spec value at level 2");
}

TEST_F(TetrahedronVectors, LevelTwoMidpointsFromTheirLevelOneStencils) {
    const rgb::VertexId v0(0);
    const rgb::VertexId m01 = midpoint(v0, rgb::VertexId(1)), m02 = midpoint(v0, rgb::VertexId(2));
    // M(v0, M01): the level-1 faces at edge v0-M01 are the corners at v0 of faces 012 and 031, whose
    // third vertices are M02 and M03.
    const rgb::VertexId a = midpoint(v0, m01);
    const glm::dvec3 pa = 3.0 / 8.0 * (base_at_1(0) + mid_at_1(0, 1)) + 1.0 / 8.0 * (mid_at_1(0, 2) + mid_at_1(0, 3));
    expect_near(mesh.insertion_position(a), pa, kExact, "M(v0,M01) at level 2");
    expect_near(pa, {0.28125, 0.15625, 0.15625}, kExact, "spec value of M(v0,M01)");
    // M(M01, M02): the corner (v0, M01, M02) and the centre (M01, M12, M02) of face 012.
    const rgb::VertexId b = midpoint(m01, m02);
    const glm::dvec3 pb = 3.0 / 8.0 * (mid_at_1(0, 1) + mid_at_1(0, 2)) + 1.0 / 8.0 * (base_at_1(0) + mid_at_1(1, 2));
    expect_near(mesh.insertion_position(b), pb, kExact, "M(M01,M02) at level 2");
    expect_near(pb, {0.21875, 0.21875, -0.03125}, kExact, "spec value of M(M01,M02)");
    // Level 3: the oracle exactly, and the spec's printed digits.
    expect_near(rgb::displayed_position(mesh, a), oracle.position(3, ids.identity(a)), kExact, "M(v0,M01) at level 3");
    expect_near(rgb::displayed_position(mesh, a), {0.256836, 0.149414, 0.149414}, 5e-7, "spec digits");
    expect_near(rgb::displayed_position(mesh, b), oracle.position(3, ids.identity(b)), kExact, "M(M01,M02) at level 3");
    expect_near(rgb::displayed_position(mesh, b), {0.201172, 0.201172, -0.027344}, 5e-7, "spec digits");
}

TEST(TetrahedronSizes, VerticesAndFacesPerUniformLevel) {
    // F_{k+1} = 4 F_k, V_{k+1} = V_k + 3 F_k / 2 (one new vertex per edge): 4, 10, 34, 130, 514.
    rgb::Mesh mesh = make_rgb_mesh(tetrahedron());
    std::size_t faces = 4, vertices = 4;
    for (int k = 1; k <= 4; ++k) {
        vertices += 3 * faces / 2;
        faces *= 4;
        rgb::refine_uniform(mesh, k);
        EXPECT_EQ(mesh.num_faces(), faces) << "level " << k;
        EXPECT_EQ(mesh.num_vertices(), vertices) << "level " << k;
    }
    EXPECT_EQ(mesh.num_vertices(), 514u);
}

}  // namespace
}  // namespace rgbtest
