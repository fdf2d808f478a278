#pragma once
// Undo/redo per stroke or action, bit for bit, within a memory bound.
//
// Each step is the record of rgb::Journal (rgb/mesh/journal.h) for one edit: starting an edit costs O(1),
// undoing or redoing it costs in proportion to what it changed, and so does its memory. Undo and
// redo change the mesh in place through its ordinary operations, so whatever observes the mesh
// (the renderer's buffers, the picking index) updates only what changed.
//
// A step also keeps what it did as script lines (io/script/lod_script.h) when a script can say it, so the
// edits in effect can be saved as a script that `rgbsub apply` replays to the same mesh.
#include <cstddef>
#include <deque>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rgb/mesh/journal.h"
#include "rgb/rules/sharp_features.h"

namespace rgb {
class Mesh;
}

namespace app {

class UndoHistory {
public:
    // Follows `mesh` (for the history's lifetime); every change of it must happen inside an edit.
    explicit UndoHistory(rgb::Mesh& mesh, std::size_t byte_bound = std::size_t{1} << 30);

    // Around one undoable change of the mesh. end_edit with changed == false forgets it; `script`
    // says what it did, if a script can; a `label` replaces begin_edit's (work stopped part way).
    void begin_edit(std::string label);
    void end_edit(bool changed, std::optional<std::string> script = std::nullopt, std::optional<std::string> label = std::nullopt);
    bool editing() const { return journal_.recording(); }
    // Gives the base mesh other crease tags (rgb::set_sharp_features) as one step, outside any edit:
    // a retag keeps every slot, so the journal's records stay valid, and its step sets the tags it
    // replaced back. Throws std::invalid_argument for refused tags (nothing changes then).
    void retag(std::string label, const rgb::SharpFeatures& features);
    // Ends the edit under way without a step and puts the mesh back as it was at begin_edit (for an
    // edit that failed half-way). False when no edit is under way.
    bool abandon_edit();

    bool can_undo() const { return !undo_.empty(); }
    bool can_redo() const { return !redo_.empty(); }
    const std::string& undo_label() const { return undo_.back().label; }
    const std::string& redo_label() const { return redo_.back().label; }
    std::size_t undo_steps() const { return undo_.size(); }
    std::size_t redo_steps() const { return redo_.size(); }

    // Step back/forward; false when there is nothing to step to.
    bool undo();
    bool redo();
    void clear();

    // Undo and redo in pieces, for a step too large for one frame (its revert costs in proportion to
    // its operations: 0.15 s for the 140k of a large stroke). begin_undo/begin_redo take the step off
    // its side (false when there is none, or an edit is under way; a retag crosses whole at once);
    // continue_crossing reverts up to `max_steps` more of its operations, true once the step has
    // crossed (its reversal is then on the other side). Nothing else may change the mesh meanwhile.
    bool begin_undo();
    bool begin_redo();
    bool crossing() const { return crossing_.has_value(); }
    bool continue_crossing(std::size_t max_steps);
    // Operations of the step crossing now: done, and in all.
    std::size_t crossed_operations() const;
    std::size_t crossing_operations() const;
    // Stops the crossing part way: the part reverted goes to the other side as one step, the part
    // still in effect stays as one step (neither has a script then: none says a part of a stroke).
    void stop_crossing();

    // The script of every step in effect (undone ones left out, those forgotten for the memory
    // bound kept), and how many of them no script could say, with their labels (each once).
    struct SessionScript {
        std::string text;
        std::size_t unscripted_steps = 0;
        std::vector<std::string> unscripted_labels;
        void add(const std::optional<std::string>& script, const std::string& label);
    };
    SessionScript session_script() const;

    // Names the state of the mesh in the history: the same after an undo and its redo, different
    // for a new edit or a step stopped part way (meaningless while a step crosses).
    std::uint64_t position() const { return undo_.empty() ? bottom_ : undo_.back().serial; }

    std::size_t bytes() const { return bytes_; }
    std::size_t byte_bound() const { return byte_bound_; }
    void set_byte_bound(std::size_t bound);

private:
    struct Step {
        std::string label;
        rgb::JournalRecord record;  // what the step did; reverting it crosses to the other side
        std::optional<std::string> script;
        // For a retag, the tags that crossing the step sets (then `record` is empty).
        std::optional<rgb::SharpFeatures> retag;
        // The position() the step leads to, applied forwards (kept while it crosses back and forth).
        std::uint64_t serial = 0;
    };
    // Pops the newest step of `from` and starts reverting it into a step for `to`.
    bool begin_cross(std::deque<Step>& from, std::deque<Step>& to);
    // One-shot: begin_cross, then continue_crossing to the end.
    bool cross(std::deque<Step>& from, std::deque<Step>& to);
    // A change made outside any edit: records from before it no longer fit the mesh.
    void forget_if_stale();
    void push(std::deque<Step>& side, Step step);
    void enforce_bound();

    rgb::Mesh& mesh_;
    rgb::Journal journal_;
    std::size_t byte_bound_;
    std::size_t bytes_ = 0;
    std::deque<Step> undo_;  // oldest first
    std::deque<Step> redo_;  // most recently undone last
    std::string pending_label_;
    // The step being reverted, how far, and the sides it goes between.
    struct Crossing {
        Step step;
        rgb::JournalRecord::Cursor cursor;
        std::deque<Step>* from;
        std::deque<Step>* to;
    };
    std::optional<Crossing> crossing_;
    SessionScript forgotten_;  // steps in effect that the bound dropped from undo_
    std::uint64_t next_serial_ = 1;
    std::uint64_t bottom_ = 0;  // position() below the oldest step of undo_
};

}  // namespace app
