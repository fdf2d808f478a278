#include "app/flood_fill.h"

#include <algorithm>
#include <vector>

#include "rgb/mesh.h"
#include "rgb/refine.h"

namespace app {
namespace {
constexpr std::uint32_t kSlotsPerBatch = 256;
}

FloodFillJob::FloodFillJob(rgb::Mesh& mesh, int level) : mesh_(mesh), level_(level) {}

bool FloodFillJob::step(std::chrono::microseconds slice) {
    const auto deadline = std::chrono::steady_clock::now() + slice;
    std::vector<rgb::FaceId> seeds;
    // The capacity grows while refining; slots beyond the cursor are revisited, which is harmless
    // (a face already at its target costs one check).
    while (next_slot_ < mesh_.face_capacity() && std::chrono::steady_clock::now() < deadline) {
        seeds.clear();
        const std::uint32_t end = std::min<std::uint32_t>(next_slot_ + kSlotsPerBatch,
                                                          static_cast<std::uint32_t>(mesh_.face_capacity()));
        for (; next_slot_ < end; ++next_slot_)
            if (mesh_.is_live(rgb::FaceId(next_slot_))) seeds.push_back(rgb::FaceId(next_slot_));
        const rgb::SetLevelStats stats =
            rgb::set_level_faces(mesh_, seeds, [this](const glm::dvec3&) { return level_; }, rgb::LodDirection::Both);
        changed_ |= stats.splits + stats.removals > 0;
    }
    return next_slot_ < mesh_.face_capacity();
}

float FloodFillJob::progress() const {
    return mesh_.face_capacity() == 0 ? 1.0f
                                      : static_cast<float>(next_slot_) / static_cast<float>(mesh_.face_capacity());
}

std::string FloodFillJob::label() const { return "set all to level " + std::to_string(level_); }

}  // namespace app
