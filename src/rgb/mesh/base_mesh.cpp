#include "rgb/mesh/base_mesh.h"

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "rgb/mesh/base_face_index.h"
#include "rgb/mesh/detail_positions.h"
#include "rgb/mesh/outgoing_halfedges.h"

namespace rgb {

namespace {

[[noreturn]] void reject(const std::string& what) { throw std::invalid_argument(what); }

std::string edge_name(std::uint32_t a, std::uint32_t b) { return std::to_string(a) + "-" + std::to_string(b); }

std::atomic<std::uint64_t> next_serial{1};

}  // namespace

BaseMesh::BaseMesh(std::span<const glm::dvec3> positions, std::span<const Triangle> triangles,
                   const SharpFeatures& features, std::shared_ptr<const DetailPositions> detail)
    : serial_(next_serial++), positions_(positions.begin(), positions.end()), faces_(triangles.begin(), triangles.end()),
      detail_(std::move(detail)) {
    if (detail_ && detail_->num_faces() != faces_.size()) reject("the detail was sampled over another base mesh");
    const auto nv = static_cast<std::uint32_t>(positions_.size());
    if (positions_.size() >= kNone || 3 * faces_.size() >= kNone) reject("the mesh is too large");
    for (std::uint32_t f = 0; f < faces_.size(); ++f) {
        const Triangle& t = faces_[f];
        for (int i = 0; i < 3; ++i)
            if (t[i] >= nv) reject("triangle " + std::to_string(f) + " uses missing vertex " + std::to_string(t[i]));
        if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) reject("triangle " + std::to_string(f) + " repeats a vertex");
    }
    // Grouped by start vertex, as a restored mesh state's are (a binary search over all halfedges
    // missed the cache at every step: a fifth of loading 819k triangles).
    const OutgoingHalfedges out = outgoing_halfedges(faces_, nv);
    if (out.repeating)
        reject("edge " + edge_name(out.repeating->from, out.repeating->to) +
               " is used twice in the same direction (non-manifold or inconsistent orientation)");
    opposite_.assign(3 * faces_.size(), kNone);
    pair_halfedges(out, nv, [this](std::uint32_t h, std::uint32_t reverse) { opposite_[h] = reverse; });
    // Two faces over the same three vertices (a "pillow") pair every edge with each other and close
    // up a two-triangle sphere that no split can handle.
    for (std::uint32_t f = 0; f < faces_.size(); ++f) {
        const std::uint32_t o = opposite_[3 * f];
        if (o == kNone) continue;
        const std::uint32_t g = o / 3;
        if (g != f && opposite_[3 * f + 1] != kNone && opposite_[3 * f + 1] / 3 == g && opposite_[3 * f + 2] != kNone &&
            opposite_[3 * f + 2] / 3 == g)
            reject("triangles " + std::to_string(f) + " and " + std::to_string(g) + " use the same three vertices");
    }

    vertex_halfedge_.assign(nv, kNone);
    std::vector<std::uint32_t> incident(nv, 0);
    for (std::uint32_t h = 0; h < opposite_.size(); ++h) {
        const std::uint32_t v = faces_[h / 3][h % 3];
        ++incident[v];
        // Keep the boundary halfedge if there is one: ccw turns from it see the whole star.
        if (vertex_halfedge_[v] == kNone || opposite_[h] == kNone) vertex_halfedge_[v] = h;
    }
    valence_.assign(nv, 0);
    boundary_.assign(nv, 0);
    for (std::uint32_t v = 0; v < nv; ++v) {
        if (vertex_halfedge_[v] == kNone) reject("vertex " + std::to_string(v) + " is used by no triangle");
        // Every incident face must be reachable by turning around v, or its faces form several fans.
        std::uint32_t fan = 0;
        std::uint32_t h = vertex_halfedge_[v];
        do {
            ++fan;
            h = ccw_rotated(h);
        } while (h != kNone && h != vertex_halfedge_[v] && fan <= incident[v]);
        if (fan != incident[v]) reject("vertex " + std::to_string(v) + " is non-manifold (bow-tie)");
        boundary_[v] = opposite_[vertex_halfedge_[v]] == kNone ? 1 : 0;
        valence_[v] = incident[v] + boundary_[v];
    }
    for (std::uint32_t h = 0; h < opposite_.size(); ++h)
        longest_edge_ = std::max(longest_edge_, glm::distance(positions_[faces_[h / 3][h % 3]], positions_[to_vertex(h)]));
    set_sharp_features(features);
}

std::uint32_t BaseMesh::find_edge(std::uint32_t a, std::uint32_t b) const {
    for (const auto& [from, to] : {std::pair{a, b}, std::pair{b, a}}) {
        std::uint32_t h = vertex_halfedge_[from];
        do {
            if (to_vertex(h) == to) return h;
            h = ccw_rotated(h);
        } while (h != kNone && h != vertex_halfedge_[from]);
    }
    return kNone;
}

void BaseMesh::set_sharp_features(const SharpFeatures& features) {
    const auto nv = static_cast<std::uint32_t>(positions_.size());
    auto checked_sharpness = [](int s, const std::string& what) {
        if (s < 0) reject(what + " has negative sharpness " + std::to_string(s));
        return std::min(s, kInfiniteSharpness);
    };
    // Later tags replace earlier ones: (key, sharpness) in input order, stably sorted by key.
    std::vector<std::pair<std::uint64_t, int>> edges;
    for (const EdgeSharpness& e : features.edges) {
        const std::string name = "crease " + edge_name(e.a, e.b);
        if (e.a >= nv || e.b >= nv) reject(name + " uses a missing vertex");
        if (find_edge(e.a, e.b) == kNone) reject(name + " is not an edge of the mesh");
        edges.push_back({(std::uint64_t(std::min(e.a, e.b)) << 32) | std::max(e.a, e.b), checked_sharpness(e.sharpness, name)});
    }
    std::vector<std::pair<std::uint64_t, int>> corners;
    for (const VertexSharpness& c : features.corners) {
        const std::string name = "corner " + std::to_string(c.vertex);
        if (c.vertex >= nv) reject(name + " is a missing vertex");
        corners.push_back({c.vertex, checked_sharpness(c.sharpness, name)});
    }
    auto last_of_each = [](std::vector<std::pair<std::uint64_t, int>>& tags) {
        std::stable_sort(tags.begin(), tags.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
        std::vector<std::pair<std::uint64_t, int>> kept;
        for (std::size_t i = 0; i < tags.size(); ++i)
            if ((i + 1 == tags.size() || tags[i + 1].first != tags[i].first) && tags[i].second > 0) kept.push_back(tags[i]);
        tags = std::move(kept);
    };
    last_of_each(edges);
    last_of_each(corners);
    features_.boundary = features.boundary;
    for (const auto& [key, s] : edges) features_.edges.push_back({std::uint32_t(key >> 32), std::uint32_t(key), s});
    for (const auto& [key, s] : corners) features_.corners.push_back({std::uint32_t(key), s});

    std::vector<std::uint8_t> edge_sharpness(opposite_.size(), 0), corner_sharpness(nv, 0), sharp_rules(nv, 0);
    bool any = false;
    for (std::uint32_t h = 0; h < opposite_.size(); ++h)
        if (opposite_[h] == kNone) edge_sharpness[h] = kInfiniteSharpness;
    for (const EdgeSharpness& e : features_.edges) {
        const std::uint32_t h = find_edge(e.a, e.b);
        if (opposite_[h] == kNone) continue;  // boundary edges are infinitely sharp anyway
        edge_sharpness[h] = edge_sharpness[opposite_[h]] = static_cast<std::uint8_t>(e.sharpness);
        sharp_rules[e.a] = sharp_rules[e.b] = 1;
        any = true;
    }
    for (const VertexSharpness& c : features_.corners) corner_sharpness[c.vertex] = static_cast<std::uint8_t>(c.sharpness);
    if (features_.boundary == BoundaryInterpolation::EdgeAndCorner)
        for (std::uint32_t v = 0; v < nv; ++v)
            if (boundary_[v] && valence_[v] == 2) corner_sharpness[v] = kInfiniteSharpness;
    for (std::uint32_t v = 0; v < nv; ++v)
        if (corner_sharpness[v] > 0) sharp_rules[v] = 1, any = true;
    if (!any) return;  // untagged Loop everywhere: keep the fast answers of the accessors
    edge_sharpness_ = std::move(edge_sharpness);
    corner_sharpness_ = std::move(corner_sharpness);
    sharp_rules_.assign(nv, 0);
    for (std::uint32_t v = 0; v < nv; ++v) {
        if (!sharp_rules[v]) continue;
        sharp_regimes_.push_back(base_vertex_regimes(*this, v));
        sharp_rules_[v] = static_cast<std::uint32_t>(sharp_regimes_.size());
    }
}

BaseMesh::~BaseMesh() = default;

const BaseFaceIndex& BaseMesh::face_index() const {
    std::call_once(index_built_, [this] { index_ = std::make_unique<BaseFaceIndex>(*this); });
    return *index_;
}

std::vector<std::uint32_t> BaseMesh::ring(std::uint32_t v) const {
    std::vector<std::uint32_t> result;
    result.reserve(valence_[v]);
    std::uint32_t h = vertex_halfedge_[v];
    std::uint32_t last = h;
    do {
        result.push_back(to_vertex(h));
        last = h;
        h = ccw_rotated(h);
    } while (h != kNone && h != vertex_halfedge_[v]);
    // The far end of the last face's incoming boundary edge closes a boundary vertex's ring.
    if (h == kNone) result.push_back(faces_[last / 3][(last % 3 + 2) % 3]);
    return result;
}

std::size_t BaseMesh::memory_bytes() const {
    return positions_.size() * sizeof(glm::dvec3) + faces_.size() * sizeof(Triangle) +
           (opposite_.size() + vertex_halfedge_.size() + valence_.size()) * sizeof(std::uint32_t) + boundary_.size() +
           edge_sharpness_.size() + corner_sharpness_.size() + sharp_rules_.size() * sizeof(std::uint32_t) +
           sharp_regimes_.size() * sizeof(Regimes) +
           features_.edges.size() * sizeof(EdgeSharpness) + features_.corners.size() * sizeof(VertexSharpness) +
           (detail_ ? detail_->memory_bytes() : 0);
}

}  // namespace rgb
