// The editor's work over frames, scripted without X or GL: a large dab spreads over frames coarse to
// fine with the display following, Esc keeps what is done as one undo step (a stroke's or automatic
// LOD's), automatic LOD to a budget is the mesh of a script's `budget` line, undo and redo give back
// every slot across a cancelled job, the undo memory bound as the
// editor uses it, the brush paints only what faces the viewer unless told to paint through, and the
// session's strokes saved as a script replay to the identical mesh, whole or in two halves with a
// save and reload between.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/editor.h"
#include "editor_fixture.h"
#include "io/mesh_file.h"
#include "io/script/lod_script.h"
#include "rgb/lod/lod_driver.h"
#include "rgb/mesh/invariants.h"
#include "rgb/values/loop_geometry.h"
#include "rgb/values/surface_error.h"
#include "support/same_mesh.h"
#include "support/same_slots.h"

namespace app {
namespace {

using test::kViewport;
using test::bunny_path;

constexpr glm::vec2 kCentre{0.5f * kViewport.x, 0.55f * kViewport.y};

std::filesystem::path scratch(const std::string& name) { return std::filesystem::path(::testing::TempDir()) / name; }

// Runs `script` (text) on `mesh` line by line.
void replay(rgb::Mesh& mesh, const std::string& script) {
    rgbio::ScriptRunner runner;
    for (const rgbio::ScriptLine& line : rgbio::parse_lod_script(script, "session")) runner.run(mesh, line);
}

class EditorJobs : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(editor.open(bunny_path())) << editor.message();
        editor.brush().mode = BrushMode::Refine;
        editor.brush().falloff = 0.0f;
    }
    // Press and release without moving: one dab, queued.
    void dab_at(glm::vec2 px, Modifiers mods = {}) {
        editor.mouse_moved(px);
        editor.mouse_pressed(MouseButton::Left, mods);
        editor.mouse_released(MouseButton::Left);
    }
    void stroke(glm::vec2 from, glm::vec2 to, Modifiers mods = {}) {
        editor.mouse_moved(from);
        editor.mouse_pressed(MouseButton::Left, mods);
        for (int i = 1; i <= 8; ++i) editor.mouse_moved(from + (to - from) * (static_cast<float>(i) / 8.0f));
        editor.mouse_released(MouseButton::Left);
        editor.finish_work();
    }
    int max_face_level() const {
        int level = 0;
        for (rgb::FaceId f : editor.document().mesh().faces()) level = std::max(level, editor.document().mesh().level(f));
        return level;
    }
    Editor editor{kViewport};
};

TEST_F(EditorJobs, WholeMeshActionsAboveTheTriangleLimitAreRefusedBeforeTheyStart) {
    const std::size_t base_faces = editor.document().mesh().num_faces();
    // The estimate (rgb::estimated_triangles) is the faces there are plus 4^level per base face they
    // meet: 17 per base face for level 2, exactly at this limit, 65 for level 3.
    const std::size_t limit = 17 * base_faces;
    editor.set_triangle_limit(limit);
    editor.start_flood_fill(3);
    EXPECT_EQ(editor.job(), nullptr);
    EXPECT_NE(editor.message().find("set all to level 3 refused"), std::string::npos) << editor.message();
    EXPECT_NE(editor.message().find(std::to_string(limit)), std::string::npos) << "names the limit: " << editor.message();
    EXPECT_EQ(editor.document().mesh().num_faces(), base_faces);
    EXPECT_FALSE(editor.document().history().can_undo());

    editor.auto_lod_settings().triangle_budget = limit + 1;
    editor.start_auto_lod();
    EXPECT_EQ(editor.job(), nullptr);
    EXPECT_NE(editor.message().find("automatic LOD refused"), std::string::npos) << editor.message();

    editor.start_flood_fill(2);
    editor.finish_work();
    EXPECT_EQ(editor.document().mesh().num_faces(), 16 * base_faces);
}

TEST_F(EditorJobs, ALargeDabSpreadsOverFramesCoarseToFineWithTheDisplayFollowing) {
    const rgb::Mesh original = editor.document().mesh();
    editor.brush().radius_px = 100.0f;
    editor.brush().target_level = 4;
    dab_at(kCentre);
    ASSERT_NE(editor.job(), nullptr) << "the dab waits for the engine, not the other way round";
    EXPECT_EQ(editor.document().mesh().num_faces(), original.num_faces()) << "pressing does no engine work";
    editor.update(std::chrono::milliseconds(2));
    ASSERT_NE(editor.job(), nullptr) << "a level-4 dab of 100 px cannot fit one 2 ms slice";
    const std::size_t partial = editor.document().mesh().num_faces();
    EXPECT_GT(partial, original.num_faces());
    EXPECT_LT(max_face_level(), 4) << "coarse levels come first";
    // What is drawn and picked is the partial mesh.
    const render::SurfaceGeometry& shown = editor.document().geometry();
    EXPECT_EQ(shown.triangles_of(rgb::Colour::Green) + shown.triangles_of(rgb::Colour::Red) + shown.triangles_of(rgb::Colour::Blue),
              partial);
    EXPECT_GT(editor.job()->progress(), 0.0f);
    EXPECT_LT(editor.job()->progress(), 1.0f);
    int frames = 1;
    for (; editor.job() != nullptr && frames < 100000; ++frames) editor.update(std::chrono::milliseconds(2));
    EXPECT_GT(frames, 5);
    EXPECT_EQ(max_face_level(), 4);
    EXPECT_EQ(editor.document().history().undo_steps(), 1u);
    // The dab applied whole gives the same mesh.
    rgb::Mesh whole = original;
    replay(whole, editor.document().history().session_script().text);
    EXPECT_TRUE(rgbtest::same_mesh(editor.document().mesh(), whole));
}

TEST_F(EditorJobs, EscKeepsTheWorkDoneAsOneStepAndUndoRedoCrossItExactly) {
    editor.brush().radius_px = 30.0f;
    editor.brush().target_level = 3;
    const rgb::Mesh original = editor.document().mesh();
    stroke({0.4f * kViewport.x, kCentre.y}, {0.5f * kViewport.x, kCentre.y});
    const rgb::Mesh after_first = editor.document().mesh();

    editor.brush().radius_px = 150.0f;
    editor.brush().target_level = 5;
    dab_at(kCentre);
    editor.update(std::chrono::milliseconds(2));
    editor.update(std::chrono::milliseconds(2));
    ASSERT_NE(editor.job(), nullptr);
    editor.key_pressed(Key::Escape, {});
    EXPECT_EQ(editor.job(), nullptr);
    EXPECT_NE(editor.message().find("cancelled"), std::string::npos) << editor.message();
    const rgb::Mesh cancelled = editor.document().mesh();
    EXPECT_GT(cancelled.num_faces(), after_first.num_faces());
    EXPECT_TRUE(rgb::check_invariants(cancelled).ok());
    ASSERT_EQ(editor.document().history().undo_steps(), 2u);

    editor.brush().radius_px = 30.0f;
    editor.brush().target_level = 4;
    editor.brush().mode = BrushMode::Set;
    stroke({0.5f * kViewport.x, 0.45f * kViewport.y}, {0.6f * kViewport.x, 0.45f * kViewport.y});
    const rgb::Mesh last = editor.document().mesh();

    // Each undo and redo runs to its end (a large one crosses over frames, history_job.h).
    ASSERT_TRUE(editor.undo());
    editor.finish_work();
    EXPECT_TRUE(rgbtest::same_slots(editor.document().mesh(), cancelled));
    ASSERT_TRUE(editor.undo());
    editor.finish_work();
    EXPECT_TRUE(rgbtest::same_slots(editor.document().mesh(), after_first));
    ASSERT_TRUE(editor.undo());
    editor.finish_work();
    EXPECT_TRUE(rgbtest::same_slots(editor.document().mesh(), original));
    for (int i = 0; i < 3; ++i) {
        ASSERT_TRUE(editor.redo());
        editor.finish_work();
    }
    EXPECT_TRUE(rgbtest::same_slots(editor.document().mesh(), last));
    // A script cannot say a stroke stopped half way, and saving the session says so.
    EXPECT_EQ(editor.document().history().session_script().unscripted_steps, 1u);
    ASSERT_TRUE(editor.save_strokes(scratch("cancelled_session.lod").string()));
    EXPECT_TRUE(editor.message_is_error());
    EXPECT_NE(editor.message().find("replay will differ"), std::string::npos) << editor.message();
}

// Automatic LOD to a budget that stops it above its *max edge*, in slices of a frame, is the canonical
// mesh of a script's `budget` line (the run reserves and faults in room for the budget as the script's
// does: LodSettings::room_for_budget); where the max edge stops it first, it is the driver's run with
// that threshold and budget and no room; either way Ctrl+Z gives back every slot.
TEST_F(EditorJobs, AutomaticLodToABudgetIsTheScriptsBudget) {
    const rgb::Mesh original = editor.document().mesh();
    constexpr std::size_t kBudget = 12000;
    AutoLodSettings& settings = editor.auto_lod_settings();
    settings.triangle_budget = kBudget;
    settings.max_edge_fraction = 0.05 / 100.0;  // the least the panel offers
    editor.start_auto_lod();
    int frames = 0;
    for (; editor.job() != nullptr && frames < 100000; ++frames) editor.update(std::chrono::milliseconds(1));
    EXPECT_GT(frames, 1) << "the job runs in slices";
    rgb::Mesh by_script = original;
    replay(by_script, "budget " + std::to_string(kBudget) + "\n");
    EXPECT_TRUE(rgbtest::same_mesh(editor.document().mesh(), by_script));
    EXPECT_LE(editor.document().mesh().num_faces(), kBudget);
    EXPECT_GT(editor.document().mesh().num_faces(), kBudget - kBudget / 10);
    editor.key_pressed(Key::Z, {.ctrl = true});
    editor.finish_work();
    EXPECT_TRUE(rgbtest::same_slots(editor.document().mesh(), original));

    settings.max_edge_fraction = 5.0 / 100.0;
    editor.start_auto_lod();
    editor.finish_work();
    rgb::LodSettings thresholded;
    thresholded.threshold = 5.0 / 100.0 * rgb::bounding_box_diagonal(original.base());
    thresholded.max_triangles = kBudget;
    rgb::Mesh by_driver = original;
    rgb::LodDriver(by_driver, thresholded).run();
    ASSERT_LT(by_driver.num_faces(), kBudget / 2) << "the max edge, not the budget, stops this run";
    ASSERT_GT(by_driver.num_faces(), original.num_faces());
    EXPECT_TRUE(rgbtest::same_mesh(editor.document().mesh(), by_driver));
    editor.key_pressed(Key::Z, {.ctrl = true});
    editor.finish_work();
    EXPECT_TRUE(rgbtest::same_slots(editor.document().mesh(), original));
}

// Automatic LOD stopped by Esc part way: the work done so far stays, as one step that Ctrl+Z takes
// back whole and Ctrl+Y brings back exactly.
TEST_F(EditorJobs, EscKeepsAPartialAutomaticLodAsOneUndoStep) {
    const rgb::Mesh original = editor.document().mesh();
    // Slices of a microsecond do a unit of work each: stop after a few.
    editor.start_auto_lod();
    ASSERT_NE(editor.job(), nullptr);
    for (int i = 0; i < 3; ++i) editor.update(std::chrono::microseconds(1));
    ASSERT_NE(editor.job(), nullptr) << "the job finished before it could be cancelled";
    const std::size_t partial_faces = editor.document().mesh().num_faces();
    ASSERT_GT(partial_faces, original.num_faces());
    const std::string label = editor.job()->label();

    editor.key_pressed(Key::Escape, {});
    EXPECT_EQ(editor.job(), nullptr);
    EXPECT_EQ(editor.document().mesh().num_faces(), partial_faces) << "cancelling keeps the work done";
    EXPECT_TRUE(rgb::check_invariants(editor.document().mesh()).ok());
    EXPECT_TRUE(editor.document().dirty());
    EXPECT_EQ(editor.document().history().undo_steps(), 1u);
    EXPECT_EQ(editor.document().history().undo_label(), label + ", stopped") << "so Ctrl+E's warning names it";
    const rgb::Mesh partial = editor.document().mesh();

    editor.key_pressed(Key::Z, {.ctrl = true});
    EXPECT_TRUE(rgbtest::same_slots(editor.document().mesh(), original));
    EXPECT_FALSE(editor.document().history().can_undo());
    editor.key_pressed(Key::Y, {.ctrl = true});
    EXPECT_TRUE(rgbtest::same_slots(editor.document().mesh(), partial));
}

// With a bound too small for any step the editor still edits, but keeps no step to undo.
TEST_F(EditorJobs, UndoMemoryBoundLimitsTheStepsKept) {
    const std::size_t base_faces = editor.document().mesh().num_faces();
    editor.document().history().set_byte_bound(0);
    editor.start_flood_fill(1);
    editor.finish_work();
    EXPECT_EQ(editor.document().mesh().num_faces(), 4 * base_faces);
    EXPECT_TRUE(editor.document().dirty());
    EXPECT_FALSE(editor.document().history().can_undo());
    EXPECT_EQ(editor.document().history().bytes(), 0u);
    EXPECT_FALSE(editor.undo());

    // With room again, two edits leave two steps; a bound just below them forgets the older.
    editor.document().history().set_byte_bound(std::size_t{1} << 30);
    editor.start_flood_fill(2);
    editor.finish_work();
    const rgb::Mesh level_two = editor.document().mesh();
    editor.start_flood_fill(0);
    editor.finish_work();
    ASSERT_EQ(editor.document().history().undo_steps(), 2u);
    editor.document().history().set_byte_bound(editor.document().history().bytes() - 1);
    EXPECT_EQ(editor.document().history().undo_steps(), 1u);
    EXPECT_EQ(editor.document().history().undo_label(), "set all to level 0");
    ASSERT_TRUE(editor.undo());
    editor.finish_work();  // 43k operations: more than one frame's (history_job.h)
    EXPECT_EQ(editor.document().mesh().num_faces(), 16 * base_faces) << "back to level 2 everywhere";
    EXPECT_TRUE(rgbtest::same_slots(editor.document().mesh(), level_two));
    EXPECT_FALSE(editor.undo());
}

TEST_F(EditorJobs, UndoWaitsForTheStrokeUnderWay) {
    editor.brush().radius_px = 150.0f;
    editor.brush().target_level = 5;
    dab_at(kCentre);
    EXPECT_FALSE(editor.undo());
    EXPECT_TRUE(editor.message_is_error());
    EXPECT_NE(editor.message().find("Esc"), std::string::npos) << editor.message();
}

TEST_F(EditorJobs, TheSessionsStrokesReplayToTheIdenticalMeshWholeOrInTwoHalves) {
    editor.brush().radius_px = 40.0f;
    editor.brush().target_level = 3;
    editor.brush().falloff = 0.4f;
    stroke({0.35f * kViewport.x, kCentre.y}, {0.6f * kViewport.x, 0.5f * kViewport.y});
    editor.brush().target_level = 2;
    editor.brush().paint_through = true;
    stroke({0.45f * kViewport.x, 0.4f * kViewport.y}, {0.5f * kViewport.x, 0.7f * kViewport.y});
    editor.brush().paint_through = false;
    stroke({0.4f * kViewport.x, kCentre.y}, {0.5f * kViewport.x, kCentre.y}, {.shift = true});  // coarsens to 0
    editor.start_flood_fill(1);
    editor.finish_work();
    editor.brush().mode = BrushMode::Set;
    editor.brush().target_level = 4;
    stroke({0.55f * kViewport.x, 0.45f * kViewport.y}, {0.65f * kViewport.x, 0.6f * kViewport.y});
    editor.brush().mode = BrushMode::Coarsen;
    editor.brush().target_level = 2;
    stroke({0.6f * kViewport.x, 0.5f * kViewport.y}, {0.62f * kViewport.x, 0.55f * kViewport.y});
    // An undone stroke is not part of the session any more.
    editor.brush().mode = BrushMode::Refine;
    stroke({0.3f * kViewport.x, 0.3f * kViewport.y}, {0.7f * kViewport.x, 0.7f * kViewport.y});
    ASSERT_TRUE(editor.undo());
    ASSERT_EQ(editor.document().history().undo_steps(), 6u);

    const std::filesystem::path script = scratch("session.lod");
    ASSERT_TRUE(editor.save_strokes(script.string())) << editor.message();
    EXPECT_FALSE(editor.message_is_error()) << editor.message();
    std::stringstream text;
    text << std::ifstream(script).rdbuf();

    rgb::Mesh whole = rgbio::load_mesh(bunny_path());
    replay(whole, text.str());
    EXPECT_TRUE(rgbtest::same_mesh(whole, editor.document().mesh()));

    // Cut at the start of the fourth step (the `level` line): each step begins with its own brush.
    const std::size_t cut = text.str().find("\nlevel 1\n");
    ASSERT_NE(cut, std::string::npos);
    rgb::Mesh first = rgbio::load_mesh(bunny_path());
    replay(first, text.str().substr(0, cut + 1));
    const std::filesystem::path half = scratch("session_half.obj");
    rgbio::save_mesh(first, half.string());
    rgb::Mesh second = rgbio::load_mesh(half.string());
    replay(second, text.str().substr(cut + 1));
    EXPECT_TRUE(rgbtest::same_mesh(second, editor.document().mesh()));
}

// A closed box, 2 wide and 0.1 thick: a brush of radius 0.3 on the middle of its top reaches through
// to the bottom in base space, which faces away from the viewer.
rgb::Mesh thin_box() {
    const std::vector<glm::dvec3> p{{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}, {-1, 0.1, -1}, {1, 0.1, -1}, {1, 0.1, 1}, {-1, 0.1, 1}};
    const std::vector<rgb::Triangle> t{{0, 1, 2}, {0, 2, 3}, {4, 6, 5}, {4, 7, 6}, {0, 4, 5}, {0, 5, 1},
                                       {1, 5, 6}, {1, 6, 2}, {2, 6, 7}, {2, 7, 3}, {3, 7, 4}, {3, 4, 0}};
    return rgb::Mesh(p, t);
}

// Refined faces whose base-space normal points down (the bottom of the box).
std::size_t refined_bottom_faces(const rgb::Mesh& mesh) {
    std::size_t n = 0;
    for (rgb::FaceId f : mesh.faces()) {
        const auto& v = mesh.face_vertices(f);
        const glm::dvec3 a = mesh.base_space_position(v[0]), b = mesh.base_space_position(v[1]), c = mesh.base_space_position(v[2]);
        n += mesh.level(f) > 0 && glm::cross(b - a, c - a).y < 0.0;
    }
    return n;
}

TEST_F(EditorJobs, TheBrushPaintsOnlyFacesFacingTheViewerUnlessPaintingThrough) {
    for (const bool through : {false, true}) {
        editor.document().adopt(thin_box(), "");
        editor.reset_view();
        editor.brush().unit = RadiusUnit::World;
        editor.brush().radius_world = 0.3f;
        editor.brush().target_level = 3;
        editor.brush().paint_through = through;
        editor.mouse_moved({0.5f * kViewport.x, 0.5f * kViewport.y});
        const std::optional<SurfaceHit> hit = editor.cursor_hit();
        ASSERT_TRUE(hit.has_value());
        ASSERT_NEAR(hit->point.y, 0.1, 1e-6) << "the view must hit the top at " << hit->point.x << ", " << hit->point.z;
        dab_at({0.5f * kViewport.x, 0.5f * kViewport.y});
        editor.finish_work();
        EXPECT_GT(editor.document().mesh().num_faces(), 12u) << (through ? "painting through" : "facing only");
        if (through) EXPECT_GT(refined_bottom_faces(editor.document().mesh()), 0u);
        else EXPECT_EQ(refined_bottom_faces(editor.document().mesh()), 0u);
    }
}

}  // namespace
}  // namespace app
