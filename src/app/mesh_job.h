#pragma once
// Work on the mesh that may take longer than a frame (a brush stroke, flood fill, automatic LOD),
// done a time slice per frame so the window keeps drawing and the user can cancel. Each job is one
// undoable step; the editor treats every job alike.
#include <chrono>
#include <optional>
#include <string>

namespace app {

class MeshJob {
public:
    virtual ~MeshJob() = default;
    // Works for about `slice` (at least one unit of work); returns false once finished.
    virtual bool step(std::chrono::microseconds slice) = 0;
    // In [0, 1].
    virtual float progress() const = 0;
    virtual bool changed() const = 0;
    virtual std::string label() const = 0;
    // A brush stroke (strokes may queue behind strokes; nothing queues behind whole-mesh work).
    virtual bool is_stroke() const { return false; }
    // Stops early: what is done stays, what is not is dropped.
    virtual void cancel() = 0;
    // What the job did as lines of a level-of-detail script (io/script/lod_script.h), when a script can
    // say it exactly.
    virtual std::optional<std::string> script() const = 0;
    // Whether the editor opens an undoable edit around the job (an undo or redo crosses a step of
    // the history instead, history_job.h).
    virtual bool makes_edit() const { return true; }
    // The status line once it is done, and once it was stopped (`changed`: it did something).
    virtual std::string done_message() const { return label() + " done"; }
    virtual std::string cancelled_message(bool changed) const {
        return label() + " cancelled" + (changed ? "; Ctrl+Z undoes what it did" : "");
    }
};

}  // namespace app
