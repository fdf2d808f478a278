// Whole-mesh jobs cancelled part way, and the undo history's memory bound as the editor uses it.
#include <chrono>
#include <string>

#include <gtest/gtest.h>

#include "editor_fixture.h"
#include "io/mesh_state_compare.h"
#include "rgb/invariants.h"
#include "rgb/state.h"

namespace app {
namespace {

class EditorJobs : public test::EditorFixture {
protected:
    void SetUp() override { ASSERT_TRUE(editor.open(test::asset_path("bunny.obj"))) << editor.message(); }
};

// Esc stops a running job; the work done so far stays, as one step that undo takes back whole and
// redo brings back exactly.
TEST_F(EditorJobs, EscKeepsAPartialJobAsOneUndoStep) {
    const rgb::MeshState original = rgb::capture_state(editor.document().mesh());
    const std::size_t faces = editor.document().mesh().num_faces();
    // Automatic LOD works in small pieces (a flood fill's first batch already spreads over the whole
    // mesh); slices of a microsecond do a piece each: stop after a few.
    editor.start_auto_lod();
    ASSERT_NE(editor.job(), nullptr);
    for (int i = 0; i < 3; ++i) editor.update(std::chrono::microseconds(1));
    ASSERT_NE(editor.job(), nullptr) << "the job finished before it could be cancelled";
    const std::size_t partial_faces = editor.document().mesh().num_faces();
    ASSERT_GT(partial_faces, faces);
    const std::string label = editor.job()->label();

    editor.key_pressed(Key::Escape, {});
    EXPECT_EQ(editor.job(), nullptr);
    EXPECT_EQ(editor.document().mesh().num_faces(), partial_faces) << "cancelling keeps the work done";
    EXPECT_TRUE(rgb::check_invariants(editor.document().mesh()).ok());
    EXPECT_TRUE(editor.document().dirty());
    EXPECT_EQ(editor.document().history().undo_steps(), 1u);
    EXPECT_EQ(editor.document().history().undo_label(), label);
    const rgb::MeshState partial = rgb::capture_state(editor.document().mesh());

    editor.key_pressed(Key::Z, {.ctrl = true});
    rgbio::test::expect_identical(rgb::capture_state(editor.document().mesh()), original);
    EXPECT_FALSE(editor.document().history().can_undo());
    editor.key_pressed(Key::Y, {.ctrl = true});
    rgbio::test::expect_identical(rgb::capture_state(editor.document().mesh()), partial);
}

// With a bound too small for any snapshot the editor still edits, but keeps no step to undo.
TEST_F(EditorJobs, UndoMemoryBoundLimitsTheStepsKept) {
    editor.document().history().set_byte_bound(0);
    editor.start_flood_fill(1);
    while (editor.job() != nullptr) editor.update();
    EXPECT_EQ(editor.document().mesh().num_faces(), 4 * 3674u);
    EXPECT_TRUE(editor.document().dirty());
    EXPECT_FALSE(editor.document().history().can_undo());
    EXPECT_EQ(editor.document().history().bytes(), 0u);
    EXPECT_FALSE(editor.undo());

    // With room again, two edits leave two steps; a bound just below them forgets the older.
    editor.document().history().set_byte_bound(std::size_t{1} << 30);
    editor.start_flood_fill(2);
    while (editor.job() != nullptr) editor.update();
    editor.start_flood_fill(0);
    while (editor.job() != nullptr) editor.update();
    ASSERT_EQ(editor.document().history().undo_steps(), 2u);
    editor.document().history().set_byte_bound(editor.document().history().bytes() - 1);
    EXPECT_EQ(editor.document().history().undo_steps(), 1u);
    EXPECT_EQ(editor.document().history().undo_label(), "set all to level 0");
    ASSERT_TRUE(editor.undo());
    EXPECT_EQ(editor.document().mesh().num_faces(), 16 * 3674u) << "back to level 2 everywhere";
}

}  // namespace
}  // namespace app
