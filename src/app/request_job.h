#pragma once
// Requests applied one after another, as many per step as fit in the time given: a brush stroke
// (its dabs' pieces arrive while it runs, request_pieces.h) or "set all" (every piece known at the
// start). The pieces of one request are canonical, so the result is the mesh the requests give whole.
#include <cstddef>
#include <deque>
#include <string>

#include "app/mesh_job.h"
#include "rgb/requests.h"

namespace rgb {
class Mesh;
}

namespace app {

class RequestJob : public MeshJob {
public:
    // An open job (a brush stroke) takes more pieces until close().
    RequestJob(rgb::Mesh& mesh, std::string label, bool open);

    // Appends the pieces of one request and the script lines that say it.
    void add(std::vector<rgb::LevelRequest> pieces, const std::string& script_lines);
    void close() { open_ = false; }

    bool step(std::chrono::microseconds slice) override;
    float progress() const override;
    bool changed() const override { return stats_.splits + stats_.removals > 0; }
    std::string label() const override { return label_; }
    bool is_stroke() const override { return stroke_; }
    void cancel() override;
    std::optional<std::string> script() const override;

    // Splits and removals so far.
    const rgb::RequestStats& stats() const { return stats_; }
    std::size_t pieces_left() const { return pieces_.size(); }

private:
    rgb::Mesh& mesh_;
    std::string label_;
    bool stroke_;
    bool open_;
    std::deque<rgb::LevelRequest> pieces_;
    std::size_t pieces_done_ = 0;
    rgb::RequestStats stats_;
    std::string script_;
    bool dropped_ = false;
};

}  // namespace app
