// rgb::RestoredPositions, the positions restore_state gives for the loader's check of a file's v
// lines, against the one-vertex-at-a-time functions of loop_geometry.h on the mesh the state was
// captured from: one with dead slots (refined, then partly coarsened; restored vertex i is its i-th
// live slot), for displayed and limit positions, large enough for several parallel blocks.
#include <vector>

#include <gtest/gtest.h>

#include "io/mesh_file.h"
#include "io/obj_reader.h"
#include "obj_test_support.h"
#include "rgb/lod/requests.h"
#include "rgb/values/loop_geometry.h"
#include "rgb/values/restore_state.h"
#include "support/set_level.h"

namespace rgbio {
namespace {

rgb::Mesh mesh_with_dead_slots() {
    rgb::Mesh mesh = build_mesh(read_obj_text(test::kOctahedron, "octahedron.obj"));
    rgbtest::set_level(mesh, 7);  // 131,072 faces: the positions' pass runs in several blocks
    rgbtest::set_level(mesh, 2, rgb::Sphere{{1, 0, 0}, 0.6});
    return mesh;
}

TEST(RestoredPositions, AreTheMeshsOwnDisplayedAndLimitPositions) {
    const rgb::Mesh mesh = mesh_with_dead_slots();
    ASSERT_LT(mesh.num_vertices(), mesh.vertex_capacity());
    const rgb::MeshState state = rgb::capture_state(mesh);
    for (rgb::ChannelLevel level : {rgb::ChannelLevel::Displayed, rgb::ChannelLevel::Limit}) {
        rgb::RestoredPositions positions{level, {}};
        rgb::restore_state(state, {}, nullptr, &positions);
        ASSERT_EQ(positions.values.size(), mesh.num_vertices());
        std::size_t i = 0, above_own_level = 0;
        for (rgb::VertexId v : mesh.vertices()) {
            const bool limit = level == rgb::ChannelLevel::Limit;
            ASSERT_EQ(positions.values[i++], limit ? rgb::limit_position_uncached(mesh, v) : rgb::displayed_position(mesh, v))
                << "vertex " << v.idx << (limit ? " (limit)" : " (displayed)");
            above_own_level += rgb::display_level(mesh, v) > mesh.level(v);
        }
        EXPECT_GT(above_own_level, 1000u) << "closed forms over limits are compared, not only insertion positions";
    }
}

}  // namespace
}  // namespace rgbio
