// Detail by size, accuracy and view in the editor (editor_detail.cpp), scripted without X or GL: the
// view-dependent mode follows the camera, settles, and freezing it (button, Esc, or saving) leaves one
// undo step that gives the mesh before the mode back; the whole-mesh tolerance edit gives the command
// line's mesh and replays from the session's script.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iterator>
#include <string>
#include <variant>
#include <vector>

#include <glm/geometric.hpp>

#include <gtest/gtest.h>

#include "app/editor.h"
#include "editor_fixture.h"
#include "io/mesh_file.h"
#include "io/script/detail_edit.h"
#include "io/script/lod_script.h"
#include "render/camera.h"
#include "rgb/lod/lod_criteria.h"
#include "rgb/lod/screen_detail.h"
#include "rgb/mesh/invariants.h"
#include "rgb/mesh/mesh.h"
#include "rgb/values/loop_geometry.h"
#include "support/same_mesh.h"

namespace app {
namespace {

using test::kViewport;
using test::bunny_path;

// The tolerances (% of the bunny's size) of the whole-mesh edit compared with the command line's and
// of the tolerance stroke. Under the sanitizers (test code at -O0 over an instrumented core, where
// these two tests were a seventh of the editor tests) three times coarser: fewer triangles, the same
// checks. (The progress test keeps its tolerance: a coarser edit ends within a frame or two.)
#if defined(__SANITIZE_ADDRESS__)
constexpr double kWholeMeshTolerance = 0.9, kStrokeTolerance = 0.3;
constexpr const char* kWholeMeshToleranceLabel = "tolerance 0.9%";
#else
constexpr double kWholeMeshTolerance = 0.3, kStrokeTolerance = 0.1;
constexpr const char* kWholeMeshToleranceLabel = "tolerance 0.3%";
#endif

class EditorDetail : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(editor.open(bunny_path())) << editor.message();
        editor.detail_settings().view_pixels = 12.0;
    }
    const rgb::Mesh& mesh() const { return editor.document().mesh(); }
    // The largest screen value (rgb/lod/screen_detail.h) of a green edge, for the editor's camera now.
    double longest_edge_on_screen() const {
        const rgb::ScreenCriterion criterion(mesh().shared_base(), render::screen_view(editor.camera().camera(), kViewport));
        const rgb::EdgeValue value = criterion.edge_value();
        double longest = 0.0;
        for (rgb::FaceId f : mesh().faces())
            for (int i = 0; i < 3; ++i) {
                const rgb::HalfedgeId h = rgb::Mesh::halfedge(f, i);
                if (mesh().edge_type(h).colour != rgb::Colour::Green) continue;
                longest = std::max(longest, value(mesh().address(mesh().from_vertex(h)), mesh().address(mesh().to_vertex(h))));
            }
        return longest;
    }
    Editor editor{kViewport};
};

TEST_F(EditorDetail, ViewDependentModeFollowsTheCameraAndFreezesIntoOneUndoStep) {
    const rgb::Mesh original = mesh();
    editor.start_view_lod();
    ASSERT_NE(editor.view_lod(), nullptr);
    editor.finish_work();  // returns once settled for the camera
    ASSERT_NE(editor.view_lod(), nullptr) << "the mode runs until frozen";
    EXPECT_TRUE(editor.view_lod()->converged());
    EXPECT_GT(mesh().num_faces(), original.num_faces());
    EXPECT_LE(longest_edge_on_screen(), 12.0);

    const rgb::Mesh first_view = mesh();
    editor.camera().orbit({300.0f, 0.0f});
    editor.update(std::chrono::milliseconds(1));
    EXPECT_FALSE(editor.view_lod()->converged()) << "a new camera is judged anew";
    editor.finish_work();
    EXPECT_FALSE(rgbtest::same_mesh(first_view, mesh()));
    EXPECT_LE(longest_edge_on_screen(), 12.0);
    EXPECT_GT(editor.view_lod()->stats().removals, 0u) << "what the first view alone needed went";

    // Another frame with the camera still changes nothing.
    const rgb::Mesh settled = mesh();
    editor.update(std::chrono::milliseconds(5));
    EXPECT_TRUE(rgbtest::same_mesh(settled, mesh()));

    editor.freeze_view_lod();
    EXPECT_EQ(editor.view_lod(), nullptr);
    EXPECT_EQ(editor.job(), nullptr);
    EXPECT_TRUE(rgbtest::same_mesh(settled, mesh())) << "freezing keeps the mesh";
    ASSERT_EQ(editor.document().history().undo_steps(), 1u);
    EXPECT_EQ(editor.document().history().undo_label(), "view-dependent LOD");
    EXPECT_TRUE(rgb::check_invariants(mesh()).ok());
    ASSERT_TRUE(editor.undo()) << editor.message();
    EXPECT_TRUE(rgbtest::same_mesh(original, mesh()));
    ASSERT_TRUE(editor.redo()) << editor.message();
    EXPECT_TRUE(rgbtest::same_mesh(settled, mesh()));
}

TEST_F(EditorDetail, EscAndSavingFreezeTheMode) {
    editor.start_view_lod();
    editor.finish_work();
    editor.key_pressed(Key::Escape, {});
    EXPECT_EQ(editor.view_lod(), nullptr);
    EXPECT_EQ(editor.document().history().undo_steps(), 1u);

    editor.start_view_lod();
    editor.camera().orbit({-200.0f, 50.0f});
    editor.finish_work();
    const rgb::Mesh shown = mesh();
    const std::filesystem::path saved = std::filesystem::path(::testing::TempDir()) / "editor_detail_frozen.obj";
    std::filesystem::remove(saved);
    editor.request_save_as(saved.string());
    editor.finish_work();
    EXPECT_EQ(editor.view_lod(), nullptr);
    EXPECT_EQ(editor.document().history().undo_steps(), 2u);
    EXPECT_FALSE(editor.message_is_error()) << editor.message();
    EXPECT_TRUE(rgbtest::same_mesh(shown, rgbio::load_mesh(saved.string())));
}

TEST_F(EditorDetail, WholeMeshToleranceGivesTheCommandLinesMesh) {
    editor.detail_settings().criterion = rgbio::DetailCriterion::Tolerance;
    editor.detail_settings().amount = {kWholeMeshTolerance, true};
    editor.start_detail_edit();
    editor.finish_work();
    rgb::Mesh expected = rgbio::load_mesh(bunny_path());
    rgbio::DetailEdit edit;
    edit.criterion = rgbio::DetailCriterion::Tolerance;
    edit.amount = {kWholeMeshTolerance, true};
    rgbio::apply_detail_edit(expected, edit, 1'000'000);
    EXPECT_TRUE(rgbtest::same_mesh(expected, mesh()));
    ASSERT_EQ(editor.document().history().undo_steps(), 1u);
    EXPECT_EQ(editor.document().history().undo_label(), kWholeMeshToleranceLabel);
}

// The status line's bar moves while the edit runs: the progress rises through many values between
// 0 and 1 over the frames, never back.
TEST_F(EditorDetail, WholeMeshEditReportsItsProgressAsItGoes) {
    editor.detail_settings().criterion = rgbio::DetailCriterion::Tolerance;
    editor.detail_settings().amount = {0.2, true};
    editor.start_detail_edit();
    std::vector<float> shown;
    while (editor.job() != nullptr) {
        shown.push_back(editor.job()->progress());
        editor.update(std::chrono::microseconds(500));
    }
    ASSERT_EQ(editor.document().history().undo_steps(), 1u) << editor.message();
    EXPECT_TRUE(std::is_sorted(shown.begin(), shown.end()));
    std::vector<float> between;
    std::copy_if(shown.begin(), shown.end(), std::back_inserter(between), [](float p) { return p > 0.0f && p < 1.0f; });
    between.erase(std::unique(between.begin(), between.end()), between.end());
    EXPECT_GE(between.size(), 5u) << "of " << shown.size() << " frames";
}

// Paints a short stroke (set, 50 px) with the brush's target as set and waits for it; returns the
// session's script lines after checking that they replay, on the file as opened, to the editor's mesh.
std::vector<rgbio::ScriptLine> paint_and_replay(Editor& editor, const std::string& name) {
    editor.brush().radius_px = 50.0f;
    editor.brush().mode = BrushMode::Set;
    const glm::vec2 from{0.45f * kViewport.x, 0.5f * kViewport.y}, to{0.55f * kViewport.x, 0.55f * kViewport.y};
    editor.mouse_moved(from);
    editor.mouse_pressed(MouseButton::Left, {});
    for (int i = 1; i <= 4; ++i) editor.mouse_moved(from + (to - from) * (static_cast<float>(i) / 4.0f));
    editor.mouse_released(MouseButton::Left);
    editor.finish_work();
    EXPECT_EQ(editor.document().history().undo_steps(), 1u);
    const std::filesystem::path script = std::filesystem::path(::testing::TempDir()) / name;
    EXPECT_TRUE(editor.save_strokes(script.string())) << editor.message();
    const std::vector<rgbio::ScriptLine> lines = rgbio::read_lod_script(script.string());
    EXPECT_GE(lines.size(), 1u);
    rgb::Mesh replayed = rgbio::load_mesh(bunny_path());
    rgbio::ScriptRunner runner;
    for (const rgbio::ScriptLine& line : lines) {
        const auto* edit = std::get_if<rgbio::DetailEdit>(&line.edit);
        EXPECT_TRUE(edit != nullptr && edit->sphere && edit->kind == rgb::RequestKind::Set) << line.text;
        runner.run(replayed, line);
    }
    EXPECT_TRUE(rgbtest::same_mesh(replayed, editor.document().mesh()));
    EXPECT_GT(editor.document().mesh().num_faces(), rgbio::load_mesh(bunny_path()).num_faces());
    return lines;
}

// A detail-size stroke: its dabs are saved as max-edge lines with their balls, which replay to the
// same mesh, and in each ball no green edge is longer than the size (checked edge by edge from the
// edges' ends in the uniform mesh of their level).
TEST_F(EditorDetail, DetailSizeStrokesHoldTheSizeAndReplayFromTheirScript) {
    BrushSettings& brush = editor.brush();
    brush.target = BrushSettings::Target::DetailSize;
    brush.detail_unit = RadiusUnit::ScreenPixels;
    brush.detail_px = 8.0f;
    std::size_t checked = 0;
    for (const rgbio::ScriptLine& line : paint_and_replay(editor, "detail_stroke.lod")) {
        const auto& edit = std::get<rgbio::DetailEdit>(line.edit);
        EXPECT_EQ(edit.criterion, rgbio::DetailCriterion::MaxEdge);
        for (rgb::FaceId f : mesh().faces())
            for (int i = 0; i < 3; ++i) {
                const rgb::HalfedgeId h = rgb::Mesh::halfedge(f, i);
                const rgb::EdgeType type = mesh().edge_type(h);
                const rgb::VertexId a = mesh().from_vertex(h), b = mesh().to_vertex(h);
                if (type.colour != rgb::Colour::Green ||
                    !rgb::segment_meets_sphere(mesh().base_space_position(a), mesh().base_space_position(b), *edit.sphere))
                    continue;
                ++checked;
                EXPECT_LE(glm::distance(rgb::control_point(mesh(), a, type.level), rgb::control_point(mesh(), b, type.level)),
                          edit.amount.value);
            }
    }
    EXPECT_GT(checked, 0u);
}

// A tolerance stroke in world units: saved as tolerance lines, and every vertex in a dab's ball is
// shown within the tolerance of its limit point.
TEST_F(EditorDetail, ToleranceStrokesHoldTheToleranceAndReplayFromTheirScript) {
    BrushSettings& brush = editor.brush();
    brush.target = BrushSettings::Target::Tolerance;
    brush.detail_unit = RadiusUnit::World;
    const double tolerance = rgbio::world_amount(mesh(), {kStrokeTolerance, true});
    brush.detail_world = static_cast<float>(tolerance);
    std::size_t checked = 0;
    for (const rgbio::ScriptLine& line : paint_and_replay(editor, "tolerance_stroke.lod")) {
        const auto& edit = std::get<rgbio::DetailEdit>(line.edit);
        EXPECT_EQ(edit.criterion, rgbio::DetailCriterion::Tolerance);
        EXPECT_EQ(edit.amount.value, static_cast<double>(static_cast<float>(tolerance)));
        for (rgb::VertexId v : mesh().vertices()) {
            if (glm::distance(mesh().base_space_position(v), edit.sphere->centre) > edit.sphere->radius) continue;
            ++checked;
            EXPECT_LE(glm::distance(rgb::displayed_position(mesh(), v), rgb::limit_position(mesh(), v)), edit.amount.value);
        }
    }
    EXPECT_GT(checked, 0u);
}

}  // namespace
}  // namespace app
