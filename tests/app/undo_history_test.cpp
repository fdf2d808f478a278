// The undo history over the core's journal: undo and redo give back every slot, a failed edit is
// abandoned back to the mesh before it, memory follows the edits, and a change made outside an edit
// drops the history instead of corrupting the mesh on a later undo; the memory bound, over both
// sides, forgets the furthest steps and counts at least what the kept steps must remember.
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/undo_history.h"
#include "rgb/lod/dab.h"
#include "rgb/lod/refine.h"
#include "rgb/lod/requests.h"
#include "rgb/mesh/invariants.h"
#include "rgb/mesh/mesh.h"
#include "rgb/mesh/observer.h"
#include "rgb/mesh/surface_point.h"
#include "support/random_operations.h"
#include "support/same_mesh.h"
#include "support/same_slots.h"
#include "support/test_meshes.h"
#include "support/set_level.h"

namespace app {
namespace {

// A brush dab of a random mode and level at a random vertex, seen from a random direction.
rgb::Dab random_dab(const rgb::Mesh& mesh, std::mt19937& rng) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    rgb::Dab dab;
    dab.mode = static_cast<rgb::BrushMode>(rng() % 3);
    dab.level = static_cast<int>(rng() % 4) + 1;
    dab.radius = mesh.base().longest_edge() * (0.5 + unit(rng));
    dab.falloff = 0.5 + 0.5 * unit(rng);
    dab.centre = mesh.base_space_position(rgbtest::random_live_vertex(mesh, rng));
    if (rng() % 2 == 0) dab.view = glm::dvec3(unit(rng), unit(rng), unit(rng));
    return dab;
}

TEST(UndoHistory, UndoAndRedoGiveBackEverySlotOverManyRandomStrokes) {
    rgb::Mesh mesh = rgbtest::make_rgb_mesh(rgbtest::bunny());
    UndoHistory history(mesh);
    std::mt19937 rng(7);
    std::vector<rgb::Mesh> states{mesh};
    std::vector<std::string> labels;
    for (int stroke = 0; stroke < 12; ++stroke) {
        history.begin_edit("stroke " + std::to_string(stroke));
        for (int dab = 0; dab < 6; ++dab) rgb::apply_dab(mesh, random_dab(mesh, rng));
        history.end_edit(true);
        // A stroke that changed nothing leaves no step.
        if (history.undo_steps() == states.size()) {
            states.push_back(mesh);
            labels.push_back("stroke " + std::to_string(stroke));
        }
    }
    ASSERT_GE(states.size(), 10u);
    ASSERT_EQ(history.undo_steps(), states.size() - 1);
    for (std::size_t i = states.size() - 1; i > 0; --i) {
        ASSERT_TRUE(history.undo());
        ASSERT_TRUE(rgbtest::same_slots(mesh, states[i - 1])) << "after undoing stroke " << i - 1;
    }
    EXPECT_FALSE(history.undo());
    EXPECT_EQ(history.redo_steps(), states.size() - 1);
    EXPECT_EQ(history.redo_label(), labels.front());
    for (std::size_t i = 1; i < states.size(); ++i) {
        ASSERT_TRUE(history.redo());
        ASSERT_TRUE(rgbtest::same_slots(mesh, states[i])) << "after redoing stroke " << i - 1;
    }
    EXPECT_TRUE(rgbtest::same_mesh(mesh, states.back()));
    EXPECT_TRUE(rgb::check_invariants(mesh).ok());
    // Half way back and a new edit: the redo side is gone.
    for (int i = 0; i < 6; ++i) ASSERT_TRUE(history.undo());
    history.begin_edit("branch");
    rgbtest::set_level(mesh, 1);
    history.end_edit(true);
    EXPECT_FALSE(history.can_redo());
    ASSERT_TRUE(history.undo());
    EXPECT_TRUE(rgbtest::same_slots(mesh, states[states.size() - 1 - 6]));
}

TEST(UndoHistory, AbandoningAnEditPutsTheMeshBack) {
    rgb::Mesh mesh = rgbtest::make_rgb_mesh(rgbtest::icosahedron());
    UndoHistory history(mesh);
    history.begin_edit("one");
    rgbtest::set_level(mesh, 2);
    history.end_edit(true);
    const rgb::Mesh before = mesh;
    history.begin_edit("two");
    rgbtest::set_level(mesh, 4);
    EXPECT_TRUE(history.abandon_edit());
    EXPECT_TRUE(rgbtest::same_slots(mesh, before));
    EXPECT_FALSE(history.editing());
    EXPECT_FALSE(history.abandon_edit());
    EXPECT_EQ(history.undo_steps(), 1u);
}

// A crossing in pieces that is stopped: before anything crossed, the step goes back whole; part
// way, the two parts are steps of their own, with no script (none says part of a stroke); a crossing
// abandoned (after a failure) puts the mesh and the step back as they were.
TEST(UndoHistory, ACrossingStoppedOrAbandonedKeepsEveryMeshReachable) {
    rgb::Mesh mesh = rgbtest::make_rgb_mesh(rgbtest::icosahedron());
    UndoHistory history(mesh);
    const rgb::Mesh bare = mesh;
    history.begin_edit("set all");
    rgbtest::set_level(mesh, 3);
    history.end_edit(true, "level 3\n");
    const rgb::Mesh refined = mesh;

    ASSERT_TRUE(history.begin_undo());
    EXPECT_TRUE(history.crossing());
    const std::size_t operations = history.crossing_operations();
    ASSERT_GT(operations, 100u);
    history.stop_crossing();
    EXPECT_FALSE(history.crossing());
    EXPECT_TRUE(rgbtest::same_slots(mesh, refined));
    EXPECT_EQ(history.undo_steps(), 1u);
    EXPECT_EQ(history.redo_steps(), 0u);
    EXPECT_EQ(history.session_script().text, "level 3\n") << "the step is whole, script and all";

    ASSERT_TRUE(history.begin_undo());
    EXPECT_FALSE(history.continue_crossing(operations / 4));
    EXPECT_EQ(history.crossed_operations(), operations / 4);
    EXPECT_TRUE(history.abandon_edit());
    EXPECT_TRUE(rgbtest::same_slots(mesh, refined));
    EXPECT_EQ(history.undo_steps(), 1u);
    EXPECT_EQ(history.undo_label(), "set all");

    ASSERT_TRUE(history.begin_undo());
    EXPECT_FALSE(history.continue_crossing(operations / 3));
    history.stop_crossing();
    const rgb::Mesh middle = mesh;
    EXPECT_EQ(history.undo_steps(), 1u);
    EXPECT_EQ(history.redo_steps(), 1u);
    EXPECT_EQ(history.session_script().unscripted_steps, 1u);
    EXPECT_TRUE(history.session_script().text.empty());
    ASSERT_TRUE(history.undo());
    EXPECT_TRUE(rgbtest::same_slots(mesh, bare));
    ASSERT_TRUE(history.redo());
    EXPECT_TRUE(rgbtest::same_slots(mesh, middle));
    ASSERT_TRUE(history.redo());
    EXPECT_TRUE(rgbtest::same_slots(mesh, refined));
    EXPECT_FALSE(history.can_redo());
}

TEST(UndoHistory, AnEditThatChangedNothingLeavesNoStep) {
    rgb::Mesh mesh = rgbtest::make_rgb_mesh(rgbtest::icosahedron());
    UndoHistory history(mesh);
    history.begin_edit("nothing");
    rgbtest::set_level(mesh, 0);
    history.end_edit(true);
    EXPECT_FALSE(history.can_undo());
}

// A small stroke on a large mesh costs what it changed, not the mesh.
TEST(UndoHistory, MemoryFollowsTheEditsNotTheMesh) {
    rgb::Mesh mesh = rgbtest::make_rgb_mesh(rgbtest::bunny());
    rgb::refine_uniform(mesh, 3);
    UndoHistory history(mesh);
    std::mt19937 rng(3);
    history.begin_edit("small");
    rgb::Dab dab{rgb::BrushMode::Refine, 4, 0.1 * mesh.base().longest_edge(), 0.0, mesh.base_space_position(rgbtest::random_live_vertex(mesh, rng)), std::nullopt};
    const rgb::RequestStats stats = rgb::apply_dab(mesh, dab);
    history.end_edit(true);
    ASSERT_GT(stats.splits, 0u);
    EXPECT_LT(history.bytes(), 2 * 60 * 3 * stats.splits + 4096) << stats.splits << " splits";  // splits and their swaps
    EXPECT_LT(history.bytes() * 100, mesh.memory_bytes());
}

// Three steps (levels 1, 2, 3 everywhere) on the tetrahedron, with the mesh before each step and the
// bytes each step added taken by the test itself.
struct ThreeLevels {
    rgb::Mesh mesh = rgbtest::make_rgb_mesh(rgbtest::tetrahedron());
    UndoHistory history{mesh};
    std::vector<rgb::Mesh> before;        // before[k]: the mesh step k + 1 started from
    std::vector<std::size_t> step_bytes;  // what each step added to the history's bytes

    ThreeLevels() {
        for (int level = 1; level <= 3; ++level) {
            before.push_back(mesh);
            const std::size_t bytes = history.bytes();
            history.begin_edit("level " + std::to_string(level));
            rgb::refine_uniform(mesh, level);
            history.end_edit(true);
            step_bytes.push_back(history.bytes() - bytes);
        }
    }
};

TEST(UndoHistory, ForgetsTheOldestStepsBeyondTheBound) {
    ThreeLevels t;
    ASSERT_EQ(t.history.undo_steps(), 3u);
    t.history.set_byte_bound(t.history.bytes() - 1);
    ASSERT_EQ(t.history.undo_steps(), 2u);
    EXPECT_EQ(t.history.bytes(), t.step_bytes[1] + t.step_bytes[2]);
    EXPECT_LE(t.history.bytes(), t.history.byte_bound());
    EXPECT_EQ(t.history.undo_label(), "level 3");

    // The two newest steps still come back exactly, newest first; the oldest is gone. (The bound is
    // lifted first: stepping back puts the redo record on the other side, which counts too.)
    t.history.set_byte_bound(std::numeric_limits<std::size_t>::max());
    ASSERT_TRUE(t.history.undo());
    EXPECT_TRUE(rgbtest::same_slots(t.mesh, t.before[2]));
    EXPECT_EQ(t.history.undo_label(), "level 2");
    ASSERT_TRUE(t.history.undo());
    EXPECT_TRUE(rgbtest::same_slots(t.mesh, t.before[1]));
    EXPECT_FALSE(t.history.can_undo());
    EXPECT_FALSE(t.history.undo()) << "the step back to the bare tetrahedron was forgotten";
    EXPECT_TRUE(rgbtest::same_slots(t.mesh, t.before[1]));
}

// Counts what the mesh reports to any observer: what an edit removed and added.
struct ChangeCounter : rgb::MeshObserver {
    std::size_t faces_removed = 0, faces_added = 0, vertices_removed = 0, vertices_added = 0;
    void face_removed(const rgb::Mesh&, rgb::FaceId) override { ++faces_removed; }
    void face_added(const rgb::Mesh&, rgb::FaceId) override { ++faces_added; }
    void vertex_removed(const rgb::Mesh&, rgb::VertexId) override { ++vertices_removed; }
    void vertex_added(const rgb::Mesh&, rgb::VertexId, rgb::VertexId, rgb::VertexId) override { ++vertices_added; }
};

// The bound counts at least what a step must keep to be undone (rgb/mesh/journal.h: each removed face with
// its slot and corners, each removed vertex with its slot, address and insertion position, the slot of
// everything added), so it bounds the memory the history really holds.
TEST(UndoHistory, BytesCoverWhatEachStepMustRemember) {
    rgb::Mesh mesh = rgbtest::make_rgb_mesh(rgbtest::tetrahedron());
    UndoHistory history(mesh);
    std::size_t total = 0;
    for (int level = 1; level <= 3; ++level) {
        ChangeCounter counter;
        mesh.add_observer(&counter);
        const std::size_t bytes = history.bytes();
        history.begin_edit("level " + std::to_string(level));
        rgb::refine_uniform(mesh, level);
        history.end_edit(true);
        mesh.remove_observer(&counter);
        const std::size_t step = history.bytes() - bytes;
        total += step;
        // Each level quadruples the 4 faces of the tetrahedron: 12, 48, 192 more faces.
        EXPECT_EQ(counter.faces_added - counter.faces_removed, 12u << (2 * (level - 1))) << "level " << level;
        const std::size_t slot = sizeof(std::uint32_t);
        const std::size_t payload = counter.faces_removed * (slot + 3 * slot) +
                                    counter.vertices_removed * (slot + sizeof(rgb::SurfacePoint) + sizeof(glm::dvec3)) +
                                    (counter.faces_added + counter.vertices_added) * slot;
        EXPECT_GE(step, payload) << "level " << level;
    }
    EXPECT_EQ(history.bytes(), total);
}

// Undoing moves a step to the redo side, which the bound covers too: shrinking the bound drops the
// furthest step first (the oldest undo, then the redo furthest from the present).
TEST(UndoHistory, BoundCoversTheRedoSideAndKeepsTheNearestSteps) {
    ThreeLevels t;
    const rgb::Mesh level_three = t.mesh;
    ASSERT_TRUE(t.history.undo());  // now at level 2; redo leads to level 3
    ASSERT_EQ(t.history.undo_steps(), 2u);
    ASSERT_EQ(t.history.redo_steps(), 1u);
    t.history.set_byte_bound(t.history.bytes() - 1);
    EXPECT_EQ(t.history.undo_steps(), 1u) << "the oldest undo step goes first";
    EXPECT_EQ(t.history.redo_steps(), 1u);
    EXPECT_LE(t.history.bytes(), t.history.byte_bound());
    ASSERT_TRUE(t.history.redo());
    EXPECT_TRUE(rgbtest::same_slots(t.mesh, level_three));

    t.history.set_byte_bound(0);
    EXPECT_EQ(t.history.bytes(), 0u);
    EXPECT_FALSE(t.history.can_undo());
    EXPECT_FALSE(t.history.can_redo());
}

// Undoing past a change the history did not see would put faces where they no longer fit.
TEST(UndoHistory, AChangeOutsideAnEditDropsTheHistory) {
    rgb::Mesh mesh = rgbtest::make_rgb_mesh(rgbtest::icosahedron());
    UndoHistory history(mesh);
    history.begin_edit("inside");
    rgbtest::set_level(mesh, 2);
    history.end_edit(true);
    const rgb::Mesh after_outside = [&] {
        rgbtest::set_level(mesh, 1);
        return mesh;
    }();
    EXPECT_FALSE(history.undo());
    EXPECT_FALSE(history.can_undo());
    EXPECT_TRUE(rgbtest::same_slots(mesh, after_outside));
}

}  // namespace
}  // namespace app
