#include "app/history_job.h"

#include <utility>

#include "app/document.h"

namespace app {

namespace {

// Operations between looks at the clock: about a millisecond.
constexpr std::size_t kPieceOperations = 1024;

}  // namespace

HistoryJob::HistoryJob(Document& document, Direction direction, std::string step_label)
    : document_(document), direction_(direction), step_label_(std::move(step_label)) {}

bool HistoryJob::step(std::chrono::microseconds slice) {
    const auto deadline = std::chrono::steady_clock::now() + slice;
    do {
        if (document_.continue_crossing(kPieceOperations)) return false;
    } while (std::chrono::steady_clock::now() < deadline);
    return true;
}

float HistoryJob::progress() const {
    const UndoHistory& history = document_.history();
    const std::size_t all = history.crossing_operations();
    return all == 0 ? 1.0f : static_cast<float>(history.crossed_operations()) / static_cast<float>(all);
}

bool HistoryJob::changed() const { return stopped_changed_ || document_.history().crossed_operations() > 0; }

std::string HistoryJob::label() const { return (direction_ == Direction::Undo ? "undo " : "redo ") + step_label_; }

void HistoryJob::cancel() {
    stopped_changed_ = document_.history().crossed_operations() > 0;
    document_.stop_crossing();
}

std::string HistoryJob::done_message() const { return (direction_ == Direction::Undo ? "undid " : "redid ") + step_label_; }

std::string HistoryJob::cancelled_message(bool changed) const {
    if (!changed) return label() + " cancelled";
    return direction_ == Direction::Undo ? label() + " stopped part way: Ctrl+Z undoes the rest, Ctrl+Y redoes the part undone"
                                         : label() + " stopped part way: Ctrl+Y redoes the rest, Ctrl+Z undoes the part redone";
}

}  // namespace app
