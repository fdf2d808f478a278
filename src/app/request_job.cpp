#include "app/request_job.h"

#include <utility>

#include "rgb/mesh.h"

namespace app {

RequestJob::RequestJob(rgb::Mesh& mesh, std::string label, bool open) : mesh_(mesh), label_(std::move(label)), stroke_(open), open_(open) {}

void RequestJob::add(Pieces pieces, const std::string& script_lines) {
    requests_.push_back(std::move(pieces));
    script_ += script_lines;
}

bool RequestJob::step(std::chrono::microseconds slice) {
    const auto deadline = std::chrono::steady_clock::now() + slice;
    // At least one piece, however short the slice.
    for (bool applied = false; !applied || std::chrono::steady_clock::now() < deadline;) {
        if (pieces_.empty()) {
            if (requests_.empty()) break;
            for (rgb::LevelRequest& piece : requests_.front()()) pieces_.push_back(std::move(piece));
            requests_.pop_front();
            pieces_done_ = 0;
            if (pieces_.empty()) ++requests_done_;
            continue;
        }
        stats_ += rgb::apply_request(mesh_, pieces_.front());
        pieces_.pop_front();
        ++pieces_done_;
        if (pieces_.empty()) ++requests_done_;
        applied = true;
    }
    return open_ || !pieces_.empty() || !requests_.empty();
}

// Requests done, and the part of the one under way that its pieces done make.
float RequestJob::progress() const {
    const std::size_t total = requests_done_ + requests_.size() + (pieces_.empty() ? 0 : 1);
    if (total == 0) return 1.0f;
    const double current = pieces_.empty() ? 0.0 : static_cast<double>(pieces_done_) / static_cast<double>(pieces_done_ + pieces_.size());
    return static_cast<float>((static_cast<double>(requests_done_) + current) / static_cast<double>(total));
}

void RequestJob::cancel() {
    dropped_ = dropped_ || !pieces_.empty() || !requests_.empty();
    pieces_.clear();
    requests_.clear();
    open_ = false;
}

std::optional<std::string> RequestJob::script() const {
    if (dropped_) return std::nullopt;
    return script_;
}

}  // namespace app
