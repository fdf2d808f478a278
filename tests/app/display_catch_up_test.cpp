// After a large change (the undo of a whole-mesh action), the displayed triangles and the picking
// index catch up a part per frame instead of all in one frame, and end bit for bit as a rebuild.
#include <algorithm>
#include <chrono>

#include <gtest/gtest.h>

#include "app/editor.h"
#include "editor_fixture.h"
#include "render/surface_geometry.h"

namespace app {
namespace {

using test::kViewport;

// The large change: the bunny set all to level 3 (3674 -> 235,136 triangles). Under the sanitizers
// (test code at -O0 over an instrumented core, where these two tests were the largest part of the
// editor tests) level 2 (58,784): still tens of thousands of face slots, several parts of the
// display's catching up.
#if defined(__SANITIZE_ADDRESS__)
constexpr int kCatchUpLevel = 2;
#else
constexpr int kCatchUpLevel = 3;
#endif
constexpr std::size_t kCatchUpFaces = std::size_t{3674} << (2 * kCatchUpLevel);

TEST(DisplayCatchUp, TheUndoOfALargeEditIsShownOverSeveralFramesAndEndsAsARebuild) {
    Editor editor(kViewport);
    ASSERT_TRUE(editor.open(test::asset_path("bunny.obj")));
    editor.start_flood_fill(kCatchUpLevel);
    editor.finish_work();
    ASSERT_EQ(editor.document().mesh().num_faces(), kCatchUpFaces);
    // The undo itself crosses over frames (history_job.h); its first part, made by the call, changes
    // more face slots than one part of the catching up takes.
    ASSERT_TRUE(editor.undo());
    EXPECT_TRUE(editor.document().display_behind()) << "tens of thousands of face slots changed: more than one part";
    editor.mouse_moved({0.5f * kViewport.x, 0.5f * kViewport.y});
    EXPECT_FALSE(editor.cursor_hit()) << "hovering does not catch up all at once";
    int frames = 0;
    for (; (editor.job() != nullptr || editor.document().display_behind()) && frames < 10000; ++frames)
        editor.update(std::chrono::microseconds(1));
    ASSERT_EQ(editor.document().mesh().num_faces(), 3674u);
    EXPECT_GT(frames, 1) << "a frame of a few milliseconds catches up a part, not everything";
    EXPECT_TRUE(editor.cursor_hit()) << "the bunny is under the centre of the view";

    render::SurfaceGeometry rebuilt(editor.document().geometry().source());
    rebuilt.rebuild(editor.document().mesh());
    const render::SurfaceGeometry& shown = editor.document().geometry();
    ASSERT_EQ(shown.vertices().size(), rebuilt.vertices().size());
    EXPECT_TRUE(std::ranges::equal(shown.vertices(), rebuilt.vertices()));
    EXPECT_EQ(shown.triangles_of(rgb::Colour::Green), 3674u);
}

// The window draws frames without input only while Editor::needs_frames(): this is what a user sees
// after a whole-mesh job or an undo once the mouse rests.
class WindowFrames : public ::testing::Test {
protected:
    // Frames as the window draws them until it waits for input: each one runs the editor for `slice`
    // and takes the display's changes, as drawing does.
    void draw_until_idle(std::chrono::microseconds slice) {
        for (int frames = 0; editor.needs_frames() && frames < 100000; ++frames) {
            editor.update(slice);
            editor.document().take_display_changes();
        }
    }
    // What is drawn (the geometry as far as it has caught up) against a rebuild from the mesh.
    void expect_display_current(const char* after) {
        const render::SurfaceGeometry& shown = editor.document().shown();
        render::SurfaceGeometry rebuilt(shown.source());
        rebuilt.rebuild(editor.document().mesh());
        EXPECT_TRUE(std::ranges::equal(shown.vertices(), rebuilt.vertices())) << "stale display after " << after;
        EXPECT_TRUE(editor.document().display_up_to_date()) << after;
    }
    Editor editor{kViewport};
};

TEST_F(WindowFrames, KeepComingUntilTheDisplayHasCaughtUpWithAJobAndAnUndo) {
    ASSERT_TRUE(editor.open(test::asset_path("bunny.obj")));
    draw_until_idle(std::chrono::microseconds(1));
    // Frames whose job takes most of the slice leave the display behind (it gets what the job's
    // share leaves, display_pace.h); the job ends with the display still catching up.
    editor.start_flood_fill(kCatchUpLevel);
    draw_until_idle(std::chrono::milliseconds(30));
    ASSERT_EQ(editor.job(), nullptr);
    ASSERT_EQ(editor.document().mesh().num_faces(), kCatchUpFaces);
    expect_display_current("set all to one level");

    // An undo of the set all, over frames of the window's usual slice.
    editor.key_pressed(Key::Z, Modifiers{.ctrl = true});
    draw_until_idle(std::chrono::milliseconds(10));
    ASSERT_EQ(editor.document().mesh().num_faces(), 3674u);
    expect_display_current("undo");
    EXPECT_FALSE(editor.needs_frames()) << "then the window idles";
}

}  // namespace
}  // namespace app
