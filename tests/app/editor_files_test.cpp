// The editor's files in the background and its recovery copy, scripted without X or GL: a save runs
// on a copy while editing goes on, quitting waits for a save, and unsaved work survives a session
// that did not exit cleanly (simulated by a session named after a process that has ended).
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "app/editor.h"
#include "io/mesh_file.h"
#include "support/same_mesh.h"

namespace app {
namespace {

constexpr glm::ivec2 kViewport{800, 600};

std::string bunny_path() { return std::string(RGBSUB_SOURCE_DIR) + "/assets/bunny.obj"; }

// A fresh folder under the test's temporary directory.
std::filesystem::path fresh_folder(const std::string& name) {
    const std::filesystem::path folder = std::filesystem::path(::testing::TempDir()) / name;
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

// The id of a process that has run and ended.
int ended_process() {
    const pid_t child = ::fork();
    if (child == 0) ::_exit(0);
    int status = 0;
    ::waitpid(child, &status, 0);
    return static_cast<int>(child);
}

void paint(Editor& editor, float y) {
    editor.brush().target_level = 3;
    editor.brush().radius_px = 30.0f;
    editor.mouse_moved({0.4f * kViewport.x, y * kViewport.y});
    editor.mouse_pressed(MouseButton::Left, {});
    editor.mouse_moved({0.6f * kViewport.x, y * kViewport.y});
    editor.mouse_released(MouseButton::Left);
    editor.finish_work();
}

TEST(EditorFiles, ABackgroundSaveWritesTheMeshAsItWasAndEditingGoesOn) {
    Editor editor(kViewport);
    ASSERT_TRUE(editor.open(bunny_path()));
    paint(editor, 0.55f);
    const rgb::Mesh at_save = editor.document().mesh();
    const std::filesystem::path file = fresh_folder("background_save") / "saved.obj";
    editor.request_save_as(file.string());
    ASSERT_NE(editor.file_task(), nullptr);
    // Painting while the copy is written.
    paint(editor, 0.45f);
    editor.finish_work();
    EXPECT_FALSE(editor.message_is_error()) << editor.message();
    EXPECT_TRUE(rgbtest::same_mesh(rgbio::load_mesh(file.string()), at_save));
    EXPECT_EQ(editor.document().path(), file.string());
    EXPECT_TRUE(editor.document().dirty()) << "the second stroke is not in the file";
    editor.request_save();
    editor.finish_work();
    EXPECT_FALSE(editor.document().dirty());
    EXPECT_TRUE(rgbtest::same_mesh(rgbio::load_mesh(file.string()), editor.document().mesh()));
}

// The stroke belongs to the mesh on screen: the file read meanwhile waits for it, then asks.
TEST(EditorFiles, AFileReadWhileAStrokeIsAppliedWaitsForItAndAsks) {
    Editor editor(kViewport);
    ASSERT_TRUE(editor.open(bunny_path()));
    const std::size_t original = editor.document().mesh().num_faces();
    editor.request_open(bunny_path());
    editor.brush().radius_px = 30.0f;
    editor.mouse_moved({0.4f * kViewport.x, 0.55f * kViewport.y});
    editor.mouse_pressed(MouseButton::Left, {});
    editor.mouse_moved({0.6f * kViewport.x, 0.55f * kViewport.y});
    editor.mouse_released(MouseButton::Left);
    editor.finish_work();
    EXPECT_GT(editor.document().mesh().num_faces(), original);
    EXPECT_EQ(editor.pending(), Pending::DiscardForOpen);
    editor.answer_pending(true);
    EXPECT_EQ(editor.document().mesh().num_faces(), original);
}

TEST(EditorFiles, EscStopsOpeningAFile) {
    Editor editor(kViewport);
    editor.request_open(bunny_path());
    editor.key_pressed(Key::Escape, {});
    EXPECT_EQ(editor.file_task(), nullptr);
    editor.finish_work();
    EXPECT_EQ(editor.document().mesh().num_faces(), 0u);
    EXPECT_NE(editor.message().find("stopped opening"), std::string::npos) << editor.message();
}

TEST(EditorFiles, SaveAndQuitQuitsOnceTheFileIsWritten) {
    Editor editor(kViewport);
    const std::filesystem::path file = fresh_folder("save_and_quit") / "mesh.obj";
    std::filesystem::copy_file(bunny_path(), file);
    ASSERT_TRUE(editor.open(file.string()));
    paint(editor, 0.55f);
    editor.request_quit();
    ASSERT_EQ(editor.pending(), Pending::DiscardForQuit);
    editor.save_and_quit();
    EXPECT_FALSE(editor.should_quit()) << "not before the file is written";
    editor.finish_work();
    EXPECT_TRUE(editor.should_quit());
    EXPECT_TRUE(rgbtest::same_mesh(rgbio::load_mesh(file.string()), editor.document().mesh()));
}

TEST(EditorFiles, TheRecoveryFolderFollowsXdgStateHome) {
    const char* saved_state = std::getenv("XDG_STATE_HOME");
    const std::string restore = saved_state ? saved_state : "";
    ::setenv("XDG_STATE_HOME", "/tmp/state-for-rgbsub-test", 1);
    EXPECT_EQ(RecoveryStore::default_folder(), std::filesystem::path("/tmp/state-for-rgbsub-test/rgbsub"));
    ::unsetenv("XDG_STATE_HOME");
    EXPECT_EQ(RecoveryStore::default_folder(), std::filesystem::path(std::getenv("HOME")) / ".local/state/rgbsub");
    if (saved_state) ::setenv("XDG_STATE_HOME", restore.c_str(), 1);
}

class EditorRecovery : public ::testing::Test {
protected:
    EditorOptions options(int process_id) const {
        EditorOptions o;
        o.viewport = kViewport;
        o.recovery_folder = folder;
        o.process_id = process_id;
        return o;
    }
    std::size_t files_in_folder() const {
        std::size_t n = 0;
        for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(folder)) ++n;
        return n;
    }
    // One folder per test: ctest runs them in parallel processes, which must not remove each other's.
    const std::filesystem::path folder =
        fresh_folder(std::string("recovery_") + ::testing::UnitTest::GetInstance()->current_test_info()->name()) / "state" / "rgbsub";
};

// A whole-mesh action is risky, so unsaved work is copied before it starts.
TEST_F(EditorRecovery, UnsavedWorkIsCopiedBeforeWholeMeshActionsAndACleanExitRemovesTheCopy) {
    Editor editor(options(0));
    ASSERT_TRUE(editor.open(bunny_path()));
    paint(editor, 0.55f);
    const rgb::Mesh painted = editor.document().mesh();
    editor.start_flood_fill(1);
    editor.finish_work();
    const std::filesystem::path copy = folder / ("recovery-" + std::to_string(::getpid()) + ".obj");
    ASSERT_TRUE(std::filesystem::exists(copy));
    EXPECT_TRUE(rgbtest::same_mesh(rgbio::load_mesh(copy.string()), painted));
    EXPECT_EQ(files_in_folder(), 2u) << "the copy and its note";
    EXPECT_EQ(std::filesystem::status(folder).permissions() & std::filesystem::perms::all, std::filesystem::perms::owner_all);
    editor.close_session();
    EXPECT_EQ(files_in_folder(), 0u);
}

TEST_F(EditorRecovery, SavingLeavesNothingToRecover) {
    EditorOptions o = options(0);
    o.recovery_interval = std::chrono::seconds(0);
    Editor editor(o);
    const std::filesystem::path file = fresh_folder("recovery_save") / "mesh.obj";
    std::filesystem::copy_file(bunny_path(), file);
    ASSERT_TRUE(editor.open(file.string()));
    paint(editor, 0.55f);
    EXPECT_EQ(files_in_folder(), 2u);
    editor.request_save();
    editor.finish_work();
    EXPECT_EQ(files_in_folder(), 0u);
}

TEST_F(EditorRecovery, TheNextSessionOffersTheWorkOfOneThatDidNotExitCleanly) {
    rgb::Mesh lost;
    {
        // A session that ends without close_session, as a crash would; its process is gone.
        EditorOptions o = options(ended_process());
        o.recovery_interval = std::chrono::seconds(0);
        Editor crashed(o);
        ASSERT_TRUE(crashed.open(bunny_path()));
        paint(crashed, 0.55f);
        paint(crashed, 0.45f);
        lost = crashed.document().mesh();
    }
    ASSERT_EQ(files_in_folder(), 2u);
    Editor editor(options(0));
    ASSERT_EQ(editor.pending(), Pending::Recover);
    EXPECT_EQ(editor.pending_path(), bunny_path());
    editor.answer_pending(true);
    editor.finish_work();
    EXPECT_TRUE(rgbtest::same_mesh(editor.document().mesh(), lost));
    EXPECT_TRUE(editor.document().dirty()) << "recovered work is not saved yet";
    EXPECT_EQ(editor.document().path(), bunny_path());
    // The orphan has gone once the work is in this session's own copy.
    EXPECT_EQ(files_in_folder(), 2u);
    EXPECT_TRUE(std::filesystem::exists(folder / ("recovery-" + std::to_string(::getpid()) + ".obj")));
    editor.close_session();
    EXPECT_EQ(files_in_folder(), 0u);
}

TEST_F(EditorRecovery, DiscardingTheOfferRemovesTheCopy) {
    {
        EditorOptions o = options(ended_process());
        o.recovery_interval = std::chrono::seconds(0);
        Editor crashed(o);
        ASSERT_TRUE(crashed.open(bunny_path()));
        paint(crashed, 0.55f);
    }
    Editor editor(options(0));
    ASSERT_EQ(editor.pending(), Pending::Recover);
    editor.answer_pending(false);
    EXPECT_EQ(files_in_folder(), 0u);
    EXPECT_EQ(Editor(options(0)).pending(), Pending::None);
}

}  // namespace
}  // namespace app
