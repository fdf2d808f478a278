// rgbsub edit --screenshot: a full editor frame through OSMesa, panels included.
#include <gtest/gtest.h>

#include "app/editor.h"
#include "app/headless_frame.h"

namespace app {
namespace {

TEST(HeadlessFrame, DrawsTheMeshAndThePanel) {
    HeadlessFrame frame;
    frame.size = {800, 600};
    const render::Image image = render_editor_frame(std::string(RGBSUB_SOURCE_DIR) + "/assets/default.obj", frame);
    ASSERT_EQ(image.width, 800);
    ASSERT_EQ(image.height, 600);
    const glm::u8vec4 background = image.pixel(2, image.height / 2);
    // The framed mesh covers the centre of what the panel leaves free, and not what it covers.
    const int free_centre = static_cast<int>((800.0f - kPanelCover) / 2.0f);
    EXPECT_NE(image.pixel(free_centre, 300), background);
    // The panel sits at the top right: its title bar is neither background nor mesh.
    EXPECT_NE(image.pixel(image.width - 100, 16), background);
    EXPECT_NE(image.pixel(image.width - 100, 16), image.pixel(free_centre, 300));
}

TEST(HeadlessFrame, ALoadErrorIsReported) {
    EXPECT_THROW(render_editor_frame("/nonexistent/mesh.obj", HeadlessFrame{}), std::runtime_error);
}

}  // namespace
}  // namespace app
