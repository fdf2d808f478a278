// The undo history over the core's journal: undo and redo give back every slot, a failed edit is
// abandoned back to the mesh before it, memory follows the edits, and a change made outside an edit
// drops the history instead of corrupting the mesh on a later undo.
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/undo_history.h"
#include "rgb/dab.h"
#include "rgb/invariants.h"
#include "rgb/mesh.h"
#include "rgb/refine.h"
#include "rgb/requests.h"
#include "support/random_operations.h"
#include "support/same_mesh.h"
#include "support/same_slots.h"
#include "support/test_meshes.h"

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
    rgb::set_level(mesh, 1);
    history.end_edit(true);
    EXPECT_FALSE(history.can_redo());
    ASSERT_TRUE(history.undo());
    EXPECT_TRUE(rgbtest::same_slots(mesh, states[states.size() - 1 - 6]));
}

TEST(UndoHistory, AbandoningAnEditPutsTheMeshBack) {
    rgb::Mesh mesh = rgbtest::make_rgb_mesh(rgbtest::icosahedron());
    UndoHistory history(mesh);
    history.begin_edit("one");
    rgb::set_level(mesh, 2);
    history.end_edit(true);
    const rgb::Mesh before = mesh;
    history.begin_edit("two");
    rgb::set_level(mesh, 4);
    EXPECT_TRUE(history.abandon_edit());
    EXPECT_TRUE(rgbtest::same_slots(mesh, before));
    EXPECT_FALSE(history.editing());
    EXPECT_FALSE(history.abandon_edit());
    EXPECT_EQ(history.undo_steps(), 1u);
}

TEST(UndoHistory, AnEditThatChangedNothingLeavesNoStep) {
    rgb::Mesh mesh = rgbtest::make_rgb_mesh(rgbtest::icosahedron());
    UndoHistory history(mesh);
    history.begin_edit("nothing");
    rgb::set_level(mesh, 0);
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

TEST(UndoHistory, ForgetsTheOldestStepsBeyondTheBound) {
    rgb::Mesh mesh = rgbtest::make_rgb_mesh(rgbtest::tetrahedron());
    UndoHistory history(mesh);
    for (int level = 1; level <= 3; ++level) {
        history.begin_edit("level " + std::to_string(level));
        rgb::refine_uniform(mesh, level);
        history.end_edit(true);
    }
    ASSERT_EQ(history.undo_steps(), 3u);
    history.set_byte_bound(history.bytes() - 1);
    EXPECT_EQ(history.undo_steps(), 2u);
    EXPECT_EQ(history.undo_label(), "level 3");
    EXPECT_LE(history.bytes(), history.byte_bound());
}

// Undoing past a change the history did not see would put faces where they no longer fit.
TEST(UndoHistory, AChangeOutsideAnEditDropsTheHistory) {
    rgb::Mesh mesh = rgbtest::make_rgb_mesh(rgbtest::icosahedron());
    UndoHistory history(mesh);
    history.begin_edit("inside");
    rgb::set_level(mesh, 2);
    history.end_edit(true);
    const rgb::Mesh after_outside = [&] {
        rgb::set_level(mesh, 1);
        return mesh;
    }();
    EXPECT_FALSE(history.undo());
    EXPECT_FALSE(history.can_undo());
    EXPECT_TRUE(rgbtest::same_slots(mesh, after_outside));
}

}  // namespace
}  // namespace app
