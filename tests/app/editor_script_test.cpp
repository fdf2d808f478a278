// The editor scripted through its own input layer, without X or GL: open the bunny, paint a stroke
// across it, undo, redo, save, and check the file.
#include <filesystem>
#include <fstream>
#include <vector>

#include <glm/geometric.hpp>

#include <gtest/gtest.h>

#include "editor_fixture.h"
#include "io/mesh_file.h"
#include "rgb/lod/requests.h"
#include "rgb/mesh/invariants.h"
#include "rgb/mesh/state.h"
#include "stroke_support.h"
#include "support/same_mesh.h"
#include "support/same_slots.h"
#include "support/set_level.h"

namespace app {
namespace {

using test::bunny_path;

using test::EditorFixture;
using test::kViewport;

class EditorScript : public EditorFixture {
protected:
    void SetUp() override {
        ASSERT_TRUE(editor.open(bunny_path())) << editor.message();
        editor.brush().mode = BrushMode::Refine;
        editor.brush().target_level = 3;
        editor.brush().radius_px = 30.0f;
        editor.brush().falloff = 0.0f;
    }

    // Where the stroke's path meets the surface, before painting changes it.
    std::vector<glm::dvec3> surface_points(glm::vec2 from, glm::vec2 to, int count) {
        std::vector<glm::dvec3> points;
        for (int i = 0; i <= count; ++i) {
            editor.mouse_moved(from + (to - from) * (float(i) / float(count)));
            if (auto hit = editor.cursor_hit()) points.push_back(hit->point);
        }
        return points;
    }

    const glm::vec2 from{0.4f * kViewport.x, 0.55f * kViewport.y};
    const glm::vec2 to{0.6f * kViewport.x, 0.55f * kViewport.y};
};

TEST_F(EditorScript, StrokeUndoRedoSaveRoundTrip) {
    const std::vector<glm::dvec3> path = surface_points(from, to, 20);
    ASSERT_EQ(path.size(), 21u) << "the stroke must cross the framed bunny";
    const rgb::Mesh original = editor.document().mesh();
    const std::size_t original_faces = editor.document().mesh().num_faces();
    const double near_radius = editor.brush_world_radius(path.front());
    const std::size_t original_near = test::faces_near(editor.document().mesh(), path, near_radius);

    stroke(from, to, 3);  // three samples for a long stroke: interpolation must fill the gaps
    const rgb::Mesh painted = editor.document().mesh();
    EXPECT_GT(editor.document().mesh().num_faces(), original_faces);
    EXPECT_TRUE(editor.document().dirty());
    EXPECT_EQ(editor.window_title(), "bunny.obj* - rgbsub");
    EXPECT_GT(editor.timing().dabs, 10u);
    EXPECT_TRUE(rgb::check_invariants(editor.document().mesh()).ok());
    // Every point of the path got refined, not just the mouse samples.
    const std::size_t painted_near = test::faces_near(editor.document().mesh(), path, near_radius);
    for (const glm::dvec3& p : path)
        EXPECT_GT(test::faces_near(editor.document().mesh(), std::span(&p, 1), 0.5 * near_radius),
                  test::faces_near(original, std::span(&p, 1), 0.5 * near_radius));

    editor.key_pressed(Key::Z, {.ctrl = true});
    EXPECT_EQ(editor.document().mesh().num_faces(), original_faces);
    EXPECT_TRUE(rgbtest::same_slots(editor.document().mesh(), original));

    editor.key_pressed(Key::Z, {.shift = true, .ctrl = true});
    EXPECT_TRUE(rgbtest::same_slots(editor.document().mesh(), painted));

    const std::filesystem::path saved = std::filesystem::path(::testing::TempDir()) / "editor_script_saved.obj";
    ASSERT_TRUE(editor.save_as(saved.string())) << editor.message();
    EXPECT_FALSE(editor.document().dirty());

    const rgb::Mesh reloaded = rgbio::load_mesh(saved.string());
    const rgb::InvariantReport report = rgb::check_invariants(reloaded);
    EXPECT_TRUE(report.ok()) << (report.ok() ? "" : report.violations.front());
    EXPECT_TRUE(rgbtest::same_mesh(reloaded, painted));
    EXPECT_EQ(test::faces_near(reloaded, path, near_radius), painted_near);
    EXPECT_GT(painted_near, original_near);
}

// Shift with the refine brush coarsens to the base level whatever the target, so it visibly removes
// what refining added, even with the target the stroke was painted at.
TEST_F(EditorScript, ShiftInvertsRefineIntoCoarsen) {
    const std::size_t original_faces = editor.document().mesh().num_faces();
    stroke(from, to, 3);
    const std::size_t refined_faces = editor.document().mesh().num_faces();
    ASSERT_GT(refined_faces, original_faces);
    stroke(from, to, 3, {.shift = true});
    EXPECT_LT(editor.document().mesh().num_faces(), refined_faces);
    EXPECT_TRUE(rgb::check_invariants(editor.document().mesh()).ok());
    EXPECT_EQ(editor.document().history().undo_steps(), 2u);

    // What Shift means (README): the refine brush becomes the coarsen brush to level 0. The same two
    // strokes in a second editor, the second with that brush and no Shift, give the identical mesh.
    Editor other{kViewport};
    ASSERT_TRUE(other.open(bunny_path())) << other.message();
    other.brush() = editor.brush();
    auto drag = [&](Modifiers mods) {
        other.mouse_moved(from);
        other.mouse_pressed(MouseButton::Left, mods);
        for (int i = 1; i <= 3; ++i) other.mouse_moved(from + (to - from) * (float(i) / 3.0f));
        other.mouse_released(MouseButton::Left);
        other.finish_work();
    };
    drag({});
    ASSERT_EQ(other.document().mesh().num_faces(), refined_faces);
    other.brush().mode = BrushMode::Coarsen;
    other.brush().target_level = 0;
    drag({});
    EXPECT_TRUE(rgbtest::same_mesh(other.document().mesh(), editor.document().mesh()));
}

TEST_F(EditorScript, NavigationDragsDoNotPaint) {
    const std::size_t original_faces = editor.document().mesh().num_faces();
    const glm::vec3 eye = editor.camera().camera().eye();
    stroke(from, to, 5, {.alt = true});  // Alt+left orbits
    EXPECT_NE(editor.camera().camera().eye(), eye);
    editor.mouse_pressed(MouseButton::Right, {});
    editor.mouse_moved(from);
    editor.mouse_released(MouseButton::Right);
    EXPECT_EQ(editor.document().mesh().num_faces(), original_faces);
    EXPECT_FALSE(editor.document().history().can_undo());
}

// The wheel zooms towards the cursor: the surface point under it stays under it.
TEST_F(EditorScript, ZoomKeepsThePointUnderTheCursor) {
    const glm::vec2 px{0.3f * kViewport.x, 0.5f * kViewport.y};
    editor.mouse_moved(px);
    const std::optional<SurfaceHit> before = editor.cursor_hit();
    ASSERT_TRUE(before.has_value());
    const float distance = editor.camera().camera().distance;
    editor.scrolled(3.0f);
    EXPECT_LT(editor.camera().camera().distance, distance);
    const std::optional<SurfaceHit> after = editor.cursor_hit();
    ASSERT_TRUE(after.has_value());
    EXPECT_LT(glm::distance(after->point, before->point), 1e-3 * static_cast<double>(distance));
}

TEST_F(EditorScript, MinusAndEqualStepTheTargetLevel) {
    editor.brush().target_level = 3;
    editor.key_pressed(Key::Equal, {});
    EXPECT_EQ(editor.brush().target_level, 4);
    for (int i = 0; i < 10; ++i) editor.key_pressed(Key::Minus, {});
    EXPECT_EQ(editor.brush().target_level, 0);
    for (int i = 0; i < 20; ++i) editor.key_pressed(Key::Equal, {});
    EXPECT_EQ(editor.brush().target_level, kMaxBrushLevel);
}

TEST_F(EditorScript, StrokeOffTheMeshLeavesNoUndoStep) {
    stroke({5.0f, 5.0f}, {40.0f, 5.0f}, 4);
    EXPECT_FALSE(editor.document().history().can_undo());
    EXPECT_FALSE(editor.document().dirty());
}

TEST_F(EditorScript, FloodFillRunsInSlicesAndUndoes) {
    const rgb::Mesh original = editor.document().mesh();
    rgb::Mesh whole = original;
    rgbtest::set_level(whole, 2);
    editor.start_flood_fill(2);
    ASSERT_NE(editor.job(), nullptr);
    int frames = 0;
    while (editor.job() != nullptr && frames < 100000) {
        editor.update(std::chrono::microseconds(200));
        ++frames;
    }
    EXPECT_GT(frames, 3) << "a flood fill must give the window frames while it works";
    EXPECT_EQ(editor.document().mesh().num_faces(), 16 * original.num_faces());
    EXPECT_TRUE(rgbtest::same_mesh(editor.document().mesh(), whole));
    EXPECT_TRUE(editor.undo());
    editor.finish_work();  // the undo of a 58k-triangle fill crosses over frames too (history_job.h)
    EXPECT_TRUE(rgbtest::same_slots(editor.document().mesh(), original));
}

TEST_F(EditorScript, SampleLevelReadsTheFaceUnderTheCursor) {
    stroke(from, to, 3);
    editor.brush().target_level = 0;
    editor.mouse_moved(0.5f * (from + to));
    ASSERT_TRUE(editor.sample_level_under_cursor());
    EXPECT_EQ(editor.brush().target_level, editor.document().mesh().level(editor.cursor_hit()->face));
    EXPECT_GE(editor.brush().target_level, 2);
}

TEST_F(EditorScript, QuittingWithUnsavedChangesAsksFirst) {
    stroke(from, to, 3);
    ASSERT_TRUE(editor.document().dirty());
    editor.key_pressed(Key::Q, {.ctrl = true});
    EXPECT_EQ(editor.pending(), Pending::DiscardForQuit);
    EXPECT_FALSE(editor.should_quit());
    editor.key_pressed(Key::Escape, {});  // Esc answers no
    EXPECT_EQ(editor.pending(), Pending::None);
    EXPECT_FALSE(editor.should_quit());
    editor.key_pressed(Key::Q, {.ctrl = true});
    editor.answer_pending(true);
    EXPECT_TRUE(editor.should_quit());
}

TEST_F(EditorScript, QuittingAfterSavingDoesNotAsk) {
    stroke(from, to, 3);
    const std::filesystem::path saved = std::filesystem::path(::testing::TempDir()) / "editor_quit_saved.obj";
    ASSERT_TRUE(editor.save_as(saved.string())) << editor.message();
    editor.key_pressed(Key::Q, {.ctrl = true});
    EXPECT_EQ(editor.pending(), Pending::None);
    EXPECT_TRUE(editor.should_quit());
}

TEST_F(EditorScript, UnsavedChangesAskBeforeQuitOrOpen) {
    stroke(from, to, 3);
    editor.request_quit();
    EXPECT_EQ(editor.pending(), Pending::DiscardForQuit);
    EXPECT_FALSE(editor.should_quit());
    editor.answer_pending(false);
    EXPECT_FALSE(editor.should_quit());
    const std::size_t painted = editor.document().mesh().num_faces();
    // The file is read first (in the background), and only then the question comes.
    editor.request_open(bunny_path());
    editor.finish_work();
    EXPECT_EQ(editor.pending(), Pending::DiscardForOpen);
    EXPECT_EQ(editor.document().mesh().num_faces(), painted);
    editor.answer_pending(true);
    EXPECT_LT(editor.document().mesh().num_faces(), painted);
    EXPECT_FALSE(editor.document().dirty());
}

TEST_F(EditorScript, AFileThatCannotBeOpenedAsksNothingAndTheMeshStays) {
    stroke(from, to, 3);
    const rgb::Mesh painted = editor.document().mesh();
    const std::filesystem::path bad = std::filesystem::path(::testing::TempDir()) / "editor_bad_open.obj";
    { std::ofstream(bad) << "v 0 0 0\nv 1 0 0\nf 1 2 7\n"; }
    const std::uint64_t failures = editor.open_failures();
    editor.request_open(bad.string());
    editor.finish_work();
    EXPECT_EQ(editor.pending(), Pending::None);
    EXPECT_TRUE(editor.message_is_error());
    EXPECT_NE(editor.message().find("editor_bad_open.obj:3"), std::string::npos) << editor.message();
    EXPECT_EQ(editor.open_failures(), failures + 1);
    EXPECT_TRUE(rgbtest::same_slots(editor.document().mesh(), painted));
    EXPECT_EQ(editor.document().path(), bunny_path());
}

TEST_F(EditorScript, LoadErrorsBecomeMessages) {
    const std::filesystem::path bad = std::filesystem::path(::testing::TempDir()) / "editor_bad.obj";
    { std::ofstream(bad) << "v 0 0 0\nv 1 0 0\nf 1 2 7\n"; }
    const std::size_t faces = editor.document().mesh().num_faces();
    EXPECT_FALSE(editor.open(bad.string()));
    EXPECT_TRUE(editor.message_is_error());
    EXPECT_NE(editor.message().find("editor_bad.obj:3"), std::string::npos) << editor.message();
    EXPECT_EQ(editor.document().mesh().num_faces(), faces);
}

TEST_F(EditorScript, SaveAsOverAnotherFileAsksFirst) {
    const std::filesystem::path other = std::filesystem::path(::testing::TempDir()) / "editor_other.obj";
    { std::ofstream(other) << "keep me\n"; }
    editor.request_save_as(other.string());
    EXPECT_EQ(editor.pending(), Pending::Overwrite);
    editor.answer_pending(false);
    EXPECT_EQ(std::filesystem::file_size(other), 8u);
    editor.request_save_as(other.string());
    editor.answer_pending(true);
    editor.finish_work();
    EXPECT_GT(std::filesystem::file_size(other), 8u);
    EXPECT_EQ(editor.document().path(), other.string());
}

}  // namespace
}  // namespace app
