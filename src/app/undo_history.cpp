#include "app/undo_history.h"

#include <utility>

#include "rgb/mesh.h"

namespace app {

std::size_t state_bytes(const rgb::MeshState& state) {
    return state.base_positions.capacity() * sizeof(glm::dvec3) + state.base_triangles.capacity() * sizeof(rgb::Triangle) +
           state.vertices.capacity() * sizeof(rgb::SurfacePoint) + state.faces.capacity() * sizeof(rgb::Triangle);
}

UndoHistory::Step UndoHistory::make_step(std::string label, rgb::MeshState state) {
    const std::size_t bytes = state_bytes(state);
    return Step{std::move(label), std::move(state), bytes};
}

void UndoHistory::begin_edit(const rgb::Mesh& mesh, std::string label) {
    pending_ = make_step(std::move(label), rgb::capture_state(mesh));
}

void UndoHistory::end_edit(const rgb::Mesh& /*mesh*/, bool changed) {
    if (!pending_) return;
    if (changed) {
        for (const Step& step : redo_) bytes_ -= step.bytes;
        redo_.clear();
        bytes_ += pending_->bytes;
        undo_.push_back(std::move(*pending_));
        enforce_bound();
    }
    pending_.reset();
}

std::optional<rgb::Mesh> UndoHistory::abandon_edit() {
    if (!pending_) return std::nullopt;
    const Step step = std::move(*pending_);
    pending_.reset();
    return rgb::restore_state(step.other);
}

std::optional<rgb::Mesh> UndoHistory::cross(std::deque<Step>& from, std::deque<Step>& to, const rgb::Mesh& current) {
    if (from.empty()) return std::nullopt;
    Step step = std::move(from.back());
    from.pop_back();
    rgb::Mesh restored = rgb::restore_state(step.other);
    bytes_ -= step.bytes;
    Step opposite = make_step(std::move(step.label), rgb::capture_state(current));
    bytes_ += opposite.bytes;
    to.push_back(std::move(opposite));
    enforce_bound();
    return restored;
}

std::optional<rgb::Mesh> UndoHistory::undo(const rgb::Mesh& current) { return cross(undo_, redo_, current); }

std::optional<rgb::Mesh> UndoHistory::redo(const rgb::Mesh& current) { return cross(redo_, undo_, current); }

void UndoHistory::clear() {
    undo_.clear();
    redo_.clear();
    pending_.reset();
    bytes_ = 0;
}

void UndoHistory::set_byte_bound(std::size_t bound) {
    byte_bound_ = bound;
    enforce_bound();
}

// Forgets the oldest steps first (the redo side's oldest is its front, the furthest step away).
void UndoHistory::enforce_bound() {
    while (bytes_ > byte_bound_ && (!undo_.empty() || !redo_.empty())) {
        std::deque<Step>& side = undo_.empty() ? redo_ : undo_;
        bytes_ -= side.front().bytes;
        side.pop_front();
    }
}

}  // namespace app
