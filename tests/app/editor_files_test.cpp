// The editor's files in the background and its recovery copy, scripted without X or GL: a save runs
// on a copy while editing goes on, quitting waits for a save, unsaved work survives a session that
// did not exit cleanly (simulated by a session named after a process that has ended), files dropped
// on the window open like any other, and the recent-files list.
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "app/background_task.h"
#include "app/crease_tool.h"
#include "app/editor.h"
#include "editor_fixture.h"
#include "io/base_uvs.h"
#include "io/mesh_file.h"
#include "rgb/lod/refine.h"
#include "support/same_mesh.h"

namespace app {
namespace {

using test::bunny_path;
using test::fresh_folder;

using test::EditorFixture;
using test::kViewport;

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

// The file's texture coordinates and the chosen face-varying option reach the saved file.
TEST(EditorFiles, TextureCoordinatesAreSavedWithTheChosenInterpolation) {
    const std::filesystem::path folder = fresh_folder("textured_save");
    std::ofstream(folder / "textured.obj") << "v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n"
                                              "vt 0.1 0.2\nvt 0.3 0.2\nvt 0.2 0.1\nvt 0.2 0.3\nvt 0.2 0.2\n"
                                              "vt 0.7 0.2\nvt 0.9 0.2\nvt 0.8 0.1\nvt 0.8 0.3\nvt 0.8 0.2\n"
                                              "f 1/1 3/3 5/5\nf 3/3 2/2 5/5\nf 2/2 4/4 5/5\nf 4/4 1/1 5/5\n"
                                              "f 3/8 1/6 6/10\nf 2/7 3/8 6/10\nf 4/9 2/7 6/10\nf 1/6 4/9 6/10\n";
    Editor editor(kViewport);
    ASSERT_TRUE(editor.open((folder / "textured.obj").string()));
    ASSERT_EQ(editor.document().uv_interpolation(), rgb::UvInterpolation::Corners);
    std::vector<std::string> warnings;
    const rgb::UvChannel original = *rgbio::load_mesh_with_uvs((folder / "textured.obj").string(), warnings).uvs;
    paint(editor, 0.5f);
    editor.document().set_uv_interpolation(rgb::UvInterpolation::Boundaries);
    EXPECT_TRUE(editor.document().dirty());
    const std::filesystem::path file = folder / "saved.obj";
    editor.request_save_as(file.string());
    editor.finish_work();
    EXPECT_FALSE(editor.message_is_error()) << editor.message();
    const rgbio::MeshWithUvs saved = rgbio::load_mesh_with_uvs(file.string(), warnings);
    ASSERT_TRUE(saved.uvs);
    EXPECT_EQ(saved.uvs->interpolation, rgb::UvInterpolation::Boundaries);
    EXPECT_EQ(saved.uvs->values, original.values);
    EXPECT_EQ(saved.uvs->corners, original.corners);
    EXPECT_TRUE(rgbtest::same_mesh(saved.mesh, editor.document().mesh()));
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

// The percentage in a status line "Opening PATH: N%" (or Saving), after checking the rest of it.
int status_percent(const std::string& status, const std::string& verb, const std::string& path) {
    const std::string prefix = verb + " " + path + ": ";
    EXPECT_EQ(status.substr(0, prefix.size()), prefix);
    EXPECT_EQ(status.back(), '%') << status;
    return std::stoi(status.substr(prefix.size()));
}

// Watches a task until it is done: its fraction and status line only grow, and end at 1 and 100%.
void expect_progress_to_the_end(const BackgroundTask& task, const std::string& verb) {
    double fraction = 0.0;
    int percent = 0;
    while (!task.done()) {
        const double now = task.fraction();
        const int shown = status_percent(task.status(), verb, task.path());
        EXPECT_GE(now, fraction);
        EXPECT_GE(shown, percent);
        EXPECT_LE(shown, 100);
        fraction = now;
        percent = shown;
        std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    EXPECT_EQ(task.fraction(), 1.0);
    EXPECT_EQ(status_percent(task.status(), verb, task.path()), 100);
}

TEST(EditorFiles, OpeningAndSavingShowHowFarTheyAreInTheStatusLine) {
    rgb::Mesh mesh = rgbio::load_mesh(bunny_path());
    rgb::refine_uniform(mesh, 2);
    const std::string file = (fresh_folder("progress") / "bunny2.obj").string();
    const std::unique_ptr<BackgroundTask> saving = BackgroundTask::save(mesh, file, {});
    expect_progress_to_the_end(*saving, "Saving");
    ASSERT_FALSE(saving->error());
    const std::unique_ptr<BackgroundTask> opening = BackgroundTask::open(file, render::PositionSource::Displayed);
    expect_progress_to_the_end(*opening, "Opening");
    ASSERT_FALSE(opening->error());
    EXPECT_TRUE(rgbtest::same_mesh(opening->take_document().mesh, mesh));
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

// A crash right after the first stroke loses nothing, whatever folder the next session starts in;
// later strokes are copied on the timer (two minutes by default), not after each.
TEST_F(EditorRecovery, TheFirstEditIsCopiedAtOnceNamingTheFileByItsAbsolutePath) {
    const std::filesystem::path file = fresh_folder(std::string("recovery_first_") + ::testing::UnitTest::GetInstance()->current_test_info()->name()) / "mesh.obj";
    std::filesystem::copy_file(bunny_path(), file);
    rgb::Mesh first_stroke;
    {
        Editor crashed(options(ended_process()));
        ASSERT_TRUE(crashed.open(std::filesystem::relative(file).string()));
        paint(crashed, 0.55f);
        first_stroke = crashed.document().mesh();
        paint(crashed, 0.45f);
    }
    ASSERT_EQ(files_in_folder(), 2u) << "the copy and its note";
    Editor editor(options(0));
    ASSERT_EQ(editor.pending(), Pending::Recover);
    EXPECT_TRUE(std::filesystem::path(editor.pending_path()).is_absolute()) << editor.pending_path();
    EXPECT_TRUE(std::filesystem::equivalent(editor.pending_path(), file)) << editor.pending_path();
    editor.answer_pending(true);
    editor.finish_work();
    EXPECT_TRUE(rgbtest::same_mesh(editor.document().mesh(), first_stroke)) << "the second stroke waits for the timer";
    editor.close_session();
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

class DroppedAndRecentFiles : public EditorFixture {
protected:
    // A copy of the default mesh named `name` in the test's folder.
    std::string mesh_copy(const std::string& name) const {
        const std::filesystem::path path = folder_ / name;
        std::filesystem::copy_file(test::asset_path("default.obj"), path, std::filesystem::copy_options::overwrite_existing);
        return path.string();
    }
    const std::filesystem::path folder_ = fresh_folder(std::string("dropped_") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
};

TEST_F(DroppedAndRecentFiles, DroppingFilesOpensTheFirst) {
    const std::vector<std::string> dropped{mesh_copy("first.obj"), mesh_copy("second.obj")};
    editor.files_dropped(dropped);
    editor.finish_work();
    EXPECT_EQ(editor.document().path(), dropped[0]);
    EXPECT_EQ(editor.window_title(), "first.obj - rgbsub");
    EXPECT_EQ(editor.document().mesh().num_faces(), 192u) << "the default mesh's control cage";
    editor.files_dropped({});
    EXPECT_EQ(editor.file_task(), nullptr) << "an empty drop reads nothing";
    EXPECT_EQ(editor.document().path(), dropped[0]);
}

TEST_F(DroppedAndRecentFiles, DroppingOnUnsavedChangesAsksFirst) {
    ASSERT_TRUE(editor.open(mesh_copy("painted.obj")));
    editor.start_flood_fill(1);
    editor.finish_work();
    ASSERT_TRUE(editor.document().dirty());
    const std::vector<std::string> dropped{mesh_copy("other.obj")};
    editor.files_dropped(dropped);
    editor.finish_work();
    EXPECT_EQ(editor.pending(), Pending::DiscardForOpen);
    EXPECT_EQ(editor.document().mesh().num_faces(), 4u * 192u) << "nothing is discarded before the answer";
    editor.answer_pending(true);
    EXPECT_EQ(editor.document().path(), dropped[0]);
    EXPECT_EQ(editor.document().mesh().num_faces(), 192u);
}

TEST_F(DroppedAndRecentFiles, ADroppedFileThatDoesNotLoadLeavesTheMeshAlone) {
    ASSERT_TRUE(editor.open(mesh_copy("kept.obj")));
    const std::filesystem::path text = folder_ / "notes.txt";
    std::ofstream(text) << "not a mesh\n";
    editor.files_dropped(std::vector<std::string>{text.string()});
    editor.finish_work();
    EXPECT_EQ(editor.pending(), Pending::None);
    EXPECT_TRUE(editor.message_is_error());
    EXPECT_NE(editor.message().find("notes.txt"), std::string::npos) << editor.message();
    EXPECT_EQ(editor.document().path(), (folder_ / "kept.obj").string());
    EXPECT_EQ(editor.document().mesh().num_faces(), 192u);
}

// A valid mesh at a scale whose numbers cannot keep its shape is refused when the editor opens it, the
// reason in its message, and the mesh on screen stays (issue 30 item 14): 1e-200 across, its squared
// lengths underflow doubles; 1e-100 across, the 32-bit floats it is drawn with hold only zeros.
// Before, the editor opened both and drew nothing.
TEST_F(DroppedAndRecentFiles, AMeshTooSmallForItsNumbersIsNotOpened) {
    ASSERT_TRUE(editor.open(mesh_copy("kept.obj")));
    for (const auto& [scale, numbers] : {std::pair{"1e-200", "that doubles"}, std::pair{"1e-100", "that 32-bit floats allow"}}) {
        const std::string s = scale, file = (folder_ / "tiny.obj").string();
        // An octahedron, each face wound outwards.
        std::ofstream(file) << "v " << s << " 0 0\nv -" << s << " 0 0\nv 0 " << s << " 0\nv 0 -" << s << " 0\nv 0 0 " << s
                            << "\nv 0 0 -" << s << "\nf 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n";
        editor.request_open(file);
        editor.finish_work();
        EXPECT_TRUE(editor.message_is_error()) << scale;
        EXPECT_NE(editor.message().find(file + ": cannot open this mesh: the mesh is "), std::string::npos) << editor.message();
        EXPECT_NE(editor.message().find(numbers), std::string::npos) << editor.message();
        EXPECT_EQ(editor.document().path(), (folder_ / "kept.obj").string());
        EXPECT_EQ(editor.document().mesh().num_faces(), 192u);
    }
}

// Most recent first, each file once, only files that really opened or saved, and a short list.
TEST_F(DroppedAndRecentFiles, RecentFilesListTheLastFilesUsedNewestFirst) {
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
    // Opened in the background, as the window does.
    editor.request_open(b);
    editor.finish_work();
    EXPECT_EQ(editor.recent_files(), (std::vector<std::string>{b, a, c}));

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

// The document and its file, with copies of the default mesh in a folder of the test's own.
using DocumentFile = DroppedAndRecentFiles;

// Saving as .glb or .gltf exports: the document stays the OBJ (its title, its Ctrl+S target and its
// unsaved mark), so Ctrl+S still writes the OBJ with the adaptive state, which reopens.
TEST_F(DocumentFile, SavingAsGltfExportsAndTheDocumentStaysTheObj) {
    const std::string obj = mesh_copy("cat.obj");
    ASSERT_TRUE(editor.open(obj));
    editor.start_flood_fill(1);
    editor.finish_work();
    ASSERT_EQ(editor.window_title(), "cat.obj* - rgbsub");
    // In the background as the window does (Ctrl+Shift+S), and right away.
    editor.request_save_as((folder_ / "cat.glb").string());
    editor.finish_work();
    ASSERT_TRUE(editor.save_as((folder_ / "cat.gltf").string())) << editor.message();
    EXPECT_TRUE(std::filesystem::exists(folder_ / "cat.glb"));
    EXPECT_TRUE(std::filesystem::exists(folder_ / "cat.gltf"));
    EXPECT_EQ(editor.document().path(), obj);
    EXPECT_TRUE(editor.document().dirty()) << "an export saves nothing of the document";
    EXPECT_EQ(editor.window_title(), "cat.obj* - rgbsub");
    EXPECT_NE(editor.message().find("exported"), std::string::npos) << editor.message();

    editor.key_pressed(Key::S, {.ctrl = true});
    editor.finish_work();
    EXPECT_FALSE(editor.document().dirty()) << editor.message();
    EXPECT_EQ(editor.window_title(), "cat.obj - rgbsub");
    Editor reopened(kViewport);
    ASSERT_TRUE(reopened.open(obj)) << reopened.message();
    EXPECT_TRUE(rgbtest::same_mesh(reopened.document().mesh(), editor.document().mesh())) << "the adaptive state, at level 1";
}

// Undoing back to the state of the file marks it saved again; redoing past it, unsaved. Over frames
// too (an undo too large for one frame).
TEST_F(DocumentFile, UndoingBackToTheSavedStateMarksTheFileSaved) {
    const std::string obj = mesh_copy("cat.obj");
    ASSERT_TRUE(editor.open(obj));
    editor.start_flood_fill(1);
    editor.finish_work();
    ASSERT_TRUE(editor.document().dirty());
    editor.key_pressed(Key::Z, {.ctrl = true});
    editor.finish_work();
    EXPECT_FALSE(editor.document().dirty()) << "back to the opened file";
    EXPECT_EQ(editor.window_title(), "cat.obj - rgbsub");
    editor.key_pressed(Key::Y, {.ctrl = true});
    editor.finish_work();
    EXPECT_TRUE(editor.document().dirty());

    // Saved at level 1: then level 4 (a step that undoes over frames) and back.
    ASSERT_TRUE(editor.save());
    editor.start_flood_fill(4);
    editor.finish_work();
    ASSERT_TRUE(editor.document().dirty());
    ASSERT_TRUE(editor.undo());
    ASSERT_NE(editor.job(), nullptr) << "the undo goes on over frames";
    EXPECT_TRUE(editor.document().dirty()) << "half way back";
    editor.finish_work();
    EXPECT_FALSE(editor.document().dirty()) << "back to the saved file";
    ASSERT_TRUE(editor.undo());
    EXPECT_TRUE(editor.document().dirty()) << "before the save: not what the file holds";
    // A new edit from there loses the way back to the saved state.
    editor.start_flood_fill(2);
    editor.finish_work();
    editor.start_flood_fill(1);
    editor.finish_work();
    EXPECT_TRUE(editor.document().dirty()) << "the same mesh as the file, but not through its history";
}

// Ctrl+E's script names the file its edits start from (the one opened, not a later Save as), and
// its warning names the edits in effect that no script says, by what they were.
TEST_F(DocumentFile, TheStrokesScriptNamesTheFileItsEditsStartFromAndWhatItCannotSay) {
    const std::string obj = mesh_copy("start.obj");
    ASSERT_TRUE(editor.open(obj));
    editor.start_flood_fill(1);
    editor.finish_work();
    ASSERT_TRUE(editor.save_as((folder_ / "later.obj").string()));
    editor.start_flood_fill(2);
    editor.finish_work();
    const std::filesystem::path script = folder_ / "session.lod";
    ASSERT_TRUE(editor.save_strokes(script.string()));
    EXPECT_FALSE(editor.message_is_error()) << editor.message();
    std::string header;
    std::getline(std::ifstream(script), header);
    EXPECT_NE(header.find("rgbsub apply " + obj + " " + script.string()), std::string::npos) << header;
    EXPECT_EQ(header.find("later.obj"), std::string::npos) << header;

    ASSERT_TRUE(editor.set_sharp_features(with_edges_above(editor.document().mesh(), 30.0), "tag edges above 30 degrees"));
    editor.start_view_lod();
    editor.finish_work();
    editor.freeze_view_lod();
    ASSERT_TRUE(editor.save_strokes(script.string()));
    EXPECT_TRUE(editor.message_is_error());
    EXPECT_NE(editor.message().find("2 edits in effect have no script"), std::string::npos) << editor.message();
    EXPECT_NE(editor.message().find("tag edges above 30 degrees"), std::string::npos) << editor.message();
    EXPECT_NE(editor.message().find("view-dependent LOD"), std::string::npos) << editor.message();
    EXPECT_EQ(editor.message().find("automatic LOD"), std::string::npos) << editor.message();

    // Saved over the file the edits start from: the script says the file holds them now.
    ASSERT_TRUE(editor.open(obj));
    editor.start_flood_fill(1);
    editor.finish_work();
    ASSERT_TRUE(editor.save());
    ASSERT_TRUE(editor.save_strokes(script.string()));
    std::stringstream text;
    text << std::ifstream(script).rdbuf();
    EXPECT_NE(text.str().find("# " + obj + " has been saved with these edits since"), std::string::npos) << text.str();
    EXPECT_NE(editor.message().find("saved with these edits since"), std::string::npos) << editor.message();
}

}  // namespace
}  // namespace app
