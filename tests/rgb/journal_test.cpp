// The undo journal: reverting a record gives back the mesh slot for slot, the record of a reversal
// redoes the edit, a record's size follows the edit and not the mesh, and a replacement that fails
// half-way through telling its observers is reverted whole or not at all.
#include <optional>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "rgb/lod/refine.h"
#include "rgb/lod/requests.h"
#include "rgb/mesh/invariants.h"
#include "rgb/mesh/journal.h"
#include "rgb/mesh/mesh.h"
#include "support/random_operations.h"
#include "support/same_mesh.h"
#include "support/same_slots.h"
#include "support/test_meshes.h"
#include "support/set_level.h"

namespace {

// A request of a random kind and level in a ball around a random vertex.
rgb::LevelRequest random_request(const rgb::Mesh& mesh, std::mt19937& rng) {
    rgb::LevelRequest request;
    request.kind = static_cast<rgb::RequestKind>(rng() % 3);
    request.level = static_cast<int>(rng() % 4) + (request.kind == rgb::RequestKind::Refine ? 1 : 0);
    const double radius = mesh.base().longest_edge() * (0.3 + 1.5 * std::uniform_real_distribution<double>(0.0, 1.0)(rng));
    request.sphere = rgb::Sphere{mesh.base_space_position(rgbtest::random_live_vertex(mesh, rng)), radius};
    return request;
}

struct Edit {
    rgb::Mesh before;
    rgb::JournalRecord record;
};

class JournalOnMeshes : public ::testing::TestWithParam<rgbtest::TestMesh> {};

TEST_P(JournalOnMeshes, RevertingEditsGivesBackEverySlotAndRevertingThatRedoesThem) {
    rgb::Mesh mesh = rgbtest::make_rgb_mesh(GetParam());
    rgb::Journal journal(mesh);
    std::mt19937 rng(20240611);
    std::vector<Edit> edits;
    for (int i = 0; i < 24; ++i) {
        Edit edit{mesh, {}};
        journal.start();
        rgb::apply_request(mesh, random_request(mesh, rng));
        edit.record = journal.stop();
        edits.push_back(std::move(edit));
    }
    const rgb::Mesh last = mesh;
    std::size_t steps = 0;
    for (const Edit& e : edits) steps += e.record.steps();
    ASSERT_GT(steps, 100u) << "the edits must do something";

    std::vector<rgb::JournalRecord> redo;
    for (auto e = edits.rbegin(); e != edits.rend(); ++e) {
        journal.start();
        journal.revert(e->record);
        redo.push_back(journal.stop());
        ASSERT_TRUE(rgbtest::same_slots(mesh, e->before)) << "undoing edit " << (edits.rend() - e - 1);
        EXPECT_EQ(redo.back().steps(), e->record.steps());
    }
    EXPECT_TRUE(rgb::check_invariants(mesh).ok());
    for (std::size_t i = 0; i < edits.size(); ++i) {
        journal.revert(redo[redo.size() - 1 - i]);
        const rgb::Mesh& after = i + 1 < edits.size() ? edits[i + 1].before : last;
        ASSERT_TRUE(rgbtest::same_slots(mesh, after)) << "redoing edit " << i;
    }
    EXPECT_TRUE(rgbtest::same_mesh(mesh, last));
    EXPECT_TRUE(rgb::check_invariants(mesh).ok());
    EXPECT_FALSE(journal.take_unrecorded_change()) << "reverting is not a change outside the journal";
}

// Several random requests recorded as one edit, for the reverts in pieces.
rgb::JournalRecord record_requests(rgb::Mesh& mesh, rgb::Journal& journal, std::mt19937& rng, int requests) {
    journal.start();
    for (int i = 0; i < requests; ++i) rgb::apply_request(mesh, random_request(mesh, rng));
    return journal.stop();
}

// What the editor does with an undo too large for a frame: the same steps, a few at a time.
TEST_P(JournalOnMeshes, ARevertInPiecesGivesTheMeshAndTheRecordOfARevertInOne) {
    rgb::Mesh mesh = rgbtest::make_rgb_mesh(GetParam());
    rgb::Journal journal(mesh);
    std::mt19937 rng(7);
    const rgb::Mesh before = mesh;
    const rgb::JournalRecord edit = record_requests(mesh, journal, rng, 8);
    ASSERT_GT(edit.steps(), 50u) << "the edit must do something";
    rgb::Mesh in_pieces = mesh;
    rgb::Journal pieces_journal(in_pieces);

    journal.start();
    journal.revert(edit);
    const rgb::JournalRecord whole_redo = journal.stop();

    pieces_journal.start();
    rgb::JournalRecord::Cursor cursor = edit.end();
    std::size_t pieces = 0;
    for (bool done = false; !done; ++pieces) {
        const std::size_t left = cursor.steps;
        const std::size_t piece = 1 + rng() % 37;
        done = pieces_journal.revert_some(edit, cursor, piece);
        ASSERT_EQ(cursor.steps, left - std::min(left, piece));
    }
    const rgb::JournalRecord pieces_redo = pieces_journal.stop();
    EXPECT_GT(pieces, 2u);
    ASSERT_TRUE(rgbtest::same_slots(in_pieces, mesh));
    ASSERT_TRUE(rgbtest::same_slots(in_pieces, before));
    EXPECT_EQ(pieces_redo.steps(), whole_redo.steps());
    // The record the pieces made redoes the edit as the one-shot's does.
    pieces_journal.revert(pieces_redo);
    journal.revert(whole_redo);
    EXPECT_TRUE(rgbtest::same_slots(in_pieces, mesh));
    EXPECT_TRUE(rgb::check_invariants(in_pieces).ok());
}

// Esc during such an undo: the steps undone so far and the steps still in effect become two
// records, each of which reverts to the mesh at the other end of it.
TEST_P(JournalOnMeshes, ARevertStoppedPartWayLeavesTwoRecordsThatRevertExactly) {
    rgb::Mesh mesh = rgbtest::make_rgb_mesh(GetParam());
    rgb::Journal journal(mesh);
    std::mt19937 rng(8);
    const rgb::Mesh before = mesh;
    rgb::JournalRecord edit = record_requests(mesh, journal, rng, 8);
    const std::size_t steps = edit.steps();
    ASSERT_GT(steps, 50u);
    const rgb::Mesh edited = mesh;

    journal.start();
    rgb::JournalRecord::Cursor cursor = edit.end();
    ASSERT_FALSE(journal.revert_some(edit, cursor, steps / 3));
    const rgb::JournalRecord undone = journal.stop();
    edit.truncate(cursor);
    EXPECT_EQ(undone.steps(), steps / 3);
    EXPECT_EQ(edit.steps(), steps - steps / 3);
    const rgb::Mesh middle = mesh;

    journal.start();
    journal.revert(edit);  // the rest of the undo
    const rgb::JournalRecord rest_redo = journal.stop();
    ASSERT_TRUE(rgbtest::same_slots(mesh, before));
    journal.revert(rest_redo);
    ASSERT_TRUE(rgbtest::same_slots(mesh, middle));
    journal.revert(undone);  // a redo of what was undone
    EXPECT_TRUE(rgbtest::same_slots(mesh, edited));
    EXPECT_TRUE(rgb::check_invariants(mesh).ok());
}

INSTANTIATE_TEST_SUITE_P(Meshes, JournalOnMeshes,
                         ::testing::Values(rgbtest::icosahedron(), rgbtest::grid(4, 3), rgbtest::fan(5), rgbtest::bunny()),
                         [](const auto& info) { return info.param.name; });

// The same edit on a coarse mesh and on one refined far away: the records are alike.
TEST(Journal, RecordFollowsTheEditNotTheMesh) {
    const rgbtest::TestMesh grid = rgbtest::grid(16, 16);
    rgb::Mesh small = rgbtest::make_rgb_mesh(grid);
    rgb::Mesh large = rgbtest::make_rgb_mesh(grid);
    // Refine the far corner of `large` deeply: (0,0) is a corner, the edit is at the opposite one.
    rgbtest::set_level(large, 5, rgb::Sphere{grid.positions.front(), 0.3 * rgbtest::bounding_box_diagonal(grid.positions)});
    ASSERT_GT(large.num_faces(), 20 * small.num_faces());
    rgb::LevelRequest request;
    request.kind = rgb::RequestKind::Refine;
    request.level = 3;
    request.sphere = rgb::Sphere{grid.positions.back(), 0.05 * rgbtest::bounding_box_diagonal(grid.positions)};
    std::vector<rgb::JournalRecord> records;
    for (rgb::Mesh* mesh : {&small, &large}) {
        rgb::Journal journal(*mesh);
        journal.start();
        const rgb::RequestStats stats = rgb::apply_request(*mesh, request);
        records.push_back(journal.stop());
        EXPECT_GE(records.back().steps(), stats.splits);
    }
    EXPECT_EQ(records[0].steps(), records[1].steps());
    EXPECT_EQ(records[0].bytes(), records[1].bytes());
    // A split or swap step is 44 to 60 bytes; chunks grow by doubling, so at most half is slack.
    EXPECT_LE(records[0].bytes(), 2 * 60 * records[0].steps() + 4096) << records[0].steps() << " steps";
}

// Throws while told of the n-th event of one kind.
class FailingObserver : public rgb::MeshObserver {
public:
    enum class When { FaceRemoved, FaceAdded };
    FailingObserver(When when, int n) : when_(when), countdown_(n) {}
    void face_removed(const rgb::Mesh&, rgb::FaceId) override {
        if (when_ == When::FaceRemoved) tick();
    }
    void face_added(const rgb::Mesh&, rgb::FaceId) override {
        if (when_ == When::FaceAdded) tick();
    }

private:
    void tick() {
        if (--countdown_ == 0) throw std::runtime_error("observer failure");
    }
    When when_;
    int countdown_;
};

class JournalFailure : public ::testing::TestWithParam<FailingObserver::When> {};

// The failing observer hears of the changes before the journal or after it; either way the journal
// holds exactly the replacements that happened.
TEST_P(JournalFailure, AFailedRequestIsRevertedToTheMeshBeforeIt) {
    for (const bool journal_first : {true, false}) {
        rgb::Mesh mesh = rgbtest::make_rgb_mesh(rgbtest::icosahedron());
        rgbtest::set_level(mesh, 1);
        const rgb::Mesh before = mesh;
        // In the middle of some replacement (the 81st event: not the first face of one, since
        // splits replace two faces or more).
        FailingObserver failing(GetParam(), 81);
        std::optional<rgb::Journal> journal;
        if (journal_first) journal.emplace(mesh);
        mesh.add_observer(&failing);
        if (!journal_first) journal.emplace(mesh);
        journal->start();
        EXPECT_THROW(rgbtest::set_level(mesh, 3), std::runtime_error);
        mesh.remove_observer(&failing);
        const rgb::JournalRecord record = journal->stop();
        EXPECT_GT(record.steps(), 10u);
        journal->revert(record);
        EXPECT_TRUE(rgbtest::same_slots(mesh, before)) << (journal_first ? "journal first" : "journal second");
        EXPECT_TRUE(rgb::check_invariants(mesh).ok());
    }
}

INSTANTIATE_TEST_SUITE_P(Events, JournalFailure,
                         ::testing::Values(FailingObserver::When::FaceRemoved, FailingObserver::When::FaceAdded),
                         [](const auto& info) { return info.param == FailingObserver::When::FaceRemoved ? "WhileRemoving" : "WhileAdding"; });

TEST(Journal, ReportsAChangeMadeWhileNotRecording) {
    rgb::Mesh mesh = rgbtest::make_rgb_mesh(rgbtest::octahedron());
    rgb::Journal journal(mesh);
    EXPECT_FALSE(journal.take_unrecorded_change());
    journal.start();
    rgbtest::set_level(mesh, 1);
    const rgb::JournalRecord record = journal.stop();
    EXPECT_FALSE(journal.take_unrecorded_change());
    journal.revert(record);
    EXPECT_FALSE(journal.take_unrecorded_change());
    rgbtest::set_level(mesh, 1);
    EXPECT_TRUE(journal.take_unrecorded_change());
    EXPECT_FALSE(journal.take_unrecorded_change());
}

}  // namespace
