#pragma once
// An undo journal: while recording, every Mesh::replace_faces becomes one step holding what it
// removed (the faces with their slots, corners and types; the vertex with its slot, level, boundary
// flag, insertion position, address and cached limit) and the slots of what it added. A step is exactly reversible
// by one replace_faces that removes what it added and recreates what it removed, so undoing an edit
// costs in proportion to the edit, the record takes memory in proportion to the edit (about 50 bytes
// a split), and observers (the renderer) see ordinary changes.
//
// Reverting the steps last to first gives back the mesh bit for bit, slots included: the mesh's
// free lists are stacks, so when the steps after a step have been undone, the slots that step took
// are again on top of them. Reverting while recording records the reversal, so the record of an undo
// is the redo.
//
// A replacement is whole or absent (Mesh::replace_faces); one that failed while observers were told
// of its removals leaves an incomplete step, which stop() drops. The journal never fails after a
// replacement has changed the mesh: it makes room for a whole step before it.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "rgb/mesh/observer.h"

namespace rgb {

class Mesh;

// The steps of one edit, packed.
class JournalRecord {
public:
    bool empty() const { return steps_ == 0; }
    std::size_t steps() const { return steps_; }
    // Memory held, in bytes.
    std::size_t bytes() const;

    // A place between two steps, for reverting in pieces (Journal::revert_some): the steps before it
    // are the ones still to be undone.
    struct Cursor {
        std::size_t chunk = 0;     // in this chunk
        std::uint32_t offset = 0;  // the byte after the last step still to be undone
        std::size_t steps = 0;     // steps before it
    };
    // After the last step: nothing undone yet.
    Cursor end() const;
    // Keeps only the steps before `at` (those a revert stopped part way has left in effect).
    void truncate(const Cursor& at);

private:
    friend class Journal;
    // Whole steps only, each followed by a byte with its length so that they can be read backwards.
    struct Chunk {
        std::unique_ptr<std::uint8_t[]> data;
        std::uint32_t size = 0;
        std::uint32_t capacity = 0;
    };
    std::vector<Chunk> chunks_;
    std::size_t steps_ = 0;
};

class Journal : private MeshObserver {
public:
    // Observes `mesh` for the journal's lifetime.
    explicit Journal(Mesh& mesh);
    ~Journal() override;
    Journal(const Journal&) = delete;
    Journal& operator=(const Journal&) = delete;

    // Records from now on into an empty record. O(1).
    void start();
    // Stops recording and hands over the record.
    JournalRecord stop();
    bool recording() const { return recording_; }

    // Undoes the steps of `record`, last to first. Throws std::logic_error if the mesh is not the one
    // the record left (some change was not recorded): then the mesh is valid but only partly reverted.
    void revert(const JournalRecord& record);
    // The same in pieces: undoes up to `max_steps` more steps before `cursor` (which starts at
    // record.end()) and moves it back over them; true once no step is left. Nothing else may change
    // the mesh between the pieces; when recording, the pieces make one record as one revert would.
    bool revert_some(const JournalRecord& record, JournalRecord::Cursor& cursor, std::size_t max_steps);

    // Whether the mesh changed while nothing was recorded since the last call: a record made before
    // such a change can no longer be reverted.
    bool take_unrecorded_change();

private:
    enum class Phase { FacesRemoved, VertexRemoved, VertexAdded, FacesAdded };
    void face_removed(const Mesh& mesh, FaceId f) override;
    void vertex_removed(const Mesh& mesh, VertexId v) override;
    void vertex_added(const Mesh& mesh, VertexId v, VertexId a, VertexId b) override;
    void face_added(const Mesh& mesh, FaceId f) override;
    // Where the event of `phase` goes: the open step, or a new one. False when not recording.
    bool enter(Phase phase);
    void start_step();
    void drop_incomplete_step();
    void append(const void* bytes, std::size_t n);
    void revert_step(const std::uint8_t* step);

    Mesh& mesh_;
    bool recording_ = false;
    bool reverting_ = false;
    bool unrecorded_change_ = false;
    JournalRecord record_;
    // The open step: where it starts in the last chunk, and how far it got.
    std::uint32_t step_start_ = 0;
    Phase phase_ = Phase::FacesAdded;
    bool step_open_ = false;
};

}  // namespace rgb
