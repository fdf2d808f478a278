#pragma once
// The sharp features of a dense mesh M (issue 28: `remesh --sharp-angle`): its interior edges whose
// two face normals differ by more than an angle (rgb/mesh/sharp_angle.h's convention, Blender's auto
// smooth), as a graph of chains. The cage keeps them (cage.h: its collapses run along a chain, never
// across one, and the chains' ends and junctions stay), so that the cage's crease edges follow M's
// ridges and corners, and the detail of a crease edge lands on its chain (remesh.cpp) rather than
// wherever a ray from the smooth surface beside the ridge meets M.
//
// Plain data in and out: positions and rgb::Triangle index triples of an oriented manifold.
#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "rgb/mesh/base_mesh.h"
#include "rgb/mesh/surface_point.h"

namespace rgbdetail {

// M's feature edges, and for each vertex its neighbours along them (compressed rows).
class FeatureGraph {
public:
    FeatureGraph() = default;
    // Over vertex_count vertices; edges (a, b) with a < b, each once.
    FeatureGraph(std::size_t vertex_count, std::vector<std::array<std::uint32_t, 2>> edges);

    std::span<const std::array<std::uint32_t, 2>> edges() const { return edges_; }
    bool empty() const { return edges_.empty(); }
    std::size_t num_vertices() const { return offsets_.size() - 1; }
    std::span<const std::uint32_t> neighbours(std::uint32_t v) const {
        return {neighbours_.data() + offsets_[v], neighbours_.data() + offsets_[v + 1]};
    }
    std::size_t valence(std::uint32_t v) const { return offsets_[v + 1] - offsets_[v]; }
    bool has_edge(std::uint32_t a, std::uint32_t b) const;

private:
    std::vector<std::array<std::uint32_t, 2>> edges_;
    std::vector<std::uint32_t> offsets_{0};
    std::vector<std::uint32_t> neighbours_;
};

// The interior edges of M whose dihedral angle exceeds `degrees`, less every connected set of them
// shorter in all than `shortest_feature` (noise and small details: a cage whose edges are longer
// cannot follow them, and each such set would pin vertices the decimation needs to remove).
FeatureGraph find_sharp_features(std::span<const glm::dvec3> positions, std::span<const rgb::Triangle> triangles,
                                 double degrees, double shortest_feature);

// The vertices the cage must keep for its creases to stay M's chains: the ends and junctions of
// chains (feature valence 1 or at least 3) and three vertices spread along every closed chain that
// has neither (a closed ridge, which collapses could otherwise shrink to nothing), ascending.
std::vector<std::uint32_t> feature_anchors(const FeatureGraph& features);

// The chain of feature edges joining a and b, two vertices that the cage kept and joined by a crease
// edge (so every vertex between them has feature valence 2 and was removed): the vertices from a to
// b, or empty where no such chain exists. `kept` tells the vertices the cage kept.
std::vector<std::uint32_t> feature_chain(const FeatureGraph& features, std::uint32_t a, std::uint32_t b,
                                         std::span<const std::uint8_t> kept);

// The point of the polyline through positions[chain[i]] nearest to p (the first of equal ones).
glm::dvec3 nearest_on_chain(std::span<const glm::dvec3> positions, std::span<const std::uint32_t> chain, const glm::dvec3& p);

// Where the hierarchy over a cage that kept M's features (cage.h) meets M along those features: a
// point on a cage feature edge goes to the point of its chain nearest its limit point (a ray along the
// limit normal of a crease would land beside the ridge, wherever the smooth surface next to it
// points), and so does a cage vertex inside a crease (two feature edges), on its two chains: its
// crease limit slides along the ridge by as much as a few hundredths of the size where its crease
// neighbours are unevenly spaced, and its neighbours along the crease slide with it. A corner or the
// end of a crease (one feature edge, or three and more) is the M vertex it was made from, so that
// M's peaks are kept exactly. Elsewhere nothing: rays decide.
class FeatureDetail {
public:
    // Throws std::logic_error for a cage feature edge that follows no chain of `features`.
    FeatureDetail(const FeatureGraph& features, std::span<const glm::dvec3> dense_positions,
                  std::span<const std::uint32_t> source_vertex, std::span<const std::array<std::uint32_t, 2>> feature_edges);

    // M's point for the hierarchy point p of `cage` (whose limit point is `limit`), or nothing where
    // p lies on no feature.
    std::optional<glm::dvec3> position(const rgb::BaseMesh& cage, const rgb::SurfacePoint& p, const glm::dvec3& limit) const;

private:
    std::span<const glm::dvec3> dense_positions_;
    std::span<const std::uint32_t> source_vertex_;
    std::vector<std::vector<std::array<std::uint32_t, 2>>> feature_edges_at_;  // per cage vertex
    std::map<std::array<std::uint32_t, 2>, std::vector<std::uint32_t>> chains_;  // by cage edge (a < b)
};

}  // namespace rgbdetail
