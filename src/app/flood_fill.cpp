#include "app/flood_fill.h"

#include <algorithm>
#include <vector>

#include "rgb/mesh.h"
#include "rgb/requests.h"

namespace app {
namespace {
constexpr std::uint32_t kBaseFacesPerBatch = 64;
}

FloodFillJob::FloodFillJob(rgb::Mesh& mesh, int level) : mesh_(mesh), level_(level) {}

// A whole-surface "set level" split into requests over batches of base faces: requests of one level
// over disjoint regions give the same mesh in any grouping (spec §3.5), so the slices add up to it.
bool FloodFillJob::step(std::chrono::microseconds slice) {
    const auto deadline = std::chrono::steady_clock::now() + slice;
    const auto base_faces = static_cast<std::uint32_t>(mesh_.base().num_faces());
    while (next_base_face_ < base_faces && std::chrono::steady_clock::now() < deadline) {
        rgb::LevelRequest request;
        request.level = level_;
        const std::uint32_t end = std::min(next_base_face_ + kBaseFacesPerBatch, base_faces);
        for (; next_base_face_ < end; ++next_base_face_) request.base_faces.push_back(next_base_face_);
        const rgb::RequestStats stats = rgb::apply_request(mesh_, request);
        changed_ |= stats.splits + stats.removals > 0;
    }
    return next_base_face_ < base_faces;
}

float FloodFillJob::progress() const {
    const auto total = mesh_.base().num_faces();
    return total == 0 ? 1.0f : static_cast<float>(next_base_face_) / static_cast<float>(total);
}

std::string FloodFillJob::label() const { return "set all to level " + std::to_string(level_); }

}  // namespace app
