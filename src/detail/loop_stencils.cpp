#include "detail/loop_stencils.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include <Eigen/Dense>

#include "rgb/rules/dart_masks.h"
#include "rgb/rules/loop_rules.h"

namespace rgbdetail {

namespace {
namespace stencils_internal {

std::uint64_t directed_key(std::uint32_t a, std::uint32_t b) { return (std::uint64_t{a} << 32) | b; }

[[noreturn]] void refuse(const std::string& why) { throw std::invalid_argument("Loop stencils: " + why); }

int checked_sharpness(int sharpness, const std::string& what) {
    if (sharpness < 0) refuse(what + " has negative sharpness " + std::to_string(sharpness));
    return std::min(sharpness, rgb::kInfiniteSharpness);
}

// Uniform creasing (loop-creases.md §2): one level finer, a finite sharpness loses one.
int sharpness_one_level_finer(int sharpness) {
    return sharpness >= rgb::kInfiniteSharpness ? sharpness : std::max(sharpness - 1, 0);
}

rgb::VertexRule rule_for(bool corner, int sharp_edges) {
    if (corner || sharp_edges >= 3) return rgb::VertexRule::Corner;
    if (sharp_edges == 2) return rgb::VertexRule::Crease;
    return sharp_edges == 1 ? rgb::VertexRule::Dart : rgb::VertexRule::Smooth;
}

// What decides a vertex's masks at one level: its corner sharpness and the sharpness of the edge to
// each ring vertex, in ring order. The masks below are weights over (the vertex, ring[0], ring[1], ...).
struct VertexTags {
    int corner = 0;
    std::vector<int> ring;
};

VertexTags vertex_tags(const LoopTopology& topology, std::uint32_t v) {
    VertexTags tags;
    tags.corner = topology.corner_sharpness(v);
    for (std::uint32_t e : topology.ring_edges(v)) tags.ring.push_back(topology.edge_sharpness(e));
    return tags;
}

rgb::VertexRule rule_of(const VertexTags& tags) {
    return rule_for(tags.corner > 0, static_cast<int>(std::count_if(tags.ring.begin(), tags.ring.end(), [](int s) { return s > 0; })));
}

// Whether a semi-sharp tag still reaches the vertex, so that its rule may change at a finer level.
bool has_finite_sharpness(const VertexTags& tags) {
    auto finite = [](int s) { return s > 0 && s < rgb::kInfiniteSharpness; };
    return finite(tags.corner) || std::any_of(tags.ring.begin(), tags.ring.end(), finite);
}

VertexTags one_level_finer(VertexTags tags) {
    tags.corner = sharpness_one_level_finer(tags.corner);
    for (int& s : tags.ring) s = sharpness_one_level_finer(s);
    return tags;
}

// The weight `per_sharp_neighbour` on each end of the vertex's sharp edges.
void add_to_sharp_neighbours(const VertexTags& tags, double per_sharp_neighbour, std::vector<double>& mask) {
    for (std::size_t i = 0; i < tags.ring.size(); ++i)
        if (tags.ring[i] > 0) mask[1 + i] += per_sharp_neighbour;
}

// The even vertex of the next level (§3).
std::vector<double> vertex_point_mask(const VertexTags& tags) {
    const std::size_t n = tags.ring.size();
    std::vector<double> mask(n + 1, 0.0);
    switch (rule_of(tags)) {
        case rgb::VertexRule::Smooth:
        case rgb::VertexRule::Dart: {
            const int valence = static_cast<int>(n);
            const double alpha = rgb::loop_alpha(valence);
            mask[0] = 1.0 - alpha;
            for (std::size_t i = 0; i < n; ++i) mask[1 + i] = alpha / valence;
            break;
        }
        case rgb::VertexRule::Crease:
            mask[0] = 0.75;
            add_to_sharp_neighbours(tags, 0.125, mask);
            break;
        case rgb::VertexRule::Corner: mask[0] = 1.0; break;
    }
    return mask;
}

// The limit, for a vertex whose rule no longer changes (§4, §6).
std::vector<double> limit_mask(const VertexTags& tags) {
    const std::size_t n = tags.ring.size();
    std::vector<double> mask(n + 1, 0.0);
    switch (rule_of(tags)) {
        case rgb::VertexRule::Smooth: {
            const int valence = static_cast<int>(n);
            const double c = rgb::loop_limit_ring_weight(valence);
            mask[0] = 1.0 - c;
            for (std::size_t i = 0; i < n; ++i) mask[1 + i] = c / valence;
            break;
        }
        case rgb::VertexRule::Dart: {
            // dart_masks.h orders the ring from the sharp edge on.
            const auto sharp_edge = std::find_if(tags.ring.begin(), tags.ring.end(), [](int s) { return s > 0; });
            const auto sharp = static_cast<std::size_t>(sharp_edge - tags.ring.begin());
            const std::vector<double> dart = rgb::dart_limit_mask(static_cast<int>(n));
            mask[0] = dart[0];
            for (std::size_t i = 0; i < n; ++i) mask[1 + (sharp + i) % n] = dart[1 + i];
            break;
        }
        case rgb::VertexRule::Crease:
            mask[0] = 2.0 / 3.0;
            add_to_sharp_neighbours(tags, 1.0 / 6.0, mask);
            break;
        case rgb::VertexRule::Corner: mask[0] = 1.0; break;
    }
    return mask;
}

// The odd vertex on an edge of this sharpness (§3): weights of its two ends and of the two vertices
// opposite it.
struct EdgePointMask {
    double end = 0.0, opposite = 0.0;
};
EdgePointMask edge_point_mask(int sharpness) { return sharpness > 0 ? EdgePointMask{0.5, 0.0} : EdgePointMask{0.375, 0.125}; }

// One level of the vertex's one-ring (§5.1): the vertex by its rule, each ring vertex the edge point
// of its edge. The edge to ring[i] has ring[i - 1] and ring[i + 1] opposite it; a boundary vertex's
// first and last edges are sharp, so its ring never wraps around.
Eigen::MatrixXd one_ring_step(const VertexTags& tags) {
    const auto n = static_cast<Eigen::Index>(tags.ring.size());
    Eigen::MatrixXd step = Eigen::MatrixXd::Zero(n + 1, n + 1);
    const std::vector<double> centre = vertex_point_mask(tags);
    for (Eigen::Index j = 0; j <= n; ++j) step(0, j) = centre[static_cast<std::size_t>(j)];
    for (Eigen::Index i = 0; i < n; ++i) {
        const EdgePointMask m = edge_point_mask(tags.ring[static_cast<std::size_t>(i)]);
        step(1 + i, 0) += m.end;
        step(1 + i, 1 + i) += m.end;
        step(1 + i, 1 + (i + n - 1) % n) += m.opposite;
        step(1 + i, 1 + (i + 1) % n) += m.opposite;
    }
    return step;
}

// v's exact limit over v and its ring at this level: while a semi-sharp tag reaches it, its one-ring
// steps one level with the rules of that level; then the limit mask of the rule it keeps for ever.
std::vector<double> limit_weights(const LoopTopology& topology, std::uint32_t v) {
    VertexTags tags = vertex_tags(topology, v);
    if (!has_finite_sharpness(tags)) return limit_mask(tags);  // nearly every vertex: no product
    const auto n = static_cast<Eigen::Index>(tags.ring.size());
    Eigen::MatrixXd carried = Eigen::MatrixXd::Identity(n + 1, n + 1);
    for (; has_finite_sharpness(tags); tags = one_level_finer(tags)) carried = one_ring_step(tags) * carried;
    const std::vector<double> mask = limit_mask(tags);
    const Eigen::RowVectorXd weights = Eigen::Map<const Eigen::RowVectorXd>(mask.data(), n + 1) * carried;
    return {weights.data(), weights.data() + n + 1};
}

// A row of weights over v and its ring, without its zeros.
void add_ring_row(Eigen::Index row, std::uint32_t v, std::span<const std::uint32_t> ring, const std::vector<double>& weights,
                  std::vector<Eigen::Triplet<double>>& entries) {
    if (weights[0] != 0.0) entries.emplace_back(row, v, weights[0]);
    for (std::size_t i = 0; i < ring.size(); ++i)
        if (weights[1 + i] != 0.0) entries.emplace_back(row, ring[i], weights[1 + i]);
}

}  // namespace stencils_internal
}  // namespace

LoopTopology::LoopTopology(std::size_t vertex_count, std::span<const rgb::Triangle> triangles, const rgb::SharpFeatures& features)
    : triangles_(triangles.begin(), triangles.end()), boundary_interpolation_(features.boundary) {
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
    ring_edges_.resize(vertex_count);
    for (std::uint32_t v = 0; v < vertex_count; ++v) {
        if (start[v] == kNone) stencils_internal::refuse("vertex " + std::to_string(v) + " is in no face");
        std::vector<std::uint32_t>& ring = rings_[v];
        std::uint32_t h = start[v];
        std::uint32_t faces = 0;
        while (true) {
            ring.push_back(to(h));
            ring_edges_[v].push_back(edge_of[h]);
            ++faces;
            const std::uint32_t back = prev(h);  // w -> v in the same face
            const std::uint32_t next = opposite[back];
            if (next == kNone) {
                ring.push_back(from(back));
                ring_edges_[v].push_back(edge_of[back]);
                break;
            }
            if (next == start[v]) break;
            h = next;
            if (faces > incident[v]) break;
        }
        if (faces != incident[v]) stencils_internal::refuse("vertex " + std::to_string(v) + " has more than one fan of faces");
    }

    // The tags, as BaseMesh reads them (header comment).
    edge_sharpness_.assign(edges_.size(), 0);
    for (const rgb::EdgeSharpness& tag : features.edges) {
        const std::string name = "crease " + std::to_string(tag.a) + "-" + std::to_string(tag.b);
        if (tag.a >= vertex_count || tag.b >= vertex_count) stencils_internal::refuse(name + " uses a missing vertex");
        auto it = directed.find(stencils_internal::directed_key(tag.a, tag.b));
        if (it == directed.end()) it = directed.find(stencils_internal::directed_key(tag.b, tag.a));
        if (it == directed.end()) stencils_internal::refuse(name + " is not an edge of the mesh");
        edge_sharpness_[edge_of[it->second]] = static_cast<std::uint8_t>(stencils_internal::checked_sharpness(tag.sharpness, name));
    }
    for (std::size_t e = 0; e < edges_.size(); ++e)
        if (edges_[e].d == kNone) edge_sharpness_[e] = rgb::kInfiniteSharpness;
    corner_sharpness_.assign(vertex_count, 0);
    for (const rgb::VertexSharpness& tag : features.corners) {
        const std::string name = "corner " + std::to_string(tag.vertex);
        if (tag.vertex >= vertex_count) stencils_internal::refuse(name + " is a missing vertex");
        corner_sharpness_[tag.vertex] = static_cast<std::uint8_t>(stencils_internal::checked_sharpness(tag.sharpness, name));
    }
    if (boundary_interpolation_ == rgb::BoundaryInterpolation::EdgeAndCorner)
        for (std::uint32_t v = 0; v < vertex_count; ++v)
            if (boundary_[v] && rings_[v].size() == 2) corner_sharpness_[v] = rgb::kInfiniteSharpness;
}

rgb::VertexRule LoopTopology::rule(std::uint32_t v) const {
    const auto sharp =
        std::count_if(ring_edges_[v].begin(), ring_edges_[v].end(), [this](std::uint32_t e) { return edge_sharpness_[e] > 0; });
    return stencils_internal::rule_for(corner_sharpness_[v] > 0, static_cast<int>(sharp));
}

std::vector<std::uint32_t> LoopTopology::sharp_neighbours(std::uint32_t v) const {
    std::vector<std::uint32_t> out;
    for (std::size_t i = 0; i < rings_[v].size(); ++i)
        if (edge_sharpness_[ring_edges_[v][i]] > 0) out.push_back(rings_[v][i]);
    return out;
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

rgb::SharpFeatures LoopTopology::refined_features() const {
    const auto n = static_cast<std::uint32_t>(num_vertices());
    rgb::SharpFeatures out;
    out.boundary = boundary_interpolation_;
    for (std::uint32_t e = 0; e < edges_.size(); ++e) {
        const int child = stencils_internal::sharpness_one_level_finer(edge_sharpness_[e]);
        if (child == 0 || edges_[e].d == kNone) continue;  // boundary edges are sharp without a tag
        out.edges.push_back({edges_[e].a, n + e, child});
        out.edges.push_back({n + e, edges_[e].b, child});
    }
    for (std::uint32_t v = 0; v < n; ++v)
        if (const int child = stencils_internal::sharpness_one_level_finer(corner_sharpness_[v]); child > 0) out.corners.push_back({v, child});
    return out;
}

StencilMatrix subdivision_matrix(const LoopTopology& topology) {
    const std::size_t n = topology.num_vertices();
    const std::size_t rows = n + topology.edges().size();
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(8 * n + 4 * topology.edges().size());
    for (std::uint32_t v = 0; v < n; ++v)
        stencils_internal::add_ring_row(static_cast<Eigen::Index>(v), v, topology.ring(v),
                                        stencils_internal::vertex_point_mask(stencils_internal::vertex_tags(topology, v)), entries);
    for (std::size_t e = 0; e < topology.edges().size(); ++e) {
        const LoopTopology::Edge& edge = topology.edges()[e];
        const auto row = static_cast<Eigen::Index>(n + e);
        const stencils_internal::EdgePointMask m = stencils_internal::edge_point_mask(topology.edge_sharpness(static_cast<std::uint32_t>(e)));
        entries.emplace_back(row, edge.a, m.end);
        entries.emplace_back(row, edge.b, m.end);
        if (m.opposite != 0.0) {  // a smooth edge, so an interior one
            entries.emplace_back(row, edge.c, m.opposite);
            entries.emplace_back(row, edge.d, m.opposite);
        }
    }
    StencilMatrix s(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(n));
    s.setFromTriplets(entries.begin(), entries.end());
    return s;
}

StencilMatrix limit_matrix(const LoopTopology& topology) {
    const std::size_t n = topology.num_vertices();
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(8 * n);
    for (std::uint32_t v = 0; v < n; ++v)
        stencils_internal::add_ring_row(static_cast<Eigen::Index>(v), v, topology.ring(v), stencils_internal::limit_weights(topology, v), entries);
    StencilMatrix l(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
    l.setFromTriplets(entries.begin(), entries.end());
    return l;
}

LoopStencils limit_stencils(std::size_t cage_vertex_count, std::span<const rgb::Triangle> cage_triangles,
                            const rgb::SharpFeatures& cage_features, int level) {
    if (level < 0 || level > 6) stencils_internal::refuse("level " + std::to_string(level) + " is not in 0-6");
    LoopTopology topology(cage_vertex_count, cage_triangles, cage_features);
    StencilMatrix product(static_cast<Eigen::Index>(cage_vertex_count), static_cast<Eigen::Index>(cage_vertex_count));
    product.setIdentity();
    for (int k = 0; k < level; ++k) {
        const StencilMatrix step = subdivision_matrix(topology);
        product = (step * product).pruned();
        topology = LoopTopology(topology.num_vertices() + topology.edges().size(), topology.refined_triangles(), topology.refined_features());
    }
    LoopStencils out;
    out.level = level;
    out.limit = (limit_matrix(topology) * product).pruned();
    out.triangles.assign(topology.triangles().begin(), topology.triangles().end());
    return out;
}

}  // namespace rgbdetail
