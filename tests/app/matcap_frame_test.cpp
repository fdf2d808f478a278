// The matcap display mode in a headless editor frame (what `edit --screenshot --mode matcap` and the
// window show): the colour is a function of the normal as the camera sees it, and the clay's key
// light comes from the upper left.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "app/editor.h"
#include "app/headless_frame.h"
#include "io/mesh_file.h"
#include "render/image.h"
#include "test_meshes.h"
#include "test_paths.h"
#include "textured_quad.h"

namespace app {
namespace {

constexpr glm::ivec2 kMatcapFrame{800, 600};

// The surface's pixels: left of the panel, above the status bar, not the white background.
template <class Visit>
void for_mesh_pixels(const render::Image& image, Visit visit) {
    for (int y = 0; y < image.height - 40; ++y)
        for (int x = 0; x < image.width - static_cast<int>(kPanelCover); ++x) {
            const glm::u8vec4 p = image.pixel(x, y);
            if (p.r != 255 || p.g != 255 || p.b != 255) visit(x, y, p);
        }
}

render::Image matcap_frame(Editor& editor) {
    HeadlessFrame frame;
    frame.size = kMatcapFrame;
    frame.colouring = render::Colouring::Matcap;
    frame.cursor = {0.01f, 0.01f};  // over the background: no brush ring on the surface
    return render_editor_frame(editor, frame);
}

// A flat square seen head-on in a parallel view has one normal, so one colour all over, where a
// headlight would shade it by the distance to the eye; turned away it has another.
TEST(MatcapFrame, OneNormalSeenIsOneColour) {
    Editor editor(kMatcapFrame);
    ASSERT_TRUE(editor.open(test::write_textured_quad(test::fresh_folder("matcap_quad")).string())) << editor.message();
    editor.key_pressed(Key::Keypad1, {});  // from +z, the square's front
    editor.key_pressed(Key::Keypad5, {});  // parallel
    editor.frame_mesh();
    const render::Image head_on = matcap_frame(editor);
    // Multisampling blends the outline with the background: all but those pixels are one colour.
    std::size_t same = 0, total = 0;
    const glm::u8vec4 centre = head_on.pixel(static_cast<int>(0.37f * kMatcapFrame.x), kMatcapFrame.y / 2);
    for_mesh_pixels(head_on, [&](int, int, glm::u8vec4 p) {
        ++total;
        same += std::abs(p.r - centre.r) <= 1 && std::abs(p.g - centre.g) <= 1 && std::abs(p.b - centre.b) <= 1;
    });
    EXPECT_GT(total, 20000u) << "the square fills much of the view";
    EXPECT_GT(static_cast<double>(same) / static_cast<double>(total), 0.97) << "one colour, but for the outline's blend";
    EXPECT_TRUE(centre.r > centre.g && centre.g > centre.b) << "the clay's warm tint: " << int(centre.r) << ' ' << int(centre.g) << ' '
                                                             << int(centre.b);

    editor.mouse_moved({100.0f, 300.0f});
    editor.mouse_pressed(MouseButton::Right, {});
    editor.mouse_moved({160.0f, 300.0f});  // orbits: the square turns its face away to one side
    editor.mouse_released(MouseButton::Right);
    const render::Image turned = matcap_frame(editor);
    const glm::u8vec4 side = turned.pixel(static_cast<int>(0.37f * kMatcapFrame.x), kMatcapFrame.y / 2);
    EXPECT_NE(glm::ivec3(side), glm::ivec3(centre)) << "another normal, another colour";
}

// On a sphere the brightest pixel lies up and to the left of the middle, where the key light's
// highlight is, from any side: the lighting turns with the view.
TEST(MatcapFrame, TheHighlightIsUpperLeft) {
    const std::filesystem::path sphere = test::fresh_folder("matcap_sphere") / "sphere.obj";
    rgbio::save_mesh(render_test::icosphere(3), sphere.string());
    Editor editor(kMatcapFrame);
    ASSERT_TRUE(editor.open(sphere.string())) << editor.message();
    for (int side = 0; side < 2; ++side) {
        if (side == 1) editor.key_pressed(Key::Keypad7, {});  // from the top
        const render::Image image = matcap_frame(editor);
        glm::ivec2 low(image.width, image.height), high(0), brightest(0);
        int best = -1;
        for_mesh_pixels(image, [&](int x, int y, glm::u8vec4 p) {
            low = glm::min(low, glm::ivec2(x, y));
            high = glm::max(high, glm::ivec2(x, y));
            if (p.r + p.g + p.b > best) best = p.r + p.g + p.b, brightest = {x, y};
        });
        // The sphere's outline: its top, bottom and left (the panel may cover its right side).
        const int radius = (high.y - low.y) / 2;
        const glm::ivec2 middle(low.x + radius, low.y + radius);
        EXPECT_LT(brightest.x, middle.x - radius / 5) << "left, side " << side;
        EXPECT_LT(brightest.y, middle.y - radius / 5) << "up (image rows run down), side " << side;
    }
}

}  // namespace
}  // namespace app
