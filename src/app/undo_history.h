#pragma once
// Undo/redo per stroke or action, bit for bit, within a memory bound.
//
// This version keeps whole-state snapshots (rgb::capture_state) and hands back a restored mesh; the
// core's undo journal (recording only the slots an edit touches) replaces it behind this same
// interface: begin_edit / end_edit around every change, undo / redo to step.
#include <cstddef>
#include <deque>
#include <optional>
#include <string>

#include "rgb/state.h"

namespace rgb {
class Mesh;
}

namespace app {

class UndoHistory {
public:
    explicit UndoHistory(std::size_t byte_bound = std::size_t{1} << 30) : byte_bound_(byte_bound) {}

    // Around one undoable change of `mesh`. end_edit with changed == false forgets it.
    void begin_edit(const rgb::Mesh& mesh, std::string label);
    void end_edit(const rgb::Mesh& mesh, bool changed);
    bool editing() const { return pending_.has_value(); }
    // Ends the edit under way without a step and hands back the mesh as it was at begin_edit (for
    // an edit that failed half-way). Empty when no edit is under way.
    std::optional<rgb::Mesh> abandon_edit();

    bool can_undo() const { return !undo_.empty(); }
    bool can_redo() const { return !redo_.empty(); }
    const std::string& undo_label() const { return undo_.back().label; }
    const std::string& redo_label() const { return redo_.back().label; }
    std::size_t undo_steps() const { return undo_.size(); }
    std::size_t redo_steps() const { return redo_.size(); }

    // Step back/forward: the mesh as it was. Empty when there is nothing to step to.
    std::optional<rgb::Mesh> undo(const rgb::Mesh& current);
    std::optional<rgb::Mesh> redo(const rgb::Mesh& current);
    void clear();

    std::size_t bytes() const { return bytes_; }
    std::size_t byte_bound() const { return byte_bound_; }
    void set_byte_bound(std::size_t bound);

private:
    struct Step {
        std::string label;
        rgb::MeshState other;  // the state on the other side of the step
        std::size_t bytes = 0;
    };
    static Step make_step(std::string label, rgb::MeshState state);
    // Pops the newest step of `from`, pushes its opposite onto `to` and returns the mesh it restores.
    std::optional<rgb::Mesh> cross(std::deque<Step>& from, std::deque<Step>& to, const rgb::Mesh& current);
    void enforce_bound();

    std::size_t byte_bound_;
    std::size_t bytes_ = 0;
    std::deque<Step> undo_;  // oldest first
    std::deque<Step> redo_;  // most recently undone last
    std::optional<Step> pending_;
};

// What a state costs to keep.
std::size_t state_bytes(const rgb::MeshState& state);

}  // namespace app
