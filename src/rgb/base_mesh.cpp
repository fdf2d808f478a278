#include "rgb/base_mesh.h"

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "rgb/base_face_index.h"

namespace rgb {

namespace {

[[noreturn]] void reject(const std::string& what) { throw std::invalid_argument(what); }

std::string edge_name(std::uint32_t a, std::uint32_t b) { return std::to_string(a) + "-" + std::to_string(b); }

struct Directed {
    std::uint64_t key;  // from << 32 | to
    std::uint32_t halfedge;
    bool operator<(const Directed& o) const { return key < o.key; }
};

std::atomic<std::uint64_t> next_serial{1};

}  // namespace

BaseMesh::BaseMesh(std::span<const glm::dvec3> positions, std::span<const Triangle> triangles)
    : serial_(next_serial++), positions_(positions.begin(), positions.end()), faces_(triangles.begin(), triangles.end()) {
    const auto nv = static_cast<std::uint32_t>(positions_.size());
    if (positions_.size() >= kNone || 3 * faces_.size() >= kNone) reject("the mesh is too large");
    std::vector<Directed> directed;
    directed.reserve(3 * faces_.size());
    for (std::uint32_t f = 0; f < faces_.size(); ++f) {
        const Triangle& t = faces_[f];
        for (int i = 0; i < 3; ++i)
            if (t[i] >= nv) reject("triangle " + std::to_string(f) + " uses missing vertex " + std::to_string(t[i]));
        if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) reject("triangle " + std::to_string(f) + " repeats a vertex");
        for (std::uint32_t i = 0; i < 3; ++i)
            directed.push_back({(std::uint64_t(t[i]) << 32) | t[(i + 1) % 3], 3 * f + i});
    }
    std::sort(directed.begin(), directed.end());
    for (std::size_t i = 1; i < directed.size(); ++i)
        if (directed[i].key == directed[i - 1].key)
            reject("edge " + edge_name(std::uint32_t(directed[i].key >> 32), std::uint32_t(directed[i].key)) +
                   " is used twice in the same direction (non-manifold or inconsistent orientation)");
    opposite_.assign(directed.size(), kNone);
    for (const Directed& d : directed) {
        const std::uint64_t reverse = (d.key << 32) | (d.key >> 32);
        const auto it = std::lower_bound(directed.begin(), directed.end(), Directed{reverse, 0});
        if (it != directed.end() && it->key == reverse) opposite_[d.halfedge] = it->halfedge;
    }
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
           (opposite_.size() + vertex_halfedge_.size() + valence_.size()) * sizeof(std::uint32_t) + boundary_.size();
}

}  // namespace rgb
