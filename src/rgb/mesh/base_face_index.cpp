#include "rgb/mesh/base_face_index.h"

#include <algorithm>
#include <numeric>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "rgb/mesh/base_mesh.h"
#include "rgb/support/triangle_geometry.h"

namespace rgb {

namespace {

constexpr std::uint32_t kLeafSize = 8;

double box_distance_squared(const glm::dvec3& p, const glm::dvec3& lo, const glm::dvec3& hi) {
    const glm::dvec3 d = glm::max(glm::max(lo - p, p - hi), glm::dvec3(0.0));
    return glm::dot(d, d);
}

}  // namespace

BaseFaceIndex::BaseFaceIndex(const BaseMesh& base) : base_(base), faces_(base.num_faces()) {
    std::iota(faces_.begin(), faces_.end(), 0u);
    if (faces_.empty()) return;
    // Each face's box and centroid once, rather than from its corners at every level of the build.
    std::vector<FaceBox> boxes(faces_.size());
    for (std::uint32_t f = 0; f < faces_.size(); ++f) {
        const auto c = base_.corner_positions(f);
        boxes[f] = {glm::min(glm::min(c[0], c[1]), c[2]), glm::max(glm::max(c[0], c[1]), c[2]), c[0] + c[1] + c[2]};
    }
    nodes_.reserve(2 * faces_.size() / kLeafSize + 2);
    nodes_.push_back({});
    build(boxes, 0, 0, static_cast<std::uint32_t>(faces_.size()));
}

void BaseFaceIndex::build(const std::vector<FaceBox>& boxes, std::uint32_t node, std::uint32_t begin, std::uint32_t end) {
    glm::dvec3 lo(1e300), hi(-1e300);
    for (std::uint32_t i = begin; i < end; ++i) {
        lo = glm::min(lo, boxes[faces_[i]].lo);
        hi = glm::max(hi, boxes[faces_[i]].hi);
    }
    nodes_[node] = {lo, hi, begin, end - begin};
    if (end - begin <= kLeafSize) return;
    // Split at the median of the centroids along the longest axis.
    const glm::dvec3 extent = hi - lo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const std::uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(faces_.begin() + begin, faces_.begin() + mid, faces_.begin() + end,
                     [&](std::uint32_t a, std::uint32_t b) { return boxes[a].centroid[axis] < boxes[b].centroid[axis]; });
    const auto left = static_cast<std::uint32_t>(nodes_.size());
    nodes_.push_back({});
    nodes_.push_back({});
    nodes_[node].first = left;
    nodes_[node].count = 0;
    build(boxes, left, begin, mid);
    build(boxes, left + 1, mid, end);
}

std::vector<std::uint32_t> BaseFaceIndex::faces_meeting_sphere(const glm::dvec3& centre, double radius) const {
    std::vector<std::uint32_t> found;
    if (nodes_.empty()) return found;
    const double r2 = radius * radius;
    std::vector<std::uint32_t> stack{0};
    while (!stack.empty()) {
        const Node& n = nodes_[stack.back()];
        stack.pop_back();
        // A little slack, so that rounding in the box test never drops a face the exact test keeps.
        if (box_distance_squared(centre, n.lo, n.hi) > r2 * (1.0 + 1e-12) + 1e-300) continue;
        if (n.count == 0) {
            stack.push_back(n.first);
            stack.push_back(n.first + 1);
            continue;
        }
        for (std::uint32_t i = n.first; i < n.first + n.count; ++i)
            if (triangle_meets_sphere(base_.corner_positions(faces_[i]), centre, radius)) found.push_back(faces_[i]);
    }
    std::sort(found.begin(), found.end());
    return found;
}

std::size_t BaseFaceIndex::memory_bytes() const { return faces_.size() * sizeof(std::uint32_t) + nodes_.size() * sizeof(Node); }

}  // namespace rgb
