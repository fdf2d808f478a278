#include "detail/dense_features.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <string>
#include <tuple>

#include <glm/geometric.hpp>

namespace rgbdetail {

FeatureGraph::FeatureGraph(std::size_t vertex_count, std::vector<std::array<std::uint32_t, 2>> edges)
    : edges_(std::move(edges)), offsets_(vertex_count + 1, 0) {
    for (const auto& [a, b] : edges_) {
        if (a >= b || b >= vertex_count) throw std::invalid_argument("feature edge out of range or not ordered");
        ++offsets_[a + 1];
        ++offsets_[b + 1];
    }
    std::partial_sum(offsets_.begin(), offsets_.end(), offsets_.begin());
    neighbours_.resize(offsets_.back());
    std::vector<std::uint32_t> next(offsets_.begin(), offsets_.end() - 1);
    for (const auto& [a, b] : edges_) {
        neighbours_[next[a]++] = b;
        neighbours_[next[b]++] = a;
    }
}

bool FeatureGraph::has_edge(std::uint32_t a, std::uint32_t b) const {
    const auto n = neighbours(a);
    return std::find(n.begin(), n.end(), b) != n.end();
}

namespace {

// As rgb::dihedral_angle_degrees (rgb/mesh/sharp_angle.cpp), on plain data: the angle between the two
// faces' normals, 0 where either has no area.
double dihedral_degrees(std::span<const glm::dvec3> positions, const rgb::Triangle& s, const rgb::Triangle& t) {
    auto normal = [&](const rgb::Triangle& f) {
        return glm::cross(positions[f[1]] - positions[f[0]], positions[f[2]] - positions[f[0]]);
    };
    const glm::dvec3 n = normal(s), m = normal(t);
    if (glm::dot(n, n) == 0.0 || glm::dot(m, m) == 0.0) return 0.0;
    return std::atan2(glm::length(glm::cross(n, m)), glm::dot(n, m)) * 180.0 / std::numbers::pi;
}

std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
}

}  // namespace

FeatureGraph find_sharp_features(std::span<const glm::dvec3> positions, std::span<const rgb::Triangle> triangles,
                                 double degrees, double shortest_feature) {
    // Each undirected edge with the faces that hold it, sorted so that an interior edge's two faces
    // are neighbours in the list.
    std::vector<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>> sides;
    sides.reserve(3 * triangles.size());
    for (std::uint32_t f = 0; f < triangles.size(); ++f)
        for (int i = 0; i < 3; ++i) {
            const std::uint32_t a = triangles[f][i], b = triangles[f][(i + 1) % 3];
            sides.emplace_back(std::min(a, b), std::max(a, b), f);
        }
    std::sort(sides.begin(), sides.end());
    std::vector<std::array<std::uint32_t, 2>> sharp;
    for (std::size_t i = 0; i + 1 < sides.size(); ++i) {
        const auto& [a, b, f] = sides[i];
        const auto& [c, d, g] = sides[i + 1];
        if (a != c || b != d) continue;
        if (dihedral_degrees(positions, triangles[f], triangles[g]) > degrees) sharp.push_back({a, b});
        ++i;
    }

    // Connected sets of feature edges, each with its length; the short ones go.
    std::vector<std::uint32_t> parent(positions.size());
    std::iota(parent.begin(), parent.end(), 0u);
    for (const auto& [a, b] : sharp) parent[find_root(parent, a)] = find_root(parent, b);
    std::vector<double> length(positions.size(), 0.0);
    for (const auto& [a, b] : sharp) length[find_root(parent, a)] += glm::distance(positions[a], positions[b]);
    std::erase_if(sharp, [&](const std::array<std::uint32_t, 2>& e) { return length[find_root(parent, e[0])] < shortest_feature; });
    return FeatureGraph(positions.size(), std::move(sharp));
}

std::vector<std::uint32_t> feature_anchors(const FeatureGraph& features) {
    const std::size_t vertex_count = features.num_vertices();
    std::vector<std::uint32_t> anchors;
    std::vector<std::uint8_t> on_open_chain(vertex_count, 0);
    for (std::uint32_t v = 0; v < vertex_count; ++v)
        if (features.valence(v) != 0 && features.valence(v) != 2) anchors.push_back(v);
    // Mark every vertex reachable from an anchor: what is left of valence 2 lies on closed chains.
    for (std::uint32_t anchor : anchors) {
        on_open_chain[anchor] = 1;
        for (std::uint32_t first : features.neighbours(anchor)) {
            std::uint32_t previous = anchor, current = first;
            while (!on_open_chain[current] && features.valence(current) == 2) {
                on_open_chain[current] = 1;
                const auto next = features.neighbours(current);
                const std::uint32_t step = next[0] == previous ? next[1] : next[0];
                previous = current;
                current = step;
            }
        }
    }
    for (std::uint32_t start = 0; start < vertex_count; ++start) {
        if (features.valence(start) != 2 || on_open_chain[start]) continue;
        std::vector<std::uint32_t> loop{start};
        on_open_chain[start] = 1;
        std::uint32_t previous = start, current = features.neighbours(start)[0];
        while (current != start) {
            loop.push_back(current);
            on_open_chain[current] = 1;
            const auto next = features.neighbours(current);
            const std::uint32_t step = next[0] == previous ? next[1] : next[0];
            previous = current;
            current = step;
        }
        for (std::size_t k = 0; k < 3; ++k) anchors.push_back(loop[k * loop.size() / 3]);
    }
    std::sort(anchors.begin(), anchors.end());
    return anchors;
}

std::vector<std::uint32_t> feature_chain(const FeatureGraph& features, std::uint32_t a, std::uint32_t b,
                                         std::span<const std::uint8_t> kept) {
    for (std::uint32_t first : features.neighbours(a)) {
        std::vector<std::uint32_t> chain{a};
        std::uint32_t previous = a, current = first;
        while (current != b && !kept[current] && features.valence(current) == 2) {
            chain.push_back(current);
            const auto next = features.neighbours(current);
            const std::uint32_t step = next[0] == previous ? next[1] : next[0];
            previous = current;
            current = step;
        }
        if (current == b) {
            chain.push_back(b);
            return chain;
        }
    }
    return {};
}

glm::dvec3 nearest_on_chain(std::span<const glm::dvec3> positions, std::span<const std::uint32_t> chain, const glm::dvec3& p) {
    if (chain.empty()) throw std::invalid_argument("nearest_on_chain: an empty chain");
    glm::dvec3 best = positions[chain[0]];
    double best_distance = glm::distance(p, best);
    for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
        const glm::dvec3 a = positions[chain[i]], b = positions[chain[i + 1]];
        const glm::dvec3 ab = b - a;
        const double length_squared = glm::dot(ab, ab);
        const double t = length_squared > 0.0 ? std::clamp(glm::dot(p - a, ab) / length_squared, 0.0, 1.0) : 0.0;
        const glm::dvec3 q = a + t * ab;
        const double d = glm::distance(p, q);
        if (d < best_distance) {
            best_distance = d;
            best = q;
        }
    }
    return best;
}

FeatureDetail::FeatureDetail(const FeatureGraph& features, std::span<const glm::dvec3> dense_positions,
                             std::span<const std::uint32_t> source_vertex,
                             std::span<const std::array<std::uint32_t, 2>> feature_edges)
    : dense_positions_(dense_positions), source_vertex_(source_vertex), feature_edges_at_(source_vertex.size()) {
    std::vector<std::uint8_t> kept(dense_positions.size(), 0);
    for (std::uint32_t v : source_vertex) kept[v] = 1;
    for (const auto& [a, b] : feature_edges) {
        std::vector<std::uint32_t> chain = feature_chain(features, source_vertex[a], source_vertex[b], kept);
        if (chain.empty())
            throw std::logic_error("the cage's feature edge " + std::to_string(a) + "-" + std::to_string(b) +
                                   " follows no chain of the dense mesh's features");
        feature_edges_at_[a].push_back({a, b});
        feature_edges_at_[b].push_back({a, b});
        chains_.emplace(std::array<std::uint32_t, 2>{a, b}, std::move(chain));
    }
}

std::optional<glm::dvec3> FeatureDetail::position(const rgb::BaseMesh& cage, const rgb::SurfacePoint& p,
                                                  const glm::dvec3& limit) const {
    if (const std::optional<std::uint32_t> v = rgb::base_vertex(cage, p)) {
        const auto& edges = feature_edges_at_[*v];
        if (edges.empty()) return std::nullopt;
        if (edges.size() != 2) return dense_positions_[source_vertex_[*v]];
        const glm::dvec3 first = nearest_on_chain(dense_positions_, chains_.at(edges[0]), limit);
        const glm::dvec3 second = nearest_on_chain(dense_positions_, chains_.at(edges[1]), limit);
        return glm::distance(second, limit) < glm::distance(first, limit) ? second : first;
    }
    const std::optional<std::uint32_t> h = rgb::base_edge_of(p);
    if (!h) return std::nullopt;
    const std::uint32_t a = cage.face(*h / 3)[*h % 3], b = cage.to_vertex(*h);
    const auto chain = chains_.find({std::min(a, b), std::max(a, b)});
    if (chain == chains_.end()) return std::nullopt;
    return nearest_on_chain(dense_positions_, chain->second, limit);
}

}  // namespace rgbdetail
