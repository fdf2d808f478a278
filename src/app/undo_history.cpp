#include "app/undo_history.h"

#include <utility>

#include "rgb/mesh.h"
#include "rgb/state.h"

namespace app {

UndoHistory::UndoHistory(rgb::Mesh& mesh, std::size_t byte_bound) : mesh_(mesh), journal_(mesh), byte_bound_(byte_bound) {}

void UndoHistory::begin_edit(std::string label) {
    forget_if_stale();
    pending_label_ = std::move(label);
    journal_.start();
}

void UndoHistory::end_edit(bool changed, std::optional<std::string> script) {
    if (!journal_.recording()) return;
    rgb::JournalRecord record = journal_.stop();
    if (!changed || record.empty()) return;
    for (const Step& step : redo_) bytes_ -= step.record.bytes();
    redo_.clear();
    push(undo_, Step{std::move(pending_label_), std::move(record), std::move(script), std::nullopt});
}

void UndoHistory::retag(std::string label, const rgb::SharpFeatures& features) {
    forget_if_stale();
    rgb::SharpFeatures replaced = mesh_.base().sharp_features();
    rgb::set_sharp_features(mesh_, features);
    for (const Step& step : redo_) bytes_ -= step.record.bytes();
    redo_.clear();
    push(undo_, Step{std::move(label), {}, std::nullopt, std::move(replaced)});
}

bool UndoHistory::abandon_edit() {
    if (!journal_.recording()) return false;
    const rgb::JournalRecord record = journal_.stop();
    try {
        journal_.revert(record);
    } catch (...) {
        clear();
        throw;
    }
    return true;
}

bool UndoHistory::cross(std::deque<Step>& from, std::deque<Step>& to) {
    forget_if_stale();
    if (from.empty() || journal_.recording()) return false;
    Step step = std::move(from.back());
    from.pop_back();
    bytes_ -= step.record.bytes();
    if (step.retag) {
        rgb::SharpFeatures replaced = mesh_.base().sharp_features();
        rgb::set_sharp_features(mesh_, *step.retag);
        push(to, Step{std::move(step.label), {}, std::move(step.script), std::move(replaced)});
        return true;
    }
    journal_.start();
    try {
        journal_.revert(step.record);
    } catch (...) {
        // Half reverted, or the mesh no longer fits the records: none can be trusted.
        journal_.stop();
        clear();
        throw;
    }
    push(to, Step{std::move(step.label), journal_.stop(), std::move(step.script), std::nullopt});
    return true;
}

bool UndoHistory::undo() { return cross(undo_, redo_); }

bool UndoHistory::redo() { return cross(redo_, undo_); }

void UndoHistory::clear() {
    undo_.clear();
    redo_.clear();
    bytes_ = 0;
    forgotten_ = {};
}

UndoHistory::SessionScript UndoHistory::session_script() const {
    SessionScript session = forgotten_;
    for (const Step& step : undo_) {
        if (step.script) session.text += *step.script;
        else ++session.unscripted_steps;
    }
    return session;
}

void UndoHistory::forget_if_stale() {
    if (!journal_.take_unrecorded_change()) return;
    SessionScript in_effect = session_script();
    ++in_effect.unscripted_steps;  // the change itself
    clear();
    forgotten_ = std::move(in_effect);
}

void UndoHistory::push(std::deque<Step>& side, Step step) {
    bytes_ += step.record.bytes();
    side.push_back(std::move(step));
    enforce_bound();
}

void UndoHistory::set_byte_bound(std::size_t bound) {
    byte_bound_ = bound;
    enforce_bound();
}

// Forgets the oldest steps first (the redo side's oldest is its front, the furthest step away).
void UndoHistory::enforce_bound() {
    while (bytes_ > byte_bound_ && (!undo_.empty() || !redo_.empty())) {
        std::deque<Step>& side = undo_.empty() ? redo_ : undo_;
        if (&side == &undo_) {
            // Still in effect, only no longer undoable.
            if (side.front().script) forgotten_.text += *side.front().script;
            else ++forgotten_.unscripted_steps;
        }
        bytes_ -= side.front().record.bytes();
        side.pop_front();
    }
}

}  // namespace app
