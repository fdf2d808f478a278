#pragma once
// Requests applied one after another, as many per step as fit in the time given: a brush stroke
// (its dabs' pieces arrive while it runs, request_pieces.h) or "set all" (every piece known at the
// start). The pieces of one request are canonical, so the result is the mesh the requests give whole.
// A piece over a batch of base faces is cut further while it runs, to what the time left in the step
// allows at the pace pieces of its kind and level have gone (the pieces are cut from estimates of
// the triangles there, which can be several times off where a stroke made the mesh denser than
// elsewhere); any partition of the batch gives the same mesh.
#include <cstddef>
#include <deque>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/mesh_job.h"
#include "rgb/lod/requests.h"

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
    // A piece: a request over a batch of base faces (cut further as time allows), or one applied whole.
    struct Piece {
        std::optional<rgb::LevelRequest> request;
        Whole whole;
    };
    // The part of the front piece to apply within `left` seconds (at least one base face); the rest
    // stays at the front.
    Piece take_front(double left);
    rgb::RequestStats apply(const Piece& piece);
    // Seconds per base face of the pieces of a kind and level so far (0: none yet).
    double& pace(const rgb::LevelRequest& request);

    // A request not cut yet, and the pieces of the one under way.
    using Cut = std::function<std::vector<Piece>()>;
    std::deque<Cut> requests_;
    std::deque<Piece> pieces_;
    std::map<std::pair<int, int>, double> pace_;  // by kind and level
    std::size_t requests_done_ = 0;
    std::size_t pieces_done_ = 0;  // of the request under way
    std::size_t front_faces_ = 0;  // base faces the front piece had when first cut further (0: not cut)
    rgb::RequestStats stats_;
    double piece_seconds_ = 0.0;  // a running mean of what pieces take, to stop before the deadline
    std::string script_;
    bool dropped_ = false;
};

}  // namespace app
