// Opening a dense plain mesh, scripted without X or GL: the editor asks whether to make a cage that
// keeps the detail or to open it as a base mesh; the cage is made in the background with its phase
// and progress, Esc stops it with nothing changed, and the cage with its detail becomes an unsaved
// document that Save asks a name for.
#include <chrono>
#include <filesystem>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "app/background_task.h"
#include "app/editor.h"
#include "editor_fixture.h"
#include "small_meshes.h"

namespace app {
namespace {

using test::fresh_folder;
using test::kViewport;
using test::write_torus;

// Reads in the background until the question or the document is there.
void read_in_background(Editor& editor, const std::string& path) {
    editor.request_open(path);
    while (editor.file_task() != nullptr) {
        editor.update(std::chrono::milliseconds(5));
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
}

// An editor that offers a cage above `threshold` triangles.
EditorOptions offering_above(std::size_t threshold) {
    EditorOptions options;
    options.viewport = kViewport;
    options.dense_mesh_triangles = threshold;
    return options;
}

TEST(EditorDenseMesh, OpeningADenseMeshAsksAndTheBaseMeshAnswerOpensItAsBefore) {
    const std::string file = write_torus(fresh_folder("dense_question"), 500, 250);  // 250,000 triangles
    Editor editor(kViewport);
    read_in_background(editor, file);
    ASSERT_EQ(editor.pending(), Pending::DenseMesh) << editor.message();
    EXPECT_EQ(editor.pending_path(), file);
    EXPECT_EQ(editor.dense_triangles(), 250000u);
    EXPECT_EQ(editor.smallest_cage_triangles(), 14u);  // a torus
    EXPECT_EQ(editor.cage_triangles(), 1250u);         // 0.5%
    EXPECT_EQ(editor.document().mesh().num_faces(), 0u) << "nothing opened before the answer";
    EXPECT_EQ(editor.message().find("opening"), std::string::npos) << "the reading is over: " << editor.message();

    editor.answer_dense_mesh(false);
    EXPECT_EQ(editor.pending(), Pending::None);
    EXPECT_EQ(editor.document().path(), file);
    EXPECT_FALSE(editor.document().dirty());
    EXPECT_EQ(editor.document().mesh().base().num_faces(), 250000u);
    EXPECT_EQ(editor.document().mesh().base().detail(), nullptr);
}

TEST(EditorDenseMesh, BelowTheThresholdNothingIsAsked) {
    const std::string file = write_torus(fresh_folder("dense_small"), 40, 20);
    Editor editor(kViewport);
    read_in_background(editor, file);
    EXPECT_EQ(editor.pending(), Pending::None);
    EXPECT_EQ(editor.document().mesh().base().num_faces(), 1600u);
}

TEST(EditorDenseMesh, TheCageKeepsTheDetailAndIsAnUnsavedDocumentThatSaveAsksANameFor) {
    const std::filesystem::path folder = fresh_folder("dense_cage");
    const std::string file = write_torus(folder, 80, 40);  // 6,400 triangles
    Editor editor(offering_above(5000));
    read_in_background(editor, file);
    ASSERT_EQ(editor.pending(), Pending::DenseMesh);
    EXPECT_EQ(editor.cage_triangles(), 32u);
    editor.cage_triangles() = 100;
    editor.answer_dense_mesh(true);
    ASSERT_NE(editor.file_task(), nullptr);
    EXPECT_EQ(editor.file_task()->kind(), BackgroundTask::Kind::Remesh);
    EXPECT_NE(editor.file_task()->status().find("Making a cage of " + file), std::string::npos) << editor.file_task()->status();
    editor.finish_work();
    ASSERT_EQ(editor.pending(), Pending::None) << editor.pending_message();

    const rgb::Mesh& mesh = editor.document().mesh();
    ASSERT_NE(mesh.base().detail(), nullptr) << editor.message();
    EXPECT_LE(mesh.base().num_faces(), 100u);
    EXPECT_GE(mesh.base().num_faces(), 30u);
    EXPECT_EQ(mesh.num_faces(), mesh.base().num_faces()) << "level 0";
    EXPECT_TRUE(editor.document().path().empty()) << "never the input's name";
    EXPECT_TRUE(editor.document().dirty());
    EXPECT_EQ(editor.suggested_path(), (folder / "torus_6400_cage.obj").string());
    EXPECT_NE(editor.message().find("made a cage of"), std::string::npos) << editor.message();

    // Ctrl+S asks where; saving there makes it the document's file.
    editor.key_pressed(Key::S, {.ctrl = true});
    EXPECT_EQ(editor.take_browse_request(), Editor::Browse::SaveAs);
    EXPECT_TRUE(editor.save_as(editor.suggested_path()));
    EXPECT_EQ(editor.document().path(), (folder / "torus_6400_cage.obj").string());
    EXPECT_TRUE(editor.suggested_path().empty());

    // The brush paints level of detail of the dense mesh: refining goes back up to its detail.
    editor.brush().mode = BrushMode::Refine;
    editor.brush().target_level = 2;
    editor.brush().radius_px = 200.0f;
    editor.frame_mesh();
    glm::vec2 on_surface{-1.0f};
    for (float x = 0.05f; x < 0.95f && on_surface.x < 0.0f; x += 0.05f) {
        editor.mouse_moved({x * kViewport.x, 0.5f * kViewport.y});
        if (editor.cursor_hit()) on_surface = {x * kViewport.x, 0.5f * kViewport.y};
    }
    ASSERT_GE(on_surface.x, 0.0f) << "the torus is in view";
    editor.mouse_pressed(MouseButton::Left, {});
    editor.mouse_moved(on_surface + glm::vec2(10.0f, 0.0f));
    editor.mouse_released(MouseButton::Left);
    editor.finish_work();
    EXPECT_GT(editor.document().mesh().num_faces(), editor.document().mesh().base().num_faces());
    EXPECT_NE(editor.document().mesh().base().detail(), nullptr);
}

TEST(EditorDenseMesh, EscWhileTheCageIsMadeLeavesTheDocumentAsItWas) {
    const std::string file = write_torus(fresh_folder("dense_stop"), 100, 100);  // 20,000 triangles
    Editor editor(offering_above(5000));
    ASSERT_TRUE(editor.open(test::asset_path("default.obj")));
    const std::size_t faces = editor.document().mesh().num_faces();
    read_in_background(editor, file);
    ASSERT_EQ(editor.pending(), Pending::DenseMesh);
    editor.answer_dense_mesh(true);
    ASSERT_NE(editor.file_task(), nullptr);
    editor.update(std::chrono::milliseconds(5));
    EXPECT_FALSE(editor.file_task()->done()) << "Esc comes while the cage is being made";
    editor.key_pressed(Key::Escape, {});
    EXPECT_EQ(editor.file_task(), nullptr);
    EXPECT_NE(editor.message().find("stopped making the cage"), std::string::npos) << editor.message();
    EXPECT_NE(editor.message().find("nothing changed"), std::string::npos) << editor.message();
    editor.finish_work();
    EXPECT_EQ(editor.document().path(), test::asset_path("default.obj"));
    EXPECT_EQ(editor.document().mesh().num_faces(), faces);
    EXPECT_EQ(editor.document().mesh().base().detail(), nullptr);
    EXPECT_FALSE(editor.document().dirty());
    // The remesh stops at its next progress report instead of running on.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (BackgroundTask::running() > 0 && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    EXPECT_EQ(BackgroundTask::running(), 0);
}

TEST(EditorDenseMesh, ACageBelowTheTopologysSmallestIsRefusedInADialog) {
    const std::string file = write_torus(fresh_folder("dense_refused"), 80, 40);
    Editor editor(offering_above(5000));
    read_in_background(editor, file);
    ASSERT_EQ(editor.pending(), Pending::DenseMesh);
    editor.cage_triangles() = 6;
    editor.answer_dense_mesh(true);
    EXPECT_EQ(editor.pending(), Pending::RemeshFailed);
    EXPECT_NE(editor.pending_message().find("14"), std::string::npos) << editor.pending_message();
    editor.answer_pending(false);
    EXPECT_EQ(editor.pending(), Pending::None);
    EXPECT_EQ(editor.document().mesh().num_faces(), 0u);
}

TEST(EditorDenseMesh, EscOnTheQuestionOpensNothing) {
    const std::string file = write_torus(fresh_folder("dense_cancel"), 80, 40);
    Editor editor(offering_above(5000));
    read_in_background(editor, file);
    ASSERT_EQ(editor.pending(), Pending::DenseMesh);
    editor.key_pressed(Key::Escape, {});
    EXPECT_EQ(editor.pending(), Pending::None);
    EXPECT_EQ(editor.document().mesh().num_faces(), 0u);
}

}  // namespace
}  // namespace app
