// What F shows on screen, in a headless editor frame: the circle whose radius is the brush's new
// radius, around the centre the adjustment placed, instead of the brush ring on the surface.
#include <cmath>

#include <gtest/gtest.h>

#include "app/editor.h"
#include "app/headless_frame.h"
#include "render/image.h"
#include "test_paths.h"

namespace app {
namespace {

constexpr glm::ivec2 kFeedbackFrame{800, 600};

bool orange_near(const render::Image& image, glm::vec2 at) {
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
            const glm::u8vec4 p = image.pixel(static_cast<int>(std::lround(at.x)) + dx, static_cast<int>(std::lround(at.y)) + dy);
            if (p.r > 200 && p.g > 90 && p.g < 190 && p.b < 80) return true;
        }
    return false;
}

TEST(BrushFeedbackFrame, FShowsTheRadiusAsACircle) {
    Editor editor(kFeedbackFrame);
    ASSERT_TRUE(editor.open(test::asset_path("default.obj"))) << editor.message();
    editor.brush().radius_px = 40.0f;
    const glm::vec2 pressed(260.0f, 300.0f);
    editor.mouse_moved(pressed);
    editor.key_pressed(Key::F, {});
    HeadlessFrame frame;
    frame.size = kFeedbackFrame;
    frame.cursor = (pressed + glm::vec2(60.0f, 0.0f)) / glm::vec2(kFeedbackFrame);  // the frame moves the pointer there
    const render::Image image = render_editor_frame(editor, frame);
    ASSERT_FLOAT_EQ(editor.brush().radius_px, 100.0f);
    const glm::vec2 centre = editor.brush_adjust()->centre;
    for (int step = 0; step < 8; ++step) {
        const float angle = 0.785398f * static_cast<float>(step) + 0.3f;
        const glm::vec2 direction(std::cos(angle), std::sin(angle));
        EXPECT_TRUE(orange_near(image, centre + 100.0f * direction)) << "on the circle at angle " << angle;
        EXPECT_FALSE(orange_near(image, centre + 60.0f * direction)) << "inside it at angle " << angle;
    }
}

}  // namespace
}  // namespace app
