// Opening files by dropping them on the window, and the recent-files list.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "editor_fixture.h"

namespace app {
namespace {

namespace fs = std::filesystem;

class EditorFiles : public test::EditorFixture {
protected:
    void SetUp() override {
        folder_ = fs::path(::testing::TempDir()) /
                  ("rgbsub_editor_files_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(folder_);
        fs::create_directories(folder_);
    }
    void TearDown() override { fs::remove_all(folder_); }

    // A copy of the default mesh named `name` in the test's folder.
    std::string mesh_copy(const std::string& name) const {
        const fs::path path = folder_ / name;
        fs::copy_file(test::asset_path("default.obj"), path, fs::copy_options::overwrite_existing);
        return path.string();
    }
    fs::path folder_;
};

TEST_F(EditorFiles, DroppingFilesOpensTheFirst) {
    const std::vector<std::string> dropped{mesh_copy("first.obj"), mesh_copy("second.obj")};
    editor.files_dropped(dropped);
    EXPECT_EQ(editor.document().path(), dropped[0]);
    EXPECT_EQ(editor.window_title(), "first.obj - rgbsub");
    EXPECT_EQ(editor.document().mesh().num_faces(), 192u) << "the default mesh's control cage";
    editor.files_dropped({});
    EXPECT_EQ(editor.document().path(), dropped[0]) << "an empty drop changes nothing";
}

TEST_F(EditorFiles, DroppingOnUnsavedChangesAsksFirst) {
    ASSERT_TRUE(editor.open(mesh_copy("painted.obj")));
    editor.start_flood_fill(1);
    while (editor.job() != nullptr) editor.update();
    ASSERT_TRUE(editor.document().dirty());
    const std::vector<std::string> dropped{mesh_copy("other.obj")};
    editor.files_dropped(dropped);
    EXPECT_EQ(editor.pending(), Pending::DiscardForOpen);
    EXPECT_EQ(editor.document().mesh().num_faces(), 4u * 192u) << "nothing is discarded before the answer";
    editor.answer_pending(true);
    EXPECT_EQ(editor.document().path(), dropped[0]);
    EXPECT_EQ(editor.document().mesh().num_faces(), 192u);
}

TEST_F(EditorFiles, ADroppedFileThatDoesNotLoadLeavesTheMeshAlone) {
    ASSERT_TRUE(editor.open(mesh_copy("kept.obj")));
    const fs::path text = folder_ / "notes.txt";
    std::ofstream(text) << "not a mesh\n";
    editor.files_dropped(std::vector<std::string>{text.string()});
    EXPECT_TRUE(editor.message_is_error());
    EXPECT_NE(editor.message().find("notes.txt"), std::string::npos) << editor.message();
    EXPECT_EQ(editor.document().path(), (folder_ / "kept.obj").string());
}

// Most recent first, each file once, only files that really opened or saved, and a short list.
TEST_F(EditorFiles, RecentFilesListTheLastFilesUsedNewestFirst) {
    const std::string a = mesh_copy("a.obj"), b = mesh_copy("b.obj");
    ASSERT_TRUE(editor.open(a));
    ASSERT_TRUE(editor.open(b));
    const std::string c = (folder_ / "c.obj").string();
    ASSERT_TRUE(editor.save_as(c));
    EXPECT_EQ(editor.recent_files(), (std::vector<std::string>{c, b, a}));
    ASSERT_TRUE(editor.open(a));
    EXPECT_EQ(editor.recent_files(), (std::vector<std::string>{a, c, b}));
    EXPECT_FALSE(editor.open((folder_ / "missing.obj").string()));
    EXPECT_EQ(editor.recent_files(), (std::vector<std::string>{a, c, b}));

    std::vector<std::string> opened;
    for (int i = 0; i < 20; ++i) {
        opened.push_back(mesh_copy("many" + std::to_string(i) + ".obj"));
        ASSERT_TRUE(editor.open(opened.back()));
    }
    const std::vector<std::string>& recent = editor.recent_files();
    ASSERT_GE(recent.size(), 3u);
    EXPECT_LT(recent.size(), 20u) << "the list stays short";
    for (std::size_t i = 0; i < recent.size(); ++i) EXPECT_EQ(recent[i], opened[opened.size() - 1 - i]);
}

}  // namespace
}  // namespace app
