// The undo history on its own: what comes back after forgetting steps, and its memory bound over
// both sides, checked against states the test captured itself.
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/undo_history.h"
#include "io/mesh_state_compare.h"
#include "rgb/mesh.h"
#include "rgb/refine.h"
#include "small_meshes.h"

namespace app {
namespace {

using test::tetrahedron;

// Three steps (levels 1, 2, 3 everywhere) on the tetrahedron, with the state before each taken by
// the test itself.
struct ThreeLevels {
    rgb::Mesh mesh = tetrahedron();
    UndoHistory history;
    std::vector<rgb::MeshState> before;  // before[k]: the state step k + 1 started from
    std::vector<std::size_t> step_bytes;  // what each step added to the history's bytes

    ThreeLevels() {
        for (int level = 1; level <= 3; ++level) {
            before.push_back(rgb::capture_state(mesh));
            const std::size_t bytes = history.bytes();
            history.begin_edit(mesh, "level " + std::to_string(level));
            rgb::refine_uniform(mesh, level);
            history.end_edit(mesh, true);
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
    EXPECT_EQ(t.history.undo_label(), "level 3");

    // The two newest steps still come back exactly, newest first; the oldest is gone. (The bound is
    // lifted first: stepping back puts the larger level-3 state on the redo side, which would count.)
    t.history.set_byte_bound(std::numeric_limits<std::size_t>::max());
    std::optional<rgb::Mesh> back = t.history.undo(t.mesh);
    ASSERT_TRUE(back.has_value());
    rgbio::test::expect_identical(rgb::capture_state(*back), t.before[2]);
    EXPECT_EQ(t.history.undo_label(), "level 2");
    back = t.history.undo(*back);
    ASSERT_TRUE(back.has_value());
    rgbio::test::expect_identical(rgb::capture_state(*back), t.before[1]);
    EXPECT_FALSE(t.history.can_undo());
    EXPECT_FALSE(t.history.undo(*back).has_value()) << "the step back to the bare tetrahedron was forgotten";
}

// The bound counts at least the snapshots' payload (every slot of every array), so it bounds the
// memory the history really holds; the bytes of a step are those of the state it keeps.
TEST(UndoHistory, BytesCoverEverySlotOfTheKeptSnapshots) {
    ThreeLevels t;
    for (std::size_t k = 0; k < 3; ++k) {
        const rgb::MeshState& kept = t.before[k];
        const std::size_t payload = kept.vertices.size() * sizeof(rgb::VertexState) + kept.faces.size() * sizeof(rgb::FaceState) +
                                    kept.base_valence.size() * sizeof(std::uint16_t) +
                                    (kept.free_vertices.size() + kept.free_faces.size()) * sizeof(std::uint32_t);
        EXPECT_GE(t.step_bytes[k], payload) << "step " << k + 1;
    }
    // The first step keeps the bare tetrahedron (4 faces), the third the tetrahedron at level 2
    // (4 * 4^2 = 64 live faces, maybe more slots).
    EXPECT_EQ(t.before[0].faces.size(), 4u);
    EXPECT_GE(t.before[2].faces.size(), 64u);
    EXPECT_GT(t.step_bytes[2], t.step_bytes[0]);
}

// Undoing moves a step to the redo side, which the bound covers too: shrinking the bound drops the
// furthest step first (the oldest undo, then the redo furthest from the present).
TEST(UndoHistory, BoundCoversTheRedoSideAndKeepsTheNearestSteps) {
    ThreeLevels t;
    std::optional<rgb::Mesh> back = t.history.undo(t.mesh);  // now at level 2; redo leads to level 3
    ASSERT_TRUE(back.has_value());
    ASSERT_EQ(t.history.undo_steps(), 2u);
    ASSERT_EQ(t.history.redo_steps(), 1u);
    t.history.set_byte_bound(t.history.bytes() - 1);
    EXPECT_EQ(t.history.undo_steps(), 1u) << "the oldest undo step goes first";
    EXPECT_EQ(t.history.redo_steps(), 1u);
    EXPECT_LE(t.history.bytes(), t.history.byte_bound());
    std::optional<rgb::Mesh> forward = t.history.redo(*back);
    ASSERT_TRUE(forward.has_value());
    rgbio::test::expect_identical(rgb::capture_state(*forward), rgb::capture_state(t.mesh));

    t.history.set_byte_bound(0);
    EXPECT_EQ(t.history.bytes(), 0u);
    EXPECT_FALSE(t.history.can_undo());
    EXPECT_FALSE(t.history.can_redo());
}

}  // namespace
}  // namespace app
