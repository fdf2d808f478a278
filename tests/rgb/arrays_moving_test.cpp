// A mesh tells its observers before it moves its face and vertex arrays or its table of limits (for
// MeshRoomPrefault, whose thread must stop reading them first: prefault_test.cpp).
#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "rgb/lod/refine.h"
#include "rgb/mesh/mesh.h"
#include "rgb/mesh/observer.h"
#include "rgb/values/loop_geometry.h"
#include "support/test_meshes.h"

namespace rgbtest {
namespace {

// At each announcement, what the arrays and the table are at that moment (before they move).
class MoveRecorder : public rgb::MeshObserver {
public:
    explicit MoveRecorder(rgb::Mesh& mesh) : mesh_(mesh) { mesh_.add_observer(this); }
    ~MoveRecorder() override { mesh_.remove_observer(this); }
    MoveRecorder(const MoveRecorder&) = delete;
    MoveRecorder& operator=(const MoveRecorder&) = delete;

    void arrays_moving(const rgb::Mesh& m) override {
        face_slots.push_back(m.reserved_face_slots());
        tables.push_back(m.limit_table().data());
    }

    std::vector<std::size_t> face_slots;
    std::vector<const std::byte*> tables;

private:
    rgb::Mesh& mesh_;
};

TEST(ArraysMoving, AnnouncedBeforeTheFaceArraysGrowAndOnlyThen) {
    rgb::Mesh mesh = make_rgb_mesh(octahedron());
    MoveRecorder recorder(mesh);
    const std::size_t before = mesh.reserved_face_slots();
    mesh.reserve(before * 4, mesh.vertex_capacity() * 4);  // room for level 1
    const std::size_t reserved = mesh.reserved_face_slots();
    ASSERT_GT(reserved, before);
    ASSERT_FALSE(recorder.face_slots.empty());
    EXPECT_EQ(recorder.face_slots.front(), before);  // heard while the arrays were the old ones
    const std::size_t announced = recorder.face_slots.size();
    rgb::refine_uniform(mesh, 1);  // 32 faces, and no limits cached: within the room
    EXPECT_EQ(mesh.reserved_face_slots(), reserved);
    EXPECT_EQ(recorder.face_slots.size(), announced);
    rgb::refine_uniform(mesh, 3);  // past it
    EXPECT_GT(mesh.reserved_face_slots(), reserved);
    EXPECT_NE(std::find(recorder.face_slots.begin() + announced, recorder.face_slots.end(), reserved), recorder.face_slots.end());
}

TEST(ArraysMoving, AnnouncedBeforeTheTableOfLimitsMoves) {
    rgb::Mesh mesh = make_rgb_mesh(icosahedron());
    rgb::refine_uniform(mesh, 3);  // caches the limits of levels 0 and 1
    MoveRecorder recorder(mesh);
    const std::byte* table = mesh.limit_table().data();
    std::size_t moves = 0;
    for (rgb::VertexId v : mesh.vertices()) {
        rgb::limit_position(mesh, v);  // caches it: the table grows now and then
        if (mesh.limit_table().data() != table) {
            ++moves;
            ASSERT_EQ(recorder.tables.size(), moves);
            EXPECT_EQ(recorder.tables.back(), table);
            table = mesh.limit_table().data();
        }
    }
    EXPECT_GE(moves, 2u);
    EXPECT_EQ(recorder.tables.size(), moves);
    mesh.reserve_limits(mesh.num_vertices() / 2);  // fewer than are cached: nothing moves
    EXPECT_EQ(mesh.limit_table().data(), table);
    EXPECT_EQ(recorder.tables.size(), moves);
    mesh.reserve_limits(mesh.num_vertices() * 4);
    EXPECT_NE(mesh.limit_table().data(), table);
    ASSERT_EQ(recorder.tables.size(), moves + 1);
    EXPECT_EQ(recorder.tables.back(), table);
}

TEST(ArraysMoving, AnnouncedToBothMeshesOfAnAssignment) {
    rgb::Mesh a = make_rgb_mesh(octahedron()), b = make_rgb_mesh(icosahedron());
    MoveRecorder heard_by_a(a);
    a = b;  // a's arrays are freed
    EXPECT_EQ(heard_by_a.tables.size(), 1u);
    rgb::Mesh c = make_rgb_mesh(tetrahedron());
    MoveRecorder heard_by_c(c);
    c = std::move(a);  // c's arrays are freed, a's handed over
    EXPECT_EQ(heard_by_c.tables.size(), 1u);
    EXPECT_EQ(heard_by_a.tables.size(), 2u);
}

}  // namespace
}  // namespace rgbtest
