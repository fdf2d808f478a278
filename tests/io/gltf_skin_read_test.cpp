// A glTF skin read (io/formats/gltf_skin.h), from files written byte by byte: each vertex's
// JOINTS_0/WEIGHTS_0 as influences (normalized integer weights scaled, a joint named twice summed,
// heaviest first, renormalised), kept through welding; the skeleton with its joint nodes, their
// ancestors, names and transforms; the inverse bind matrices, times the inverse of the mesh node's
// transform, which the reader applies to the positions and glTF's skinning ignores. A skin that not
// every mesh has is dropped in the one warning; bad weights and joints are refused with a reason.
// Written skins and their weights through subdivision: tests/cli/gltf_skin_check.py.
#include <map>

#include <gtest/gtest.h>

#include "foreign_fixtures.h"
#include "io/mesh_reader.h"
#include "io/obj/obj_error.h"
#include "obj_test_support.h"
#include "scratch_folder.h"

namespace rgbio {
namespace {

using test::GlbBuffer;

// A square as two triangles of their own three vertices each (a seam splits every vertex), skinned
// to three joints; `weights` are normalized unsigned bytes, four per vertex.
GlbBuffer skinned_square(const std::vector<std::uint8_t>& weights, const std::vector<std::uint16_t>& joints) {
    GlbBuffer buffer;
    buffer.add_floats({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0}, "VEC3", 3);
    buffer.add(joints, "VEC4", 4, 5123);
    buffer.add(weights, "VEC4", 4, 5121, true);
    // Inverse bind matrices: translations by -1, -2, -3 along x.
    std::vector<float> matrices;
    for (float x : {-1.f, -2.f, -3.f})
        for (float m : {1.f, 0.f, 0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 0.f, 1.f, 0.f, x, 0.f, 0.f, 1.f}) matrices.push_back(m);
    buffer.add_floats(matrices, "MAT4", 16);
    return buffer;
}

// The scene: the mesh node (moved by `mesh_transform`), a rig node above joints "a" and "b" (a's
// child "b"), a lone joint "c", and a node no skin uses; with `unskinned`, a node 6 that places the
// same positions as mesh 1, without a skin.
std::string skinned_scene(const std::string& mesh_transform, const std::string& joints = "2,3,4", bool unskinned = false) {
    return std::string(R"("scene":0,"scenes":[{"nodes":[0,1,4,5)") + (unskinned ? ",6" : "") + R"(]}],"nodes":[{"mesh":0,"skin":0)" +
           mesh_transform +
           R"(},{"name":"rig","children":[2]},{"name":"a","translation":[1,0,0],"children":[3]},)"
           R"({"name":"b","rotation":[0,0,1,0]},{"name":"c","matrix":[1,0,0,0,0,1,0,0,0,0,1,0,3,0,0,1]},{"name":"other"})" +
           (unskinned ? R"(,{"mesh":1,"translation":[5,0,0]})" : "") +
           R"(],"meshes":[{"primitives":[{"attributes":{"POSITION":0,"JOINTS_0":1,"WEIGHTS_0":2}}]},{"primitives":[{"attributes":{"POSITION":0}}]}],)"
           R"("skins":[{"name":"rigging","joints":[)" + joints + R"(],"skeleton":1,"inverseBindMatrices":3}])";
}

// Per corner: (joints, weights); the seam's copies of a vertex agree.
const std::vector<std::uint16_t> kJoints = {0, 1, 0, 0, 1, 1, 2, 0, 2, 0, 0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 2, 0, 0};
const std::vector<std::uint8_t> kWeights = {128, 64, 0, 0, 10, 20, 30, 0, 255, 0, 0, 0, 128, 64, 0, 0, 255, 0, 0, 0, 51, 51, 0, 0};

class GltfSkinRead : public test::ScratchFolder {};

TEST_F(GltfSkinRead, InfluencesAndSkeletonAreRead) {
    write("skinned.glb", skinned_square(kWeights, kJoints).file(skinned_scene("")));
    const LoadedMesh mesh = read_mesh_file(path("skinned.glb"));
    ASSERT_EQ(mesh.positions.size(), 4u);
    EXPECT_TRUE(mesh.warnings.empty()) << mesh.warnings.front();
    ASSERT_TRUE(mesh.skeleton);
    ASSERT_EQ(mesh.influences.size(), 4u);
    // By position: (0,0,0) 128/255 on 0, 64/255 on 1 -> 2/3, 1/3; (1,0,0) joint 1 twice (10 + 20) and
    // 2 (30) -> 1/2 each, the lower joint first; (1,1,0) all on 2; (0,1,0) 51 on 1 and 2 -> 1/2 each.
    const std::map<std::array<double, 3>, JointInfluences> expected = {
        {{0, 0, 0}, {{0, 1, 0, 0}, {128.0 / 192.0, 64.0 / 192.0, 0, 0}}},
        {{1, 0, 0}, {{1, 2, 0, 0}, {0.5, 0.5, 0, 0}}},
        {{1, 1, 0}, {{2, 0, 0, 0}, {1, 0, 0, 0}}},
        {{0, 1, 0}, {{1, 2, 0, 0}, {0.5, 0.5, 0, 0}}},
    };
    for (std::size_t v = 0; v < 4; ++v) {
        const glm::dvec3& p = mesh.positions[v];
        const JointInfluences& want = expected.at({p.x, p.y, p.z});
        EXPECT_EQ(mesh.influences[v].joints, want.joints) << v;
        for (std::size_t k = 0; k < kMaxInfluences; ++k) EXPECT_NEAR(mesh.influences[v].weights[k], want.weights[k], 1e-15) << v << k;
    }
    const Skeleton& s = *mesh.skeleton;
    EXPECT_EQ(s.name, "rigging");
    ASSERT_EQ(s.nodes.size(), 4u);  // rig, a, b, c: the joints and their ancestors, in file order
    EXPECT_EQ(s.nodes[0].name, "rig");
    EXPECT_EQ(s.nodes[0].children, std::vector<std::uint32_t>{1});
    EXPECT_EQ(s.nodes[1].translation, (std::vector<double>{1, 0, 0}));
    EXPECT_EQ(s.nodes[1].children, std::vector<std::uint32_t>{2});
    EXPECT_EQ(s.nodes[2].rotation, (std::vector<double>{0, 0, 1, 0}));
    EXPECT_EQ(s.nodes[3].matrix.size(), 16u);
    EXPECT_EQ(s.joints, (std::vector<std::uint32_t>{1, 2, 3}));
    EXPECT_EQ(s.root, 0);
    ASSERT_EQ(s.inverse_bind_matrices.size(), 3u);
    EXPECT_EQ(s.inverse_bind_matrices[2][3], glm::dvec4(-3, 0, 0, 1));
}

TEST_F(GltfSkinRead, MeshNodeTransformMovesTheInverseBindMatrices) {
    // The positions are moved by +10 in y; the skinned pose J * IBM' * p' must stay J * IBM * p.
    write("moved.glb", skinned_square(kWeights, kJoints).file(skinned_scene(R"(,"translation":[0,10,0])")));
    const LoadedMesh mesh = read_mesh_file(path("moved.glb"));
    ASSERT_TRUE(mesh.skeleton);
    for (const glm::dvec3& p : mesh.positions) EXPECT_GE(p.y, 10.0);
    EXPECT_EQ(mesh.skeleton->inverse_bind_matrices[0][3], glm::dvec4(-1, -10, 0, 1));
}

TEST_F(GltfSkinRead, WeldedCornersWithOtherWeightsKeepTheFirst) {
    std::vector<std::uint8_t> weights = kWeights;
    weights[12] = 255;  // corner 3 (at (0,0,0), like corner 0): 255 on 0, 64 on 1
    write("conflict.glb", skinned_square(weights, kJoints).file(skinned_scene("")));
    const LoadedMesh mesh = read_mesh_file(path("conflict.glb"));
    EXPECT_TRUE(test::has_warning(mesh.warnings, "1 corners carry other joint weights than the first corner"));
    for (std::size_t v = 0; v < 4; ++v)
        if (mesh.positions[v] == glm::dvec3(0.0)) {
            EXPECT_NEAR(mesh.influences[v].weights[0], 2.0 / 3.0, 1e-15);
        }
}

TEST_F(GltfSkinRead, SkinThatNotEveryMeshHasIsDropped) {
    write("mixed.glb", skinned_square(kWeights, kJoints).file(skinned_scene("", "2,3,4", true)));
    const LoadedMesh mesh = read_mesh_file(path("mixed.glb"));
    EXPECT_FALSE(mesh.skeleton);
    EXPECT_TRUE(mesh.influences.empty());
    ASSERT_EQ(mesh.warnings.size(), 1u);
    EXPECT_TRUE(test::has_warning(mesh.warnings, "a skin is kept only when every mesh is skinned by the same one")) << mesh.warnings[0];
    EXPECT_TRUE(test::has_warning(mesh.warnings, "1 skins")) << mesh.warnings[0];
}

TEST_F(GltfSkinRead, BadJointsAreRefused) {
    const auto reason = [&](const std::vector<std::uint16_t>& joints, const std::string& scene) {
        write("bad.glb", skinned_square(kWeights, joints).file(scene));
        try {
            read_mesh_file(path("bad.glb"));
        } catch (const ObjError& e) {
            EXPECT_EQ(e.problem(), ObjProblem::Malformed);
            return e.reason();
        }
        return std::string("read");
    };
    std::vector<std::uint16_t> beyond = kJoints;
    beyond[1] = 3;
    EXPECT_EQ(reason(beyond, skinned_scene("")), "vertex 1 of a skinned primitive names joint 3 of a skin with 3");
    EXPECT_EQ(reason(kJoints, skinned_scene("", "2,3,9")), "skin 0 names joint node 9, which does not exist");
}

}  // namespace
}  // namespace rgbio
