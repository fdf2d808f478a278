#include "app/request_job.h"

#include <utility>

#include "rgb/mesh.h"

namespace app {

RequestJob::RequestJob(rgb::Mesh& mesh, std::string label, bool open) : mesh_(mesh), label_(std::move(label)), stroke_(open), open_(open) {}

void RequestJob::add(Pieces pieces, const std::string& script_lines) {
    requests_.push_back([this, pieces = std::move(pieces)] {
        std::vector<Whole> cut;
        for (rgb::LevelRequest& piece : pieces()) cut.push_back([this, piece = std::move(piece)] { return rgb::apply_request(mesh_, piece); });
        return cut;
    });
    script_ += script_lines;
}

void RequestJob::add_whole(Whole apply, const std::string& script_lines) {
    requests_.push_back([apply = std::move(apply)] { return std::vector<Whole>{apply}; });
    script_ += script_lines;
}

bool RequestJob::step(std::chrono::microseconds slice) {
    using Clock = std::chrono::steady_clock;
    const auto deadline = Clock::now() + slice;
    const auto piece_time = [&] { return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(piece_seconds_)); };
    // At least one piece, however short the slice; then another while one is expected to fit.
    for (bool applied = false; !applied || Clock::now() + piece_time() < deadline;) {
        if (pieces_.empty()) {
            if (requests_.empty()) break;
            for (Whole& piece : requests_.front()()) pieces_.push_back(std::move(piece));
            requests_.pop_front();
            pieces_done_ = 0;
            if (pieces_.empty()) ++requests_done_;
            continue;
        }
        const auto start = Clock::now();
        stats_ += pieces_.front()();
        const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
        piece_seconds_ = pieces_done_ + requests_done_ == 0 ? seconds : 0.8 * piece_seconds_ + 0.2 * seconds;
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
