// Stroke comfort, through the editor's input calls: the stroke spacing (dabs per brush radius), the
// lazy mouse, and F / Ctrl+F setting the brush's radius and target by dragging (docs/editor.md).
#include <cmath>

#include <gtest/gtest.h>

#include "editor_fixture.h"

namespace app {
namespace {

using test::kViewport;

class StrokeComfort : public test::EditorFixture {
protected:
    void SetUp() override {
        ASSERT_TRUE(editor.open(test::asset_path("default.obj"))) << editor.message();
        editor.brush().radius_px = 20.0f;
        editor.brush().target_level = 1;
    }
    // The dabs a left drag along the middle row from `x0` to `x1` places, in mouse samples 2 px apart.
    std::size_t dabs_of_stroke(float x0, float x1) {
        const std::size_t before = editor.timing().dabs;
        editor.mouse_moved({x0, y});
        editor.mouse_pressed(MouseButton::Left, {});
        for (float x = x0 + 2.0f; x <= x1; x += 2.0f) editor.mouse_moved({x, y});
        editor.mouse_released(MouseButton::Left);
        editor.finish_work();
        return editor.timing().dabs - before;
    }
    const float y = 0.5f * kViewport.y;
    const glm::vec2 centre{0.5f * kViewport.x, 0.5f * kViewport.y};
};

// A dab on the press, then one every radius / (dabs per radius) pixels along the stroke: 102 px with
// a 20 px radius are 20 steps of 5 px at 4 per radius, 5 steps of 20 px at 1 per radius.
TEST_F(StrokeComfort, SpacingIsDabsPerBrushRadius) {
    editor.brush().dabs_per_radius = 4.0f;
    EXPECT_EQ(dabs_of_stroke(349.0f, 451.0f), 1u + 20u);
    editor.brush().dabs_per_radius = 1.0f;
    EXPECT_EQ(dabs_of_stroke(349.0f, 451.0f), 1u + 5u);
    editor.brush().dabs_per_radius = 10.0f;  // 2 px apart
    EXPECT_EQ(dabs_of_stroke(349.0f, 451.0f), 1u + 51u);
}

// The brush trails the pointer on a string of lazy_px: the pointer moving within it moves nothing;
// beyond it, the brush follows at the string's length behind, and dabs only along its own path.
TEST_F(StrokeComfort, TheLazyMouseTrailsThePointerOnItsString) {
    editor.brush().dabs_per_radius = 4.0f;  // a dab every 5 px
    editor.brush().lazy_px = 32.0f;
    const std::size_t before = editor.timing().dabs;
    const glm::vec2 press{340.0f, y};
    editor.mouse_moved(press);
    EXPECT_FALSE(editor.lazy_point()) << "only while painting";
    editor.mouse_pressed(MouseButton::Left, {});
    ASSERT_TRUE(editor.lazy_point());
    for (float dx = 2.0f; dx <= 30.0f; dx += 2.0f) editor.mouse_moved(press + glm::vec2(dx, 0.0f));
    EXPECT_EQ(*editor.lazy_point(), press) << "within the string: the brush stays";
    EXPECT_EQ(editor.timing().dabs - before, 1u) << "the press's dab alone";
    for (float dx = 32.0f; dx <= 100.0f; dx += 2.0f) editor.mouse_moved(press + glm::vec2(dx, 0.0f));
    EXPECT_NEAR(editor.lazy_point()->x, press.x + 100.0f - 32.0f, 1e-3f);
    EXPECT_EQ(editor.lazy_point()->y, press.y);
    EXPECT_EQ(editor.timing().dabs - before, 1u + 13u) << "68 px of brush path, a dab every 5 px";
    // A jerk back and sideways within the string leaves the brush where it is.
    editor.mouse_moved(press + glm::vec2(78.0f, 25.0f));
    EXPECT_NEAR(editor.lazy_point()->x, press.x + 68.0f, 1e-3f);
    EXPECT_EQ(editor.lazy_point()->y, press.y);
    editor.mouse_released(MouseButton::Left);
    editor.finish_work();
    EXPECT_FALSE(editor.lazy_point());
}

// F: the pointer's distance from the circle's centre is the radius; the circle starts at the current
// radius, a left click keeps the new one (and paints nothing), a right click or Esc puts it back.
TEST_F(StrokeComfort, FSetsTheRadiusByDragging) {
    const std::size_t steps = editor.document().history().undo_steps();
    const float azimuth = editor.camera().camera().azimuth_deg;
    editor.mouse_moved(centre);
    editor.key_pressed(Key::F, {});
    ASSERT_TRUE(editor.brush_adjust());
    EXPECT_EQ(editor.brush_adjust()->centre, centre - glm::vec2(20.0f, 0.0f)) << "the pointer starts on the current radius";
    editor.mouse_moved(centre + glm::vec2(30.0f, 40.0f));  // from the centre: (50, 40)
    EXPECT_FLOAT_EQ(editor.brush().radius_px, std::hypot(50.0f, 40.0f));
    EXPECT_EQ(editor.camera().camera().azimuth_deg, azimuth) << "the drag neither orbits nor paints";
    editor.mouse_pressed(MouseButton::Left, {});
    editor.mouse_released(MouseButton::Left);
    editor.finish_work();
    EXPECT_FALSE(editor.brush_adjust());
    EXPECT_FLOAT_EQ(editor.brush().radius_px, std::hypot(50.0f, 40.0f));
    EXPECT_FALSE(editor.painting());
    EXPECT_EQ(editor.document().history().undo_steps(), steps) << "the confirming click paints nothing";

    const float kept = editor.brush().radius_px;
    editor.key_pressed(Key::F, {});
    editor.mouse_moved(centre + glm::vec2(200.0f, 0.0f));
    EXPECT_NE(editor.brush().radius_px, kept);
    editor.key_pressed(Key::Escape, {});
    EXPECT_FALSE(editor.brush_adjust());
    EXPECT_EQ(editor.brush().radius_px, kept) << "Esc puts it back";
    editor.key_pressed(Key::F, {});
    editor.mouse_moved(centre + glm::vec2(-100.0f, 0.0f));
    editor.mouse_pressed(MouseButton::Right, {});
    EXPECT_EQ(editor.brush().radius_px, kept) << "so does a right click";

    // A radius in world units scales with the distance: twice as far, twice the radius.
    editor.brush().unit = RadiusUnit::World;
    editor.brush().radius_world = 0.1f;
    editor.mouse_moved(centre);
    editor.key_pressed(Key::F, {});
    editor.mouse_moved(centre + glm::vec2(kScaleDistance, 0.0f));
    EXPECT_FLOAT_EQ(editor.brush().radius_world, 0.2f);
    EXPECT_EQ(brush_adjust_label(*editor.brush_adjust(), editor.brush()), "radius 0.2 units");
    editor.mouse_pressed(MouseButton::Left, {});
}

// Ctrl+F: the target by dragging, kPixelsPerLevel per level from the centre (the circle starts at the
// current level), clamped to the levels the brush offers; a detail amount scales like a radius.
TEST_F(StrokeComfort, CtrlFSetsTheTargetByDragging) {
    editor.brush().target_level = 3;
    editor.mouse_moved(centre);
    editor.key_pressed(Key::F, {.ctrl = true});
    ASSERT_TRUE(editor.brush_adjust());
    EXPECT_EQ(editor.brush_adjust()->centre, centre - glm::vec2(3.0f * kPixelsPerLevel, 0.0f));
    editor.mouse_moved(centre + glm::vec2(2.0f * kPixelsPerLevel + 5.0f, 0.0f));
    EXPECT_EQ(editor.brush().target_level, 5);
    EXPECT_EQ(brush_adjust_label(*editor.brush_adjust(), editor.brush()), "target level 5");
    editor.mouse_moved(centre + glm::vec2(100.0f * kPixelsPerLevel, 0.0f));
    EXPECT_EQ(editor.brush().target_level, kMaxBrushLevel);
    editor.mouse_moved(centre - glm::vec2(3.0f * kPixelsPerLevel, 0.0f));
    EXPECT_EQ(editor.brush().target_level, 0) << "on the centre";
    editor.mouse_pressed(MouseButton::Left, {});
    EXPECT_EQ(editor.brush().target_level, 0);
    EXPECT_EQ(editor.brush().radius_px, 20.0f) << "the radius untouched";

    editor.brush().target = BrushSettings::Target::DetailSize;
    editor.brush().detail_px = 6.0f;
    editor.key_pressed(Key::F, {.ctrl = true});
    editor.mouse_moved(editor.brush_adjust()->centre + glm::vec2(0.0f, 0.5f * kScaleDistance));
    EXPECT_FLOAT_EQ(editor.brush().detail_px, 3.0f);
    EXPECT_EQ(brush_adjust_label(*editor.brush_adjust(), editor.brush()), "detail size 3 px");
    editor.key_pressed(Key::Escape, {});
    EXPECT_FLOAT_EQ(editor.brush().detail_px, 6.0f);
}

// While painting, F starts nothing: the stroke goes on.
TEST_F(StrokeComfort, FWaitsForTheStrokeToEnd) {
    editor.mouse_moved(centre);
    editor.mouse_pressed(MouseButton::Left, {});
    editor.key_pressed(Key::F, {});
    EXPECT_FALSE(editor.brush_adjust());
    editor.mouse_moved(centre + glm::vec2(30.0f, 0.0f));
    EXPECT_EQ(editor.brush().radius_px, 20.0f);
    editor.mouse_released(MouseButton::Left);
    editor.finish_work();
}

}  // namespace
}  // namespace app
