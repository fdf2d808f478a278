#include "app/request_job.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "app/request_pieces.h"
#include "rgb/mesh/mesh.h"

namespace app {

RequestJob::RequestJob(rgb::Mesh& mesh, std::string label, bool open) : mesh_(mesh), label_(std::move(label)), stroke_(open), open_(open) {}

void RequestJob::add(Pieces pieces, const std::string& script_lines) {
    requests_.push_back([pieces = std::move(pieces)] {
        std::vector<Piece> cut;
        for (rgb::LevelRequest& piece : pieces()) cut.push_back({std::move(piece), {}});
        return cut;
    });
    script_ += script_lines;
}

void RequestJob::add_whole(Whole apply, const std::string& script_lines) {
    requests_.push_back([apply = std::move(apply)] { return std::vector<Piece>{{std::nullopt, apply}}; });
    script_ += script_lines;
}

double& RequestJob::pace(const rgb::LevelRequest& request) { return pace_[{static_cast<int>(request.kind), request.level}]; }

RequestJob::Piece RequestJob::take_front(double left) {
    Piece& front = pieces_.front();
    if (front.request) {
        std::vector<std::uint32_t>& faces = front.request->base_faces;
        // A request without a restriction is the request restricted to the faces it may touch.
        if (faces.empty()) faces = request_base_faces(mesh_, *front.request);
        const double per_face = pace(*front.request);
        // Of a kind and level not seen yet, one base face first, to learn the pace.
        const double fit = per_face > 0.0 ? std::floor(left / per_face) : 1.0;
        const auto taken = static_cast<std::ptrdiff_t>(std::clamp(fit, 1.0, std::max(static_cast<double>(faces.size()), 1.0)));
        if (taken < std::ssize(faces)) {
            if (front_faces_ == 0) front_faces_ = faces.size();
            Piece part{rgb::LevelRequest(*front.request), {}};
            part.request->base_faces.assign(faces.begin(), faces.begin() + taken);
            faces.erase(faces.begin(), faces.begin() + taken);
            return part;
        }
    }
    Piece piece = std::move(front);
    pieces_.pop_front();
    ++pieces_done_;
    front_faces_ = 0;
    return piece;
}

rgb::RequestStats RequestJob::apply(const Piece& piece) {
    if (!piece.request) return piece.whole();
    // Restricted to no face (its ball meets none), the request does nothing; unrestricted it would
    // be the whole surface.
    if (piece.request->base_faces.empty()) return {};
    return rgb::apply_request(mesh_, *piece.request);
}

bool RequestJob::step(std::chrono::microseconds slice) {
    using Clock = std::chrono::steady_clock;
    const auto deadline = Clock::now() + slice;
    // At least one piece, however short the slice; then another while one is expected to fit.
    for (bool applied = false;;) {
        if (pieces_.empty()) {
            if (requests_.empty()) break;
            for (Piece& piece : requests_.front()()) pieces_.push_back(std::move(piece));
            requests_.pop_front();
            pieces_done_ = 0;
            if (pieces_.empty()) ++requests_done_;
            continue;
        }
        const double left = std::chrono::duration<double>(deadline - Clock::now()).count();
        const Piece& front = pieces_.front();
        const double at_least = front.request && pace(*front.request) > 0.0 ? pace(*front.request) : piece_seconds_;
        if (applied && left < at_least) break;
        const Piece piece = take_front(left);
        const auto start = Clock::now();
        stats_ += apply(piece);
        const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
        piece_seconds_ = piece_seconds_ > 0.0 ? 0.8 * piece_seconds_ + 0.2 * seconds : seconds;
        if (piece.request && !piece.request->base_faces.empty()) {
            // Quick to follow a slower region, slow to trust a faster one: frames stay within the slice.
            const double measured = seconds / static_cast<double>(piece.request->base_faces.size());
            double& per_face = pace(*piece.request);
            per_face = per_face > 0.0 ? std::max(measured, 0.7 * per_face + 0.3 * measured) : measured;
        }
        if (pieces_.empty()) ++requests_done_;
        applied = true;
    }
    return open_ || !pieces_.empty() || !requests_.empty();
}

// Requests done, and the part of the one under way that its pieces done make.
float RequestJob::progress() const {
    const std::size_t total = requests_done_ + requests_.size() + (pieces_.empty() ? 0 : 1);
    if (total == 0) return 1.0f;
    // The front piece, when cut further, counts by the base faces it has left.
    const double front_done =
        front_faces_ == 0 ? 0.0 : 1.0 - static_cast<double>(pieces_.front().request->base_faces.size()) / static_cast<double>(front_faces_);
    const double current =
        pieces_.empty() ? 0.0 : (static_cast<double>(pieces_done_) + front_done) / static_cast<double>(pieces_done_ + pieces_.size());
    return static_cast<float>((static_cast<double>(requests_done_) + current) / static_cast<double>(total));
}

void RequestJob::cancel() {
    dropped_ = dropped_ || !pieces_.empty() || !requests_.empty();
    pieces_.clear();
    front_faces_ = 0;
    requests_.clear();
    open_ = false;
}

std::optional<std::string> RequestJob::script() const {
    if (dropped_) return std::nullopt;
    return script_;
}

}  // namespace app
