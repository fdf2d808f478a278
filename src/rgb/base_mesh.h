#pragma once
// The base mesh Σ0 that an adaptive mesh refines: its triangles, their adjacency, the input
// positions, valences and boundary flags. It never changes once built, so every adaptive mesh
// refined from it (and every copy of one) shares it. The virtual uniform hierarchy Σk above it is
// addressed by SurfacePoint (surface_point.h).
//
// Base halfedge 3f+i runs from corner i to corner i+1 of base face f, as in Mesh.
#include <array>
#include <cstdint>
#include <memory>
#include <mutex>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

namespace rgb {

class BaseFaceIndex;

using Triangle = std::array<std::uint32_t, 3>;

class BaseMesh {
public:
    static constexpr std::uint32_t kNone = 0xffffffffu;

    // Requires an oriented 2-manifold triangle mesh whose vertices are all used; throws
    // std::invalid_argument naming the first problem otherwise (io validates user input first, so
    // this only catches callers that skip it).
    BaseMesh(std::span<const glm::dvec3> positions, std::span<const Triangle> triangles);
    ~BaseMesh();
    BaseMesh(const BaseMesh&) = delete;
    BaseMesh& operator=(const BaseMesh&) = delete;

    std::size_t num_vertices() const { return positions_.size(); }
    std::size_t num_faces() const { return faces_.size(); }
    const glm::dvec3& position(std::uint32_t v) const { return positions_[v]; }
    std::span<const glm::dvec3> positions() const { return positions_; }
    const Triangle& face(std::uint32_t f) const { return faces_[f]; }
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
    std::vector<glm::dvec3> positions_;
    std::vector<Triangle> faces_;
    std::vector<std::uint32_t> opposite_;
    std::vector<std::uint32_t> vertex_halfedge_;
    std::vector<std::uint32_t> valence_;
    std::vector<std::uint8_t> boundary_;
    double longest_edge_ = 0.0;
    mutable std::once_flag index_built_;
    mutable std::unique_ptr<BaseFaceIndex> index_;
};

}  // namespace rgb
