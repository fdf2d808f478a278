#pragma once
// The base mesh Σ0 that an adaptive mesh refines: its triangles, their adjacency, the input
// positions, valences and boundary flags. It never changes once built, so every adaptive mesh
// refined from it (and every copy of one) shares it. The virtual uniform hierarchy Σk above it is
// addressed by SurfacePoint (surface_point.h).
//
// Base halfedge 3f+i runs from corner i to corner i+1 of base face f, as in Mesh.
//
// The crease and corner tags (sharp_features.h) are part of it: refinement rules follow from them
// (vertex_rules.h), so meshes refined from one base mesh always agree on them.
#include <array>
#include <cstdint>
#include <memory>
#include <mutex>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "rgb/mesh/vertex_rules.h"
#include "rgb/rules/sharp_features.h"

namespace rgb {

class BaseFaceIndex;
class DetailPositions;

using Triangle = std::array<std::uint32_t, 3>;

class BaseMesh {
public:
    static constexpr std::uint32_t kNone = 0xffffffffu;

    // Requires an oriented 2-manifold triangle mesh whose vertices are all used, and tags on existing
    // edges and vertices with sharpness 0-10 (above 10 counts as 10); throws std::invalid_argument
    // naming the first problem otherwise (io validates user input first, so this only catches callers
    // that skip it).
    // `detail`, if given, are the positions of a dense surface for every vertex of the hierarchy
    // (detail_positions.h), sampled over a base mesh of these triangles.
    BaseMesh(std::span<const glm::dvec3> positions, std::span<const Triangle> triangles,
             const SharpFeatures& features = {}, std::shared_ptr<const DetailPositions> detail = nullptr);
    ~BaseMesh();
    BaseMesh(const BaseMesh&) = delete;
    BaseMesh& operator=(const BaseMesh&) = delete;

    std::size_t num_vertices() const { return positions_.size(); }
    std::size_t num_faces() const { return faces_.size(); }
    const glm::dvec3& position(std::uint32_t v) const { return positions_[v]; }
    std::span<const glm::dvec3> positions() const { return positions_; }
    const Triangle& face(std::uint32_t f) const { return faces_[f]; }
    std::array<glm::dvec3, 3> corner_positions(std::uint32_t f) const {
        return {positions_[faces_[f][0]], positions_[faces_[f][1]], positions_[faces_[f][2]]};
    }
    std::span<const Triangle> faces() const { return faces_; }

    // The halfedge opposite base halfedge h (3f+i), or kNone on the boundary.
    std::uint32_t opposite(std::uint32_t h) const { return opposite_[h]; }
    bool is_boundary_vertex(std::uint32_t v) const { return boundary_[v] != 0; }
    // Neighbours in Σ0 (for a boundary vertex, the number of incident edges).
    int valence(std::uint32_t v) const { return static_cast<int>(valence_[v]); }
    // An outgoing base halfedge of v; for a boundary vertex the one on the boundary, so that turning
    // counter-clockwise from it visits every incident face.
    std::uint32_t vertex_halfedge(std::uint32_t v) const { return vertex_halfedge_[v]; }
    // Outgoing halfedge reached by turning counter-clockwise, or kNone at the boundary.
    std::uint32_t ccw_rotated(std::uint32_t h) const {
        const std::uint32_t previous = h - h % 3 + (h % 3 + 2) % 3;
        return opposite_[previous];
    }
    std::uint32_t to_vertex(std::uint32_t h) const { return faces_[h / 3][(h % 3 + 1) % 3]; }

    // The neighbours of v in Σ0 in counter-clockwise order; for a boundary vertex the first and last
    // are its two boundary neighbours.
    std::vector<std::uint32_t> ring(std::uint32_t v) const;

    // ---- sharp features (docs/loop-creases.md §1) ----
    // The tags as given, normalised: each edge once with a < b, sorted, later tags of the same edge or
    // vertex replacing earlier ones, sharpness 0 dropped, above 10 lowered to 10.
    const SharpFeatures& sharp_features() const { return features_; }
    // Whether any rule differs from untagged Loop (an interior edge tagged, or a vertex a corner):
    // false means every value is the spec's, and the core skips every crease test.
    bool has_sharp_features() const { return !edge_sharpness_.empty(); }
    // Sharpness of the edge of halfedge h: 10 on the boundary, else its tag (0 if none).
    int edge_sharpness(std::uint32_t h) const {
        if (edge_sharpness_.empty()) return opposite_[h] == kNone ? kInfiniteSharpness : 0;
        return edge_sharpness_[h];
    }
    // A vertex's corner sharpness: its tag, or 10 for a boundary vertex with a single face under
    // edge-and-corner boundaries.
    int corner_sharpness(std::uint32_t v) const { return edge_sharpness_.empty() ? 0 : corner_sharpness_[v]; }
    // Whether v is a corner or has a sharp interior edge, so its rules are not untagged Loop's.
    bool has_sharp_rules(std::uint32_t v) const { return !edge_sharpness_.empty() && sharp_rules_[v] != 0; }
    // The rule regimes of a vertex with sharp rules (vertex_rules.h), kept because every value of it
    // and of its neighbourhood needs them; nullptr for any other vertex.
    const Regimes* sharp_vertex_regimes(std::uint32_t v) const {
        return has_sharp_rules(v) ? &sharp_regimes_[sharp_rules_[v] - 1] : nullptr;
    }

    // ---- detail (detail_positions.h) ----
    // The dense surface's positions, if this base mesh is a cage with detail: then every vertex is
    // displayed there (loop_geometry.h, displayed_position), and the Loop values stay those of the cage.
    const DetailPositions* detail() const { return detail_.get(); }
    const std::shared_ptr<const DetailPositions>& shared_detail() const { return detail_; }

    // Bounding-volume hierarchy over the base triangles, built on first use.
    const BaseFaceIndex& face_index() const;
    // The longest base edge: no triangle of any Σk is larger than this.
    double longest_edge() const { return longest_edge_; }

    std::size_t memory_bytes() const;
    // Different for every base mesh a process makes, so that caches of derived values can tell
    // whether they belong to this one (an address can be reused by a later base mesh).
    std::uint64_t serial() const { return serial_; }

private:
    std::uint64_t serial_;
    // Checks, normalises and stores the tags, after the adjacency is built.
    void set_sharp_features(const SharpFeatures& features);
    // The halfedge a->b or b->a, or kNone.
    std::uint32_t find_edge(std::uint32_t a, std::uint32_t b) const;

    std::vector<glm::dvec3> positions_;
    std::vector<Triangle> faces_;
    std::vector<std::uint32_t> opposite_;
    std::vector<std::uint32_t> vertex_halfedge_;
    std::vector<std::uint32_t> valence_;
    std::vector<std::uint8_t> boundary_;
    double longest_edge_ = 0.0;
    SharpFeatures features_;
    // Empty without sharp features; otherwise per halfedge and per vertex.
    std::vector<std::uint8_t> edge_sharpness_, corner_sharpness_;
    // Per vertex: 0, or 1 + the index of its regimes in sharp_regimes_.
    std::vector<std::uint32_t> sharp_rules_;
    std::vector<Regimes> sharp_regimes_;
    std::shared_ptr<const DetailPositions> detail_;
    mutable std::once_flag index_built_;
    mutable std::unique_ptr<BaseFaceIndex> index_;
};

}  // namespace rgb
