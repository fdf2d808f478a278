// The editor's keys, wheel and navigation drags on the default mesh, checked against what they must
// do to the view and the brush (docs/editor.md).
#include <optional>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include "editor_fixture.h"
#include "rgb/mesh/mesh.h"
#include "rgb/values/loop_geometry.h"
#include "support/same_mesh.h"

namespace app {
namespace {

using test::kViewport;

class EditorInput : public test::EditorFixture {
protected:
    void SetUp() override { ASSERT_TRUE(editor.open(test::asset_path("default.obj"))) << editor.message(); }

    // Where `p` lands in the viewport, in pixels (origin top left, y down).
    glm::dvec2 pixel_of(const glm::dvec3& p) const {
        const render::OrbitCamera& camera = editor.camera().camera();
        const glm::vec4 clip = camera.view_projection(float(kViewport.x) / float(kViewport.y)) * glm::vec4(glm::vec3(p), 1.0f);
        const glm::dvec2 ndc(clip.x / clip.w, clip.y / clip.w);
        return {(ndc.x + 1.0) * 0.5 * kViewport.x, (1.0 - ndc.y) * 0.5 * kViewport.y};
    }
    // Whether every vertex of the mesh lands inside the viewport.
    bool whole_mesh_in_view() const {
        const rgb::Mesh& mesh = editor.document().mesh();
        for (rgb::VertexId v : mesh.vertices()) {
            const glm::dvec2 px = pixel_of(rgb::displayed_position(mesh, v));
            if (px.x < 0 || px.y < 0 || px.x > kViewport.x || px.y > kViewport.y) return false;
        }
        return true;
    }
    const render::OrbitCamera& camera() const { return editor.camera().camera(); }
    const glm::vec2 centre{0.5f * kViewport.x, 0.5f * kViewport.y};
};

// The wheel zooms towards the point under the cursor (EditorScript.ZoomKeepsThePointUnderTheCursor
// checks that it stays there); the same steps back out give back the framed view.
TEST_F(EditorInput, WheelZoomsInTowardsTheCursorAndBackOut) {
    editor.mouse_moved(centre);
    const render::OrbitCamera before = camera();
    editor.scrolled(3.0f);
    EXPECT_LT(camera().distance, before.distance);
    EXPECT_FALSE(whole_mesh_in_view()) << "three steps in, the framed mesh overflows the view";
    editor.scrolled(-3.0f);
    EXPECT_NEAR(camera().distance, before.distance, 1e-5f * before.distance);
    EXPECT_LT(glm::distance(camera().target, before.target), 1e-4f * before.distance);
    EXPECT_TRUE(whole_mesh_in_view());
}

// Panning drags the scene with the mouse: the point that was at the target (the view's centre)
// ends up under the pointer's displacement, for the middle button and for Alt+Shift+left alike.
TEST_F(EditorInput, PanMovesTheSceneWithThePointer) {
    const glm::dvec3 target(camera().target);
    ASSERT_NEAR(pixel_of(target).x, centre.x, 0.5);
    drag(MouseButton::Middle, centre, {50.0f, 30.0f});
    EXPECT_NEAR(pixel_of(target).x, centre.x + 50.0, 0.5);
    EXPECT_NEAR(pixel_of(target).y, centre.y + 30.0, 0.5);
    drag(MouseButton::Left, centre, {-20.0f, 10.0f}, {.shift = true, .alt = true});
    EXPECT_NEAR(pixel_of(target).x, centre.x + 30.0, 0.5);
    EXPECT_NEAR(pixel_of(target).y, centre.y + 40.0, 0.5);
    EXPECT_FALSE(editor.document().history().can_undo()) << "navigation never paints";
}

// Home frames the mesh again from the current angles (as Blender; F sizes the brush); R also
// restores the default angles.
TEST_F(EditorInput, HomeFramesTheMeshKeepingTheAnglesAndRResetsThem) {
    const render::OrbitCamera opened = camera();
    drag(MouseButton::Right, centre, {40.0f, -25.0f});  // orbit
    drag(MouseButton::Middle, centre, {200.0f, 0.0f});  // pan most of the mesh out of view
    editor.scrolled(4.0f);
    const render::OrbitCamera moved = camera();
    ASSERT_NE(moved.azimuth_deg, opened.azimuth_deg);
    ASSERT_FALSE(whole_mesh_in_view());

    editor.key_pressed(Key::Home, {});
    EXPECT_EQ(camera().azimuth_deg, moved.azimuth_deg);
    EXPECT_EQ(camera().elevation_deg, moved.elevation_deg);
    EXPECT_EQ(camera().target, opened.target);
    EXPECT_FLOAT_EQ(camera().distance, opened.distance) << "framing depends on the mesh, not on the angles";
    EXPECT_TRUE(whole_mesh_in_view());

    editor.key_pressed(Key::R, {});
    EXPECT_EQ(camera().azimuth_deg, opened.azimuth_deg);
    EXPECT_EQ(camera().elevation_deg, opened.elevation_deg);
    EXPECT_EQ(camera().target, opened.target);
    EXPECT_FLOAT_EQ(camera().distance, opened.distance);
}

TEST_F(EditorInput, BracketsScaleTheBrushByTenPercentInItsUnit) {
    editor.brush().radius_px = 40.0f;
    editor.key_pressed(Key::RightBracket, {});
    EXPECT_FLOAT_EQ(editor.brush().radius_px, 44.0f);
    editor.key_pressed(Key::LeftBracket, {});
    editor.key_pressed(Key::LeftBracket, {});
    EXPECT_FLOAT_EQ(editor.brush().radius_px, 40.0f / 1.1f);
    editor.brush().unit = RadiusUnit::World;
    editor.brush().radius_world = 0.5f;
    editor.key_pressed(Key::RightBracket, {});
    EXPECT_FLOAT_EQ(editor.brush().radius_world, 0.55f);
    EXPECT_FLOAT_EQ(editor.brush().radius_px, 40.0f / 1.1f) << "only the radius in use changes";
}

TEST_F(EditorInput, DigitsPickTheBrushMode) {
    editor.key_pressed(Key::Digit2, {});
    EXPECT_EQ(editor.brush().mode, BrushMode::Coarsen);
    editor.key_pressed(Key::Digit3, {});
    EXPECT_EQ(editor.brush().mode, BrushMode::Set);
    editor.key_pressed(Key::Digit1, {});
    EXPECT_EQ(editor.brush().mode, BrushMode::Refine);
    editor.set_modifiers({.shift = true});
    EXPECT_EQ(editor.active_mode(), BrushMode::Coarsen) << "Shift inverts what 1 picked";
}

// In world units the brush covers the same part of the surface at any zoom; in screen pixels it
// covers less of it the closer the camera is. Each dab is measured by the mesh it makes, then undone.
TEST_F(EditorInput, WorldRadiusIgnoresTheZoomAndPixelRadiusFollowsIt) {
    editor.brush().mode = BrushMode::Refine;
    editor.brush().target_level = 2;
    editor.brush().falloff = 0.0f;
    const std::size_t base_faces = editor.document().mesh().num_faces();
    const auto dab_at_centre = [&] {
        stroke(centre, centre, 0);
        rgb::Mesh painted = editor.document().mesh();
        EXPECT_TRUE(editor.undo());
        return painted;
    };
    editor.mouse_moved(centre);
    const std::optional<SurfaceHit> hit = editor.cursor_hit();
    ASSERT_TRUE(hit.has_value()) << "the framed mesh covers the centre of the view";

    editor.brush().unit = RadiusUnit::World;
    editor.brush().radius_world = 0.4f;
    EXPECT_EQ(editor.brush_world_radius(hit->point), 0.4f);
    const rgb::Mesh world_far = dab_at_centre();
    editor.brush().unit = RadiusUnit::ScreenPixels;
    editor.brush().radius_px = 100.0f;
    const double pixel_far_radius = editor.brush_world_radius(hit->point);
    const rgb::Mesh pixel_far = dab_at_centre();

    // A pixel spans a world length proportional to the depth it is seen at.
    const double depth_far = editor.camera().depth_of(hit->point);
    editor.scrolled(4.0f);
    const double depth_near = editor.camera().depth_of(hit->point);
    ASSERT_LT(depth_near, depth_far);
    EXPECT_NEAR(editor.brush_world_radius(hit->point), pixel_far_radius * depth_near / depth_far, 1e-6 * pixel_far_radius);
    EXPECT_LT(dab_at_centre().num_faces(), pixel_far.num_faces());
    editor.brush().unit = RadiusUnit::World;
    EXPECT_TRUE(rgbtest::same_mesh(dab_at_centre(), world_far));
    EXPECT_GT(world_far.num_faces(), base_faces);
    EXPECT_GT(pixel_far.num_faces(), base_faces);
    EXPECT_FALSE(editor.document().history().can_undo());
}

}  // namespace
}  // namespace app
