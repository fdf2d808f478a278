#include "rgb/lod/view_priority.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace rgb {

std::optional<std::size_t> view_bucket(const Mesh& mesh, const ScreenCriterion& criterion, FaceId f, int from_level) {
    int level = kMaxLevel + 1;
    for (int i = 0; i < 3; ++i)
        if (const EdgeType t = mesh.edge_type(Mesh::halfedge(f, i)); t.colour == Colour::Green && t.level >= from_level)
            level = std::min(level, t.level);
    if (level > kMaxLevel) return std::nullopt;
    const ScreenView& view = criterion.view();
    const auto vertices = mesh.face_vertices(f);
    glm::dvec3 corners[3];
    glm::dvec2 screen[3];
    bool behind = false;
    for (std::size_t i = 0; i < 3; ++i) {
        corners[i] = mesh.base_space_position(vertices[i]);
        const glm::dvec4 clip = view.view_projection * glm::dvec4(corners[i], 1.0);
        behind = behind || clip.w <= 0.0;
        screen[i] = 0.5 * glm::dvec2(clip) / clip.w * view.viewport;
    }
    const bool seen = criterion.may_see(corners);
    // The longest side in pixels; a face reaching behind the eye counts as the largest.
    double pixels = 0.0;
    for (std::size_t i = 0; i < 3; ++i) pixels = std::max(pixels, glm::distance(screen[i], screen[(i + 1) % 3]));
    const int band = behind ? 0 : std::clamp(kViewSizeBands - 1 - static_cast<int>(std::floor(2.0 * std::log2(std::max(pixels, 1.0)))), 0, kViewSizeBands - 1);
    return (seen ? 0 : kViewBuckets / 2) + static_cast<std::size_t>(level * kViewSizeBands + band);
}

void FaceBuckets::push(std::size_t bucket, FaceId f) {
    buckets_[bucket].push_back(f);
    lowest_ = std::min(lowest_, bucket);
}

std::optional<FaceBuckets::Taken> FaceBuckets::pop() {
    for (; lowest_ < kViewBuckets; ++lowest_) {
        std::vector<FaceId>& bucket = buckets_[lowest_];
        if (bucket.empty()) continue;
        const FaceId f = bucket.back();
        bucket.pop_back();
        return Taken{f, static_cast<int>(lowest_ % (kViewBuckets / 2)) / kViewSizeBands};
    }
    return std::nullopt;
}

void FaceBuckets::clear() {
    for (std::vector<FaceId>& bucket : buckets_) bucket.clear();  // keeps their memory for the next pass
    lowest_ = kViewBuckets;
}

}  // namespace rgb
