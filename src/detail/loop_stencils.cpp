#include "detail/loop_stencils.h"

#include <stdexcept>
#include <string>
#include <unordered_map>

#include "rgb/rules/loop_rules.h"

namespace rgbdetail {

namespace {
namespace stencils_internal {

std::uint64_t directed_key(std::uint32_t a, std::uint32_t b) { return (std::uint64_t{a} << 32) | b; }

[[noreturn]] void refuse(const std::string& why) { throw std::invalid_argument("Loop stencils: " + why); }

}  // namespace stencils_internal
}  // namespace

LoopTopology::LoopTopology(std::size_t vertex_count, std::span<const rgb::Triangle> triangles)
    : triangles_(triangles.begin(), triangles.end()) {
    const std::size_t halfedges = 3 * triangles_.size();
    if (vertex_count >= kNone || halfedges >= kNone) stencils_internal::refuse("mesh too large");
    auto from = [&](std::uint32_t h) { return triangles_[h / 3][h % 3]; };
    auto to = [&](std::uint32_t h) { return triangles_[h / 3][(h % 3 + 1) % 3]; };
    auto prev = [](std::uint32_t h) { return h - h % 3 + (h % 3 + 2) % 3; };

    std::unordered_map<std::uint64_t, std::uint32_t> directed;
    directed.reserve(halfedges);
    std::vector<std::uint32_t> incident(vertex_count, 0);
    for (std::size_t f = 0; f < triangles_.size(); ++f) {
        const rgb::Triangle& t = triangles_[f];
        for (int i = 0; i < 3; ++i)
            if (t[i] >= vertex_count) stencils_internal::refuse("face " + std::to_string(f) + " has a vertex index out of range");
        if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) stencils_internal::refuse("face " + std::to_string(f) + " repeats a corner");
        for (std::uint32_t i = 0; i < 3; ++i) {
            const auto h = static_cast<std::uint32_t>(3 * f + i);
            if (!directed.emplace(stencils_internal::directed_key(from(h), to(h)), h).second)
                stencils_internal::refuse("directed edge " + std::to_string(from(h)) + "->" + std::to_string(to(h)) + " is used twice");
            ++incident[t[i]];
        }
    }
    std::vector<std::uint32_t> opposite(halfedges, kNone);
    for (std::uint32_t h = 0; h < halfedges; ++h) {
        const auto it = directed.find(stencils_internal::directed_key(to(h), from(h)));
        if (it != directed.end()) opposite[h] = it->second;
    }

    // Edges in order of first appearance.
    face_edges_.resize(triangles_.size());
    std::vector<std::uint32_t> edge_of(halfedges, kNone);
    for (std::uint32_t h = 0; h < halfedges; ++h) {
        const std::uint32_t o = opposite[h];
        if (o != kNone && edge_of[o] != kNone) {
            edge_of[h] = edge_of[o];
        } else {
            Edge e;
            e.a = from(h);
            e.b = to(h);
            e.c = from(prev(h));
            if (o != kNone) e.d = from(prev(o));
            edge_of[h] = static_cast<std::uint32_t>(edges_.size());
            edges_.push_back(e);
        }
        face_edges_[h / 3][h % 3] = edge_of[h];
    }

    // One outgoing halfedge per vertex: the boundary one where there is one (more than one: two fans).
    std::vector<std::uint32_t> start(vertex_count, kNone);
    boundary_.assign(vertex_count, 0);
    for (std::uint32_t h = 0; h < halfedges; ++h) {
        const std::uint32_t v = from(h);
        if (opposite[h] == kNone) {
            if (boundary_[v]) stencils_internal::refuse("vertex " + std::to_string(v) + " has more than one fan of faces");
            boundary_[v] = 1;
            start[v] = h;
        } else if (start[v] == kNone) {
            start[v] = h;
        }
    }
    rings_.resize(vertex_count);
    for (std::uint32_t v = 0; v < vertex_count; ++v) {
        if (start[v] == kNone) stencils_internal::refuse("vertex " + std::to_string(v) + " is in no face");
        std::vector<std::uint32_t>& ring = rings_[v];
        std::uint32_t h = start[v];
        std::uint32_t faces = 0;
        while (true) {
            ring.push_back(to(h));
            ++faces;
            const std::uint32_t back = prev(h);  // w -> v in the same face
            const std::uint32_t next = opposite[back];
            if (next == kNone) {
                ring.push_back(from(back));
                break;
            }
            if (next == start[v]) break;
            h = next;
            if (faces > incident[v]) break;
        }
        if (faces != incident[v]) stencils_internal::refuse("vertex " + std::to_string(v) + " has more than one fan of faces");
    }
}

std::vector<rgb::Triangle> LoopTopology::refined_triangles() const {
    const auto n = static_cast<std::uint32_t>(num_vertices());
    std::vector<rgb::Triangle> out;
    out.reserve(4 * triangles_.size());
    for (std::size_t f = 0; f < triangles_.size(); ++f) {
        const rgb::Triangle& t = triangles_[f];
        const std::uint32_t ab = n + face_edges_[f][0], bc = n + face_edges_[f][1], ca = n + face_edges_[f][2];
        out.push_back({t[0], ab, ca});
        out.push_back({ab, t[1], bc});
        out.push_back({ca, bc, t[2]});
        out.push_back({ab, bc, ca});
    }
    return out;
}

StencilMatrix subdivision_matrix(const LoopTopology& topology) {
    const std::size_t n = topology.num_vertices();
    const std::size_t rows = n + topology.edges().size();
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(8 * n + 4 * topology.edges().size());
    for (std::uint32_t v = 0; v < n; ++v) {
        const auto ring = topology.ring(v);
        const auto row = static_cast<Eigen::Index>(v);
        if (topology.is_boundary(v)) {
            entries.emplace_back(row, v, 0.75);
            entries.emplace_back(row, ring.front(), 0.125);
            entries.emplace_back(row, ring.back(), 0.125);
        } else {
            const int valence = static_cast<int>(ring.size());
            const double alpha = rgb::loop_alpha(valence);
            entries.emplace_back(row, v, 1.0 - alpha);
            for (std::uint32_t w : ring) entries.emplace_back(row, w, alpha / valence);
        }
    }
    for (std::size_t e = 0; e < topology.edges().size(); ++e) {
        const LoopTopology::Edge& edge = topology.edges()[e];
        const auto row = static_cast<Eigen::Index>(n + e);
        if (edge.d == LoopTopology::kNone) {
            entries.emplace_back(row, edge.a, 0.5);
            entries.emplace_back(row, edge.b, 0.5);
        } else {
            entries.emplace_back(row, edge.a, 0.375);
            entries.emplace_back(row, edge.b, 0.375);
            entries.emplace_back(row, edge.c, 0.125);
            entries.emplace_back(row, edge.d, 0.125);
        }
    }
    StencilMatrix s(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(n));
    s.setFromTriplets(entries.begin(), entries.end());
    return s;
}

StencilMatrix ring_mask_matrix(const LoopTopology& topology, const std::function<RingMask(bool boundary, int valence)>& mask) {
    const std::size_t n = topology.num_vertices();
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(8 * n);
    for (std::uint32_t v = 0; v < n; ++v) {
        const auto ring = topology.ring(v);
        const auto row = static_cast<Eigen::Index>(v);
        const bool boundary = topology.is_boundary(v);
        const RingMask m = mask(boundary, static_cast<int>(ring.size()));
        entries.emplace_back(row, v, m.centre);
        if (boundary) {
            entries.emplace_back(row, ring.front(), m.neighbour);
            entries.emplace_back(row, ring.back(), m.neighbour);
        } else {
            for (std::uint32_t w : ring) entries.emplace_back(row, w, m.neighbour);
        }
    }
    StencilMatrix l(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
    l.setFromTriplets(entries.begin(), entries.end());
    return l;
}

StencilMatrix limit_matrix(const LoopTopology& topology) {
    return ring_mask_matrix(topology, [](bool boundary, int valence) {
        if (boundary) return RingMask{2.0 / 3.0, 1.0 / 6.0};
        const double c = rgb::loop_limit_ring_weight(valence);
        return RingMask{1.0 - c, c / valence};
    });
}

LoopStencils limit_stencils(std::size_t cage_vertex_count, std::span<const rgb::Triangle> cage_triangles, int level) {
    if (level < 0 || level > 6) stencils_internal::refuse("level " + std::to_string(level) + " is not in 0-6");
    LoopTopology topology(cage_vertex_count, cage_triangles);
    StencilMatrix product(static_cast<Eigen::Index>(cage_vertex_count), static_cast<Eigen::Index>(cage_vertex_count));
    product.setIdentity();
    for (int k = 0; k < level; ++k) {
        const StencilMatrix step = subdivision_matrix(topology);
        product = (step * product).pruned();
        topology = LoopTopology(topology.num_vertices() + topology.edges().size(), topology.refined_triangles());
    }
    LoopStencils out;
    out.level = level;
    out.limit = (limit_matrix(topology) * product).pruned();
    out.triangles.assign(topology.triangles().begin(), topology.triangles().end());
    return out;
}

}  // namespace rgbdetail
