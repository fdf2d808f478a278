// An undo or redo too large for a frame crosses its step over several frames like any other job, and
// ends bit for bit where the one-shot crossing ends; Esc stops it part way with both parts kept as
// steps, from which Ctrl+Z and Ctrl+Y still reach every earlier mesh exactly.
#include <chrono>
#include <string>

#include <gtest/gtest.h>

#include "app/editor.h"
#include "editor_fixture.h"
#include "rgb/mesh/mesh.h"
#include "support/same_slots.h"

namespace app {
namespace {

constexpr std::chrono::microseconds kShortFrame{1000};

class HistoryJobs : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(editor.open(test::asset_path("bunny.obj")));
        before = editor.document().mesh();
        editor.start_flood_fill(3);  // 3674 -> 235,136 triangles: 115,731 splits, many frames' worth
        editor.finish_work();
        after = editor.document().mesh();
        ASSERT_EQ(after.num_faces(), 235136u);
    }

    // Frames of `slice` until the job is done; returns how many.
    int run_frames(std::chrono::microseconds slice) {
        int frames = 0;
        for (; editor.job() != nullptr && frames < 100000; ++frames) editor.update(slice);
        return frames;
    }

    Editor editor{test::kViewport};
    rgb::Mesh before, after;
};

TEST_F(HistoryJobs, ALargeUndoCrossesOverFramesWithProgressAndEndsAsTheMeshBefore) {
    ASSERT_TRUE(editor.undo());
    ASSERT_NE(editor.job(), nullptr) << "too large to cross within the call";
    EXPECT_EQ(editor.job()->label(), "undo set all to level 3");
    const std::size_t first_faces = editor.document().mesh().num_faces();
    EXPECT_LT(first_faces, after.num_faces()) << "the call crossed a first part";
    EXPECT_GT(first_faces, before.num_faces());
    float progress = editor.job()->progress();
    EXPECT_GT(progress, 0.0f);
    int frames = 0;
    for (; editor.job() != nullptr; ++frames) {
        editor.update(kShortFrame);
        if (editor.job() == nullptr) break;
        EXPECT_GE(editor.job()->progress(), progress);
        progress = editor.job()->progress();
    }
    EXPECT_GT(frames, 2);
    EXPECT_EQ(editor.message(), "undid set all to level 3");
    EXPECT_TRUE(rgbtest::same_slots(editor.document().mesh(), before));

    ASSERT_TRUE(editor.redo());
    EXPECT_GT(run_frames(kShortFrame), 2);
    EXPECT_TRUE(rgbtest::same_slots(editor.document().mesh(), after));
    EXPECT_EQ(editor.message(), "redid set all to level 3");
}

TEST_F(HistoryJobs, NothingElseStartsWhileItRuns) {
    ASSERT_TRUE(editor.undo());
    ASSERT_NE(editor.job(), nullptr);
    const std::size_t faces = editor.document().mesh().num_faces();
    EXPECT_FALSE(editor.undo());
    EXPECT_FALSE(editor.redo());
    editor.mouse_moved({0.5f * test::kViewport.x, 0.5f * test::kViewport.y});
    editor.mouse_pressed(MouseButton::Left, {});
    EXPECT_FALSE(editor.painting()) << "painting waits for the undo";
    editor.mouse_released(MouseButton::Left);
    EXPECT_EQ(editor.document().mesh().num_faces(), faces);
    run_frames(std::chrono::seconds(1));
    EXPECT_TRUE(rgbtest::same_slots(editor.document().mesh(), before));
}

TEST_F(HistoryJobs, EscStopsItPartWayAndBothPartsCrossBackExactly) {
    ASSERT_TRUE(editor.undo());
    for (int i = 0; i < 3 && editor.job() != nullptr; ++i) editor.update(kShortFrame);
    ASSERT_NE(editor.job(), nullptr);
    editor.key_pressed(Key::Escape, {});
    EXPECT_EQ(editor.job(), nullptr);
    EXPECT_NE(editor.message().find("stopped part way"), std::string::npos) << editor.message();
    const rgb::Mesh middle = editor.document().mesh();
    ASSERT_LT(middle.num_faces(), after.num_faces());
    ASSERT_GT(middle.num_faces(), before.num_faces());
    EXPECT_EQ(editor.document().history().undo_steps(), 1u) << "the part still in effect";
    EXPECT_EQ(editor.document().history().redo_steps(), 1u) << "the part undone";

    // The rest of the undo, then both redos, each through its own frames.
    ASSERT_TRUE(editor.undo());
    run_frames(kShortFrame);
    EXPECT_TRUE(rgbtest::same_slots(editor.document().mesh(), before));
    ASSERT_TRUE(editor.redo());
    run_frames(kShortFrame);
    EXPECT_TRUE(rgbtest::same_slots(editor.document().mesh(), middle));
    ASSERT_TRUE(editor.redo());
    run_frames(kShortFrame);
    EXPECT_TRUE(rgbtest::same_slots(editor.document().mesh(), after));
    EXPECT_FALSE(editor.document().history().can_redo());
}

TEST_F(HistoryJobs, EscRightAfterTheCallKeepsThePartTheCallCrossed) {
    ASSERT_TRUE(editor.undo());  // the call crosses HistoryJob::kImmediateOperations
    EXPECT_EQ(editor.document().history().crossed_operations(), HistoryJob::kImmediateOperations);
    editor.key_pressed(Key::Escape, {});
    EXPECT_EQ(editor.job(), nullptr);
    ASSERT_TRUE(editor.redo());
    run_frames(kShortFrame);
    EXPECT_TRUE(rgbtest::same_slots(editor.document().mesh(), after));
    EXPECT_EQ(editor.document().history().undo_steps(), 2u) << "the part never undone, and the part redone";
    ASSERT_TRUE(editor.undo());
    run_frames(kShortFrame);
    ASSERT_TRUE(editor.undo());
    run_frames(kShortFrame);
    EXPECT_TRUE(rgbtest::same_slots(editor.document().mesh(), before));
}

}  // namespace
}  // namespace app
