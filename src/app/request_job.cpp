#include "app/request_job.h"

#include <utility>

#include "rgb/mesh.h"

namespace app {

RequestJob::RequestJob(rgb::Mesh& mesh, std::string label, bool open) : mesh_(mesh), label_(std::move(label)), stroke_(open), open_(open) {}

void RequestJob::add(std::vector<rgb::LevelRequest> pieces, const std::string& script_lines) {
    for (rgb::LevelRequest& piece : pieces) pieces_.push_back(std::move(piece));
    script_ += script_lines;
}

bool RequestJob::step(std::chrono::microseconds slice) {
    const auto deadline = std::chrono::steady_clock::now() + slice;
    do {
        if (pieces_.empty()) break;
        stats_ += rgb::apply_request(mesh_, pieces_.front());
        pieces_.pop_front();
        ++pieces_done_;
    } while (std::chrono::steady_clock::now() < deadline);
    return open_ || !pieces_.empty();
}

float RequestJob::progress() const {
    const std::size_t total = pieces_done_ + pieces_.size();
    return total == 0 ? 1.0f : static_cast<float>(pieces_done_) / static_cast<float>(total);
}

void RequestJob::cancel() {
    dropped_ = dropped_ || !pieces_.empty();
    pieces_.clear();
    open_ = false;
}

std::optional<std::string> RequestJob::script() const {
    if (dropped_) return std::nullopt;
    return script_;
}

}  // namespace app
