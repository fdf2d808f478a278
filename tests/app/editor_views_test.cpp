// Views as in Blender: the numpad's front, right and top views (Ctrl for the opposite side) and the
// orthographic toggle, scripted through the editor's key input without X or GL; painting and picking
// work in a parallel view as in a perspective one.
#include <cmath>

#include <glm/geometric.hpp>

#include <gtest/gtest.h>

#include "app/editor.h"
#include "editor_fixture.h"
#include "rgb/mesh/mesh.h"

namespace app {
namespace {

using test::EditorFixture;
using test::kViewport;

class EditorViews : public EditorFixture {
protected:
    void SetUp() override { ASSERT_TRUE(editor.open(test::bunny_path())) << editor.message(); }
    // Where the eye is, seen from the target, as a unit vector.
    glm::dvec3 eye_side() const {
        const render::OrbitCamera& camera = editor.camera().camera();
        return glm::normalize(glm::dvec3(camera.eye()) - glm::dvec3(camera.target));
    }
};

TEST_F(EditorViews, NumpadKeysLookAlongTheAxesCtrlFromTheOppositeSide) {
    struct View {
        Key key;
        bool ctrl;
        glm::dvec3 eye_side;
    };
    const View views[] = {{Key::Keypad1, false, {0, 0, 1}}, {Key::Keypad1, true, {0, 0, -1}}, {Key::Keypad3, false, {1, 0, 0}},
                          {Key::Keypad3, true, {-1, 0, 0}}, {Key::Keypad7, false, {0, 1, 0}}, {Key::Keypad7, true, {0, -1, 0}}};
    const float distance = editor.camera().camera().distance;
    for (const View& view : views) {
        editor.key_pressed(view.key, {.ctrl = view.ctrl});
        EXPECT_LT(glm::distance(eye_side(), view.eye_side), 1e-6) << static_cast<int>(view.key) << (view.ctrl ? " with Ctrl" : "");
        EXPECT_FLOAT_EQ(editor.camera().camera().distance, distance) << "the same framing";
    }
    // The top view has a well-defined up: the screen's up is -Z (the front is at the bottom).
    editor.key_pressed(Key::Keypad7, {});
    const glm::mat4 view = editor.camera().camera().view();
    EXPECT_NEAR(view[2][1], -1.0f, 1e-5f);
}

TEST_F(EditorViews, Numpad5TogglesAParallelViewThatPicksAndPaints) {
    ASSERT_FALSE(editor.camera().camera().orthographic);
    editor.key_pressed(Key::Keypad5, {});
    ASSERT_TRUE(editor.camera().camera().orthographic);

    const Ray a = editor.camera().ray_through({100.0f, 120.0f}, kViewport);
    const Ray b = editor.camera().ray_through({700.0f, 500.0f}, kViewport);
    EXPECT_GT(glm::dot(a.direction, b.direction), 1.0 - 1e-9) << "parallel rays";
    EXPECT_DOUBLE_EQ(editor.camera().world_per_pixel(1.0, kViewport), editor.camera().world_per_pixel(5.0, kViewport));

    // A pixel is as large at the target as in the perspective view: the mesh stays the size it was.
    const double ortho_pixel = editor.camera().world_per_pixel(1.0, kViewport);
    editor.key_pressed(Key::Keypad5, {});
    EXPECT_FALSE(editor.camera().camera().orthographic);
    EXPECT_NEAR(editor.camera().world_per_pixel(editor.camera().camera().distance, kViewport), ortho_pixel, 1e-9 * ortho_pixel);

    editor.key_pressed(Key::Keypad5, {});
    editor.mouse_moved(glm::vec2(kViewport) * 0.5f);
    ASSERT_TRUE(editor.cursor_hit().has_value()) << "the middle of the framed bunny";
    const std::size_t before = editor.document().mesh().num_faces();
    stroke({0.4f * kViewport.x, 0.5f * kViewport.y}, {0.6f * kViewport.x, 0.5f * kViewport.y}, 20);
    EXPECT_GT(editor.document().mesh().num_faces(), before);

    // Zoomed in until the eye is inside the bunny: the parallel view still sees (and picks) what lies
    // behind the eye.
    for (int i = 0; i < 40; ++i) editor.scrolled(1.0f);
    editor.mouse_moved(glm::vec2(kViewport) * 0.5f);
    EXPECT_TRUE(editor.cursor_hit().has_value());
}

// View-dependent LOD in a parallel view: the detail follows what the view shows, the front and not
// the back.
TEST_F(EditorViews, ViewDependentDetailFollowsAParallelView) {
    editor.key_pressed(Key::Keypad1, {});
    editor.key_pressed(Key::Keypad5, {});
    const std::size_t before = editor.document().mesh().num_faces();
    editor.start_view_lod();
    editor.finish_work();
    editor.freeze_view_lod();
    const rgb::Mesh& mesh = editor.document().mesh();
    ASSERT_GT(mesh.num_faces(), before);
    std::size_t front = 0, back = 0;
    for (rgb::FaceId f : mesh.faces()) {
        if (mesh.level(f) == 0) continue;
        const auto corner = [&](int i) { return mesh.insertion_position(mesh.from_vertex(rgb::Mesh::halfedge(f, i))); };
        const glm::dvec3 normal = glm::cross(corner(1) - corner(0), corner(2) - corner(0));
        (normal.z > 0.0 ? front : back) += 1;
    }
    EXPECT_GT(front, 2 * back) << "refined faces facing the front view (+Z) against the others";
}

}  // namespace
}  // namespace app
