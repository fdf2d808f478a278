// The search tree's build (surface_tree.h): recursive median splits into a tree of double boxes, then
// compacted into the searched layout of float boxes rounded outwards.
#include "detail/surface_tree.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <glm/common.hpp>

namespace rgbdetail::dense_surface_internal {

namespace {

constexpr std::uint32_t kLeafSize = 4;

// The tree as built: count > 0 is a leaf of triangles [first, first + count) in the reordered
// arrays; else an inner node whose children are this index + 1 and `right`. Boxes are padded.
struct BuildNode {
    glm::dvec3 lo{0.0};
    glm::dvec3 hi{0.0};
    std::uint32_t right = 0;
    std::uint32_t first = 0;
    std::uint32_t count = 0;
};

float round_down(double x) {
    float f = static_cast<float>(x);
    if (static_cast<double>(f) > x) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
    return f;
}
float round_up(double x) {
    float f = static_cast<float>(x);
    if (static_cast<double>(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
    return f;
}

// The build's progress in triangle visits: each node visits its triangles once (its box, then
// nth_element), so the whole visits about n (1 + log2(n / kLeafSize)). Told every kVisitsPerReport
// visits, a few milliseconds, so that a stop is heard at once on a million triangles too.
class BuildProgress {
public:
    static constexpr std::uint64_t kVisitsPerReport = 65536;
    // The recursion's share of the build; the compaction and the triangles' corners in the tree's
    // order take the rest, a report before each.
    static constexpr double kTreeShare = 0.9;

    BuildProgress(const ProgressFunction& progress, std::uint32_t triangles) : progress_(progress) {
        const double n = std::max(1.0, static_cast<double>(triangles));
        total_ = n * (1.0 + std::max(0.0, std::ceil(std::log2(n / kLeafSize))));
    }

    void visited(std::uint32_t triangles) {
        visits_ += triangles;
        if (visits_ < next_) return;
        next_ = visits_ + kVisitsPerReport;
        report_share(progress_, kTreeShare * std::min(1.0, static_cast<double>(visits_) / total_));
    }

private:
    const ProgressFunction& progress_;
    double total_ = 1.0;
    std::uint64_t visits_ = 0, next_ = kVisitsPerReport;
};

void set_child_box(Node& node, int c, const BuildNode& child) {
    for (int a = 0; a < 3; ++a) {
        node.lo[c][a] = round_down(child.lo[a]);
        node.hi[c][a] = round_up(child.hi[a]);
    }
}

class TreeBuilder {
public:
    TreeBuilder(std::span<const glm::dvec3> positions, std::span<const rgb::Triangle> triangles, double box_pad,
                const ProgressFunction& progress)
        : positions_(positions), triangles_(triangles), box_pad_(box_pad), report_(progress),
          progress_(progress, static_cast<std::uint32_t>(triangles.size())) {}

    SurfaceTree build() {
        const auto n = static_cast<std::uint32_t>(triangles_.size());
        centroids_.resize(n);
        for (std::uint32_t f = 0; f < n; ++f) {
            const rgb::Triangle& t = triangles_[f];
            centroids_[f] = (positions_[t[0]] + positions_[t[1]] + positions_[t[2]]) / 3.0;
        }
        order_.resize(n);
        std::iota(order_.begin(), order_.end(), 0u);
        built_.reserve(2 * (n / kLeafSize + 1));
        split(0, n);
        SurfaceTree tree;
        tree.nodes.reserve(built_.size() / 2 + 1);
        if (built_[0].count > 0) {
            // One leaf: a root whose only child it is.
            Node root{};
            set_child_box(root, 0, built_[0]);
            root.index[0] = built_[0].first;
            root.kind[0] = kLeafChild;
            root.count[0] = static_cast<std::uint8_t>(built_[0].count);
            tree.nodes.push_back(root);
        } else {
            report_share(report_, BuildProgress::kTreeShare);
            compact(tree.nodes, 0);
        }
        report_share(report_, 0.95);
        tree.corners.resize(n);
        for (std::uint32_t s = 0; s < n; ++s) {
            const rgb::Triangle& t = triangles_[order_[s]];
            tree.corners[s] = {positions_[t[0]], positions_[t[1]], positions_[t[2]]};
        }
        tree.original = std::move(order_);
        return tree;
    }

private:
    // The node of triangles order_[begin, end), its subtree built after it; returns its index.
    std::uint32_t split(std::uint32_t begin, std::uint32_t end) {
        progress_.visited(end - begin);
        const auto index = static_cast<std::uint32_t>(built_.size());
        built_.emplace_back();
        glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
        glm::dvec3 clo = lo, chi = hi;
        for (std::uint32_t i = begin; i < end; ++i) {
            for (std::uint32_t v : triangles_[order_[i]]) {
                lo = glm::min(lo, positions_[v]);
                hi = glm::max(hi, positions_[v]);
            }
            clo = glm::min(clo, centroids_[order_[i]]);
            chi = glm::max(chi, centroids_[order_[i]]);
        }
        built_[index].lo = lo - glm::dvec3(box_pad_);
        built_[index].hi = hi + glm::dvec3(box_pad_);
        if (end - begin <= kLeafSize) {
            built_[index].first = begin;
            built_[index].count = end - begin;
            return index;
        }
        const glm::dvec3 extent = chi - clo;
        int axis = 0;
        if (extent.y > extent[axis]) axis = 1;
        if (extent.z > extent[axis]) axis = 2;
        const std::uint32_t mid = begin + (end - begin) / 2;
        std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                         [&](std::uint32_t a, std::uint32_t b) {
                             const double ca = centroids_[a][axis], cb = centroids_[b][axis];
                             return ca != cb ? ca < cb : a < b;
                         });
        split(begin, mid);
        const std::uint32_t right = split(mid, end);
        built_[index].right = right;
        return index;
    }

    // The searched node of built_[i] (an inner node) and its subtree, appended to nodes.
    std::uint32_t compact(std::vector<Node>& nodes, std::uint32_t i) const {
        const auto index = static_cast<std::uint32_t>(nodes.size());
        nodes.emplace_back();
        const std::uint32_t children[2] = {i + 1, built_[i].right};
        for (int c = 0; c < 2; ++c) {
            const BuildNode& child = built_[children[c]];
            set_child_box(nodes[index], c, child);
            if (child.count > 0) {
                nodes[index].index[c] = child.first;
                nodes[index].kind[c] = kLeafChild;
                nodes[index].count[c] = static_cast<std::uint8_t>(child.count);
            } else {
                nodes[index].kind[c] = kInnerChild;
                const std::uint32_t inner = compact(nodes, children[c]);
                nodes[index].index[c] = inner;
            }
        }
        return index;
    }

    std::span<const glm::dvec3> positions_;
    std::span<const rgb::Triangle> triangles_;
    double box_pad_;
    const ProgressFunction& report_;
    BuildProgress progress_;
    std::vector<glm::dvec3> centroids_;
    std::vector<std::uint32_t> order_;
    std::vector<BuildNode> built_;
};

}  // namespace

SurfaceTree build_surface_tree(std::span<const glm::dvec3> positions, std::span<const rgb::Triangle> triangles,
                               double box_pad, const ProgressFunction& progress) {
    return TreeBuilder(positions, triangles, box_pad, progress).build();
}

}  // namespace rgbdetail::dense_surface_internal
