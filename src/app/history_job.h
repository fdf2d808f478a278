#pragma once
// An undo or redo too large for one frame (a stroke of 140k operations takes 0.15 s to revert at
// 3.8M triangles), crossing its step of the history a slice per frame like any other job: the
// display follows each frame, the status line shows how far it got, and Esc stops it with what is
// done kept, as other jobs do: the part crossed and the part not crossed become two steps
// (UndoHistory::stop_crossing), so Ctrl+Z and Ctrl+Y go on from there.
#include <chrono>
#include <optional>
#include <string>

#include "app/mesh_job.h"

namespace app {

class Document;

class HistoryJob : public MeshJob {
public:
    enum class Direction { Undo, Redo };
    // Operations a crossing makes at once when it starts (Editor::undo), a few milliseconds' worth:
    // a step of no more is done before the call returns, without a job.
    static constexpr std::size_t kImmediateOperations = 8192;

    // Takes over the crossing `document` began (Document::begin_undo or begin_redo) of the step
    // labelled `step_label`.
    HistoryJob(Document& document, Direction direction, std::string step_label);

    bool step(std::chrono::microseconds slice) override;
    float progress() const override;
    bool changed() const override;
    std::string label() const override;
    void cancel() override;
    std::optional<std::string> script() const override { return std::nullopt; }
    bool makes_edit() const override { return false; }
    std::string done_message() const override;
    std::string cancelled_message(bool changed) const override;

private:
    Document& document_;
    Direction direction_;
    std::string step_label_;
    bool stopped_changed_ = false;  // whether cancel() stopped a crossing that had crossed something
};

}  // namespace app
