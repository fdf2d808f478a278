#pragma once
// Requests applied one after another, as many per step as fit in the time given: a brush stroke
// (its dabs' pieces arrive while it runs, request_pieces.h) or "set all" (every piece known at the
// start). The pieces of one request are canonical, so the result is the mesh the requests give whole.
#include <cstddef>
#include <deque>
#include <functional>
#include <string>
#include <vector>

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

    // What makes a request's pieces (request_pieces.h); called when the job reaches the request, so
    // that adding costs nothing and the pieces are cut for the mesh as it then is.
    using Pieces = std::function<std::vector<rgb::LevelRequest>()>;
    // Appends one request and the script lines that say it.
    void add(Pieces pieces, const std::string& script_lines);
    // Appends a request applied whole, in one piece (a detail-size dab: small, and its criterion
    // cuts no pieces), and the script lines that say it.
    using Whole = std::function<rgb::RequestStats()>;
    void add_whole(Whole apply, const std::string& script_lines);
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

private:
    rgb::Mesh& mesh_;
    std::string label_;
    bool stroke_;
    bool open_;
    // A request not cut yet, and the pieces of the one under way, each as what applies it.
    using Cut = std::function<std::vector<Whole>()>;
    std::deque<Cut> requests_;
    std::deque<Whole> pieces_;
    std::size_t requests_done_ = 0;
    std::size_t pieces_done_ = 0;  // of the request under way
    rgb::RequestStats stats_;
    double piece_seconds_ = 0.0;  // a running mean of what pieces take, to stop before the deadline
    std::string script_;
    bool dropped_ = false;
};

}  // namespace app
