// rgb::count_differing_positions, the loader's check of a file's v lines, against the one-vertex-at-
// a-time functions of loop_geometry.h: on a mesh with dead slots (refined, then partly coarsened),
// for displayed and limit positions, on all cores.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "io/mesh_file.h"
#include "io/obj_reader.h"
#include "obj_test_support.h"
#include "rgb/loop_geometry.h"
#include "rgb/position_check.h"
#include "rgb/requests.h"

namespace rgbio {
namespace {

rgb::Mesh mesh_with_dead_slots() {
    rgb::Mesh mesh = build_mesh(read_obj_text(test::kOctahedron, "octahedron.obj"));
    rgb::set_level(mesh, 7);  // 131,072 faces: the comparison runs in several blocks
    rgb::set_level(mesh, 2, rgb::Sphere{{1, 0, 0}, 0.6});
    return mesh;
}

TEST(PositionCheck, CountsExactlyTheVerticesThatDiffer) {
    const rgb::Mesh mesh = mesh_with_dead_slots();
    ASSERT_LT(mesh.num_vertices(), mesh.vertex_capacity());
    for (bool limit : {false, true}) {
        std::vector<glm::dvec3> expected;
        for (rgb::VertexId v : mesh.vertices()) expected.push_back(limit ? rgb::limit_position(mesh, v) : rgb::displayed_position(mesh, v));
        EXPECT_EQ(rgb::count_differing_positions(mesh, expected, limit), 0u);
        // One ulp off in three places, one of them the last vertex.
        for (std::size_t i : {std::size_t(0), expected.size() / 2, expected.size() - 1}) expected[i].x = std::nextafter(expected[i].x, 1e9);
        EXPECT_EQ(rgb::count_differing_positions(mesh, expected, limit), 3u);
    }
}

}  // namespace
}  // namespace rgbio
