#include "app/undo_history.h"

#include <algorithm>
#include <utility>

#include "rgb/mesh/mesh.h"
#include "rgb/values/restore_state.h"

namespace app {

UndoHistory::UndoHistory(rgb::Mesh& mesh, std::size_t byte_bound) : mesh_(mesh), journal_(mesh), byte_bound_(byte_bound) {}

void UndoHistory::begin_edit(std::string label) {
    forget_if_stale();
    pending_label_ = std::move(label);
    journal_.start();
}

void UndoHistory::end_edit(bool changed, std::optional<std::string> script, std::optional<std::string> label) {
    if (!journal_.recording()) return;
    rgb::JournalRecord record = journal_.stop();
    if (!changed || record.empty()) return;
    for (const Step& step : redo_) bytes_ -= step.record.bytes();
    redo_.clear();
    push(undo_, Step{label ? std::move(*label) : std::move(pending_label_), std::move(record), std::move(script), std::nullopt, next_serial_++});
}

void UndoHistory::retag(std::string label, const rgb::SharpFeatures& features) {
    forget_if_stale();
    rgb::SharpFeatures replaced = mesh_.base().sharp_features();
    rgb::set_sharp_features(mesh_, features);
    for (const Step& step : redo_) bytes_ -= step.record.bytes();
    redo_.clear();
    push(undo_, Step{std::move(label), {}, std::nullopt, std::move(replaced), next_serial_++});
}

// An edit, or a crossing (then its step goes back where it was, whole).
bool UndoHistory::abandon_edit() {
    if (!journal_.recording()) return false;
    const rgb::JournalRecord record = journal_.stop();
    std::optional<Crossing> crossing = std::exchange(crossing_, std::nullopt);
    try {
        journal_.revert(record);
    } catch (...) {
        clear();
        throw;
    }
    if (crossing) push(*crossing->from, std::move(crossing->step));
    return true;
}

bool UndoHistory::begin_cross(std::deque<Step>& from, std::deque<Step>& to) {
    forget_if_stale();
    if (from.empty() || journal_.recording()) return false;
    Step step = std::move(from.back());
    from.pop_back();
    bytes_ -= step.record.bytes();
    if (step.retag) {
        rgb::SharpFeatures replaced = mesh_.base().sharp_features();
        rgb::set_sharp_features(mesh_, *step.retag);
        push(to, Step{std::move(step.label), {}, std::move(step.script), std::move(replaced), step.serial});
        return true;
    }
    journal_.start();
    const rgb::JournalRecord::Cursor end = step.record.end();
    crossing_ = Crossing{std::move(step), end, &from, &to};
    return true;
}

bool UndoHistory::continue_crossing(std::size_t max_steps) {
    if (!crossing_) return true;
    try {
        if (!journal_.revert_some(crossing_->step.record, crossing_->cursor, max_steps)) return false;
    } catch (...) {
        // Half reverted, or the mesh no longer fits the records: none can be trusted.
        journal_.stop();
        crossing_.reset();
        clear();
        throw;
    }
    Crossing crossed = std::move(*crossing_);
    crossing_.reset();
    push(*crossed.to, Step{std::move(crossed.step.label), journal_.stop(), std::move(crossed.step.script), std::nullopt, crossed.step.serial});
    return true;
}

std::size_t UndoHistory::crossed_operations() const {
    return crossing_ ? crossing_->step.record.steps() - crossing_->cursor.steps : 0;
}

std::size_t UndoHistory::crossing_operations() const { return crossing_ ? crossing_->step.record.steps() : 0; }

void UndoHistory::stop_crossing() {
    if (!crossing_) return;
    Crossing stopped = std::move(*crossing_);
    crossing_.reset();
    rgb::JournalRecord reverted = journal_.stop();
    if (reverted.empty()) {
        push(*stopped.from, std::move(stopped.step));
        return;
    }
    // Both parts lead to states no step led to before, and no script says a part of a step.
    Step rest = std::move(stopped.step);
    rest.record.truncate(stopped.cursor);
    const std::string label = rest.label + ", in part";
    if (!rest.record.empty()) push(*stopped.from, Step{label, std::move(rest.record), std::nullopt, std::nullopt, next_serial_++});
    push(*stopped.to, Step{label, std::move(reverted), std::nullopt, std::nullopt, next_serial_++});
}

bool UndoHistory::cross(std::deque<Step>& from, std::deque<Step>& to) {
    if (!begin_cross(from, to)) return false;
    continue_crossing(crossing_operations());
    return true;
}

bool UndoHistory::undo() { return cross(undo_, redo_); }

bool UndoHistory::redo() { return cross(redo_, undo_); }

bool UndoHistory::begin_undo() { return begin_cross(undo_, redo_); }

bool UndoHistory::begin_redo() { return begin_cross(redo_, undo_); }

void UndoHistory::clear() {
    if (crossing_) {
        journal_.stop();
        crossing_.reset();
    }
    undo_.clear();
    redo_.clear();
    bytes_ = 0;
    forgotten_ = {};
    bottom_ = next_serial_++;
}

UndoHistory::SessionScript UndoHistory::session_script() const {
    SessionScript session = forgotten_;
    for (const Step& step : undo_) session.add(step.script, step.label);
    return session;
}

void UndoHistory::SessionScript::add(const std::optional<std::string>& script, const std::string& label) {
    if (script) {
        text += *script;
        return;
    }
    ++unscripted_steps;
    if (std::find(unscripted_labels.begin(), unscripted_labels.end(), label) == unscripted_labels.end())
        unscripted_labels.push_back(label);
}

void UndoHistory::forget_if_stale() {
    if (!journal_.take_unrecorded_change()) return;
    SessionScript in_effect = session_script();
    in_effect.add(std::nullopt, "a change outside the undo history");  // the change itself
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
            forgotten_.add(side.front().script, side.front().label);
            bottom_ = side.front().serial;
        }
        bytes_ -= side.front().record.bytes();
        side.pop_front();
    }
}

}  // namespace app
