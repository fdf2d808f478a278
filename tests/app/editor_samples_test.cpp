// The files that ship with rgbsub open as samples: a stroke and Ctrl+S never write over them, the
// first save asks where. The "shipped" folder is one of the test's own (EditorOptions::samples_folder),
// so the real assets are never touched.
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "app/editor.h"
#include "editor_fixture.h"

namespace app {
namespace {

using test::fresh_folder;
using test::kViewport;

std::string file_bytes(const std::filesystem::path& path) {
    std::stringstream bytes;
    bytes << std::ifstream(path, std::ios::binary).rdbuf();
    return bytes.str();
}

class ShippedSamples : public ::testing::Test {
protected:
    ShippedSamples() {
        std::filesystem::copy_file(test::asset_path("default.obj"), sample_);
        EditorOptions options;
        options.viewport = kViewport;
        options.samples_folder = shipped_;
        editor_.emplace(options);
    }

    // One stroke across the middle of the view, run to its end.
    void paint() {
        editor_->brush().target_level = 3;
        editor_->mouse_moved({0.4f * kViewport.x, 0.5f * kViewport.y});
        editor_->mouse_pressed(MouseButton::Left, {});
        editor_->mouse_moved({0.6f * kViewport.x, 0.5f * kViewport.y});
        editor_->mouse_released(MouseButton::Left);
        editor_->finish_work();
    }

    // A stroke, then Ctrl+S writes the open file without asking where.
    void paint_and_expect_ctrl_s_saves_in_place() {
        paint();
        editor_->key_pressed(Key::S, {.ctrl = true});
        editor_->finish_work();
        EXPECT_EQ(editor_->take_browse_request(), Editor::Browse::None);
        EXPECT_FALSE(editor_->document().dirty()) << editor_->message();
    }

    // Of this test alone: ctest may run the others at the same time.
    const std::string test_name_ = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    const std::filesystem::path shipped_ = fresh_folder("shipped_" + test_name_);
    const std::filesystem::path elsewhere_ = fresh_folder("saved_" + test_name_);
    const std::filesystem::path sample_ = shipped_ / "default.obj";
    std::optional<Editor> editor_;
};

TEST_F(ShippedSamples, AStrokeAndCtrlSAskWhereInsteadOfWritingOverTheSample) {
    const std::string shipped_bytes = file_bytes(sample_);
    // As the window opens it (in the background), by a path that is not the folder's own spelling.
    editor_->request_open((shipped_ / "." / "default.obj").string());
    editor_->finish_work();
    ASSERT_EQ(editor_->document().mesh().num_faces(), 192u) << editor_->message();
    EXPECT_NE(editor_->message().find("a sample that ships with rgbsub"), std::string::npos) << editor_->message();
    paint();
    ASSERT_TRUE(editor_->document().dirty());

    editor_->key_pressed(Key::S, {.ctrl = true});
    editor_->finish_work();
    EXPECT_EQ(editor_->take_browse_request(), Editor::Browse::SaveAs) << editor_->message();
    EXPECT_TRUE(file_bytes(sample_) == shipped_bytes) << "the sample was written over";
    EXPECT_TRUE(editor_->document().dirty());
    const std::filesystem::path proposed(editor_->suggested_path());
    EXPECT_EQ(proposed.filename(), "default.obj");
    EXPECT_NE(proposed.parent_path(), shipped_) << "the proposal is outside the shipped files";

    EXPECT_FALSE(editor_->save()) << "a save right away refuses too";
    EXPECT_TRUE(file_bytes(sample_) == shipped_bytes) << "the sample was written over";
    // Saving as the sample itself, on purpose, asks first.
    editor_->request_save_as(editor_->document().path());
    EXPECT_EQ(editor_->pending(), Pending::Overwrite);
    editor_->answer_pending(false);
    editor_->finish_work();
    EXPECT_TRUE(file_bytes(sample_) == shipped_bytes) << "the sample was written over";

    // Saved elsewhere, the file is the user's: Ctrl+S writes it without asking.
    const std::filesystem::path own = elsewhere_ / "cat.obj";
    editor_->request_save_as(own.string());
    editor_->finish_work();
    ASSERT_EQ(editor_->document().path(), own.string()) << editor_->message();
    EXPECT_TRUE(editor_->suggested_path().empty());
    paint_and_expect_ctrl_s_saves_in_place();
    EXPECT_TRUE(file_bytes(sample_) == shipped_bytes) << "the sample was written over";
}

TEST_F(ShippedSamples, AFileOutsideTheShippedFolderSavesInPlace) {
    const std::filesystem::path own = elsewhere_ / "mine.obj";
    std::filesystem::copy_file(sample_, own);
    ASSERT_TRUE(editor_->open(own.string()));
    EXPECT_TRUE(editor_->suggested_path().empty());
    paint_and_expect_ctrl_s_saves_in_place();
}

}  // namespace
}  // namespace app
