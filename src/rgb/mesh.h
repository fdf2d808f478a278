#pragma once
// The adaptive RGB mesh: a triangle mesh in flat arrays (faces, one opposite halfedge per face
// corner, per-vertex attributes) with the colour/level codes of RGB subdivision and the per-vertex
// Loop data of spec §4.3. There is no hierarchy: everything about coarser levels is derived.
//
// Halfedge 3f+i goes from corner i to corner i+1 of face f. Only opposites are stored. Each vertex
// keeps one outgoing halfedge; for a boundary vertex it is the one without an opposite, so that
// turning counter-clockwise from it visits the whole star.
//
// This class owns storage and navigation only. The operators (operators.h), refinement (refine.h)
// and Loop geometry (loop_geometry.h) are free functions on top of it.
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "rgb/face_type.h"
#include "rgb/handles.h"
#include "rgb/inline_vector.h"
#include "rgb/observer.h"

namespace rgb {

using Triangle = std::array<std::uint32_t, 3>;

// Live-slot ranges: iterate with `for (FaceId f : mesh.faces())`.
template <class Id>
class LiveRange {
public:
    class iterator {
    public:
        iterator(const std::vector<std::uint8_t>* alive, std::uint32_t i) : alive_(alive), i_(i) { skip(); }
        Id operator*() const { return Id(i_); }
        iterator& operator++() { ++i_; skip(); return *this; }
        bool operator!=(const iterator& o) const { return i_ != o.i_; }
        bool operator==(const iterator& o) const { return i_ == o.i_; }
    private:
        void skip() { while (i_ < alive_->size() && !(*alive_)[i_]) ++i_; }
        const std::vector<std::uint8_t>* alive_;
        std::uint32_t i_;
    };
    explicit LiveRange(const std::vector<std::uint8_t>& alive) : alive_(&alive) {}
    iterator begin() const { return iterator(alive_, 0); }
    iterator end() const { return iterator(alive_, static_cast<std::uint32_t>(alive_->size())); }
private:
    const std::vector<std::uint8_t>* alive_;
};

// The faces one operator deletes or creates: at most six (a split that completes two parents).
using FaceList = InlineVector<FaceId, 6>;

// A triangle to be created by replace_faces.
struct NewFace {
    std::array<VertexId, 3> v;
    FaceType type;
};

class Mesh {
public:
    Mesh() = default;
    // The base mesh Σ0: every triangle green, every vertex level 0, limit points computed.
    // Requires an oriented 2-manifold (io validates user input); throws std::invalid_argument
    // naming the first problem otherwise.
    Mesh(std::span<const glm::dvec3> positions, std::span<const Triangle> triangles);

    // ---- sizes and liveness ----
    std::size_t num_vertices() const { return vertex_count_; }
    std::size_t num_faces() const { return face_count_; }
    std::size_t vertex_capacity() const { return vertex_alive_.size(); }
    std::size_t face_capacity() const { return face_alive_.size(); }
    std::size_t num_base_vertices() const { return base_valence_.size(); }
    bool is_live(VertexId v) const { return v.idx < vertex_alive_.size() && vertex_alive_[v.idx]; }
    bool is_live(FaceId f) const { return f.idx < face_alive_.size() && face_alive_[f.idx]; }
    LiveRange<VertexId> vertices() const { return LiveRange<VertexId>(vertex_alive_); }
    LiveRange<FaceId> faces() const { return LiveRange<FaceId>(face_alive_); }
    int max_vertex_level() const;

    // ---- halfedge arithmetic ----
    static HalfedgeId halfedge(FaceId f, int corner) { return HalfedgeId(3 * f.idx + static_cast<std::uint32_t>(corner)); }
    static FaceId face(HalfedgeId h) { return FaceId(h.idx / 3); }
    static int corner(HalfedgeId h) { return static_cast<int>(h.idx % 3); }
    static HalfedgeId next(HalfedgeId h) { return HalfedgeId(h.idx - h.idx % 3 + (h.idx % 3 + 1) % 3); }
    static HalfedgeId prev(HalfedgeId h) { return HalfedgeId(h.idx - h.idx % 3 + (h.idx % 3 + 2) % 3); }
    HalfedgeId opposite(HalfedgeId h) const { return opposite_[h.idx]; }
    bool is_boundary(HalfedgeId h) const { return !opposite_[h.idx].valid(); }
    VertexId from_vertex(HalfedgeId h) const { return face_vertices_[h.idx / 3][h.idx % 3]; }
    VertexId to_vertex(HalfedgeId h) const { return from_vertex(next(h)); }
    // The vertex of h's face that is not on h.
    VertexId opposite_vertex(HalfedgeId h) const { return from_vertex(prev(h)); }
    // Outgoing halfedges around from_vertex(h); invalid when the boundary is reached.
    HalfedgeId ccw_rotated(HalfedgeId h) const { return opposite(prev(h)); }
    HalfedgeId cw_rotated(HalfedgeId h) const {
        HalfedgeId o = opposite(h);
        return o.valid() ? next(o) : HalfedgeId();
    }
    // Outgoing halfedge a->b, or invalid if a and b are not adjacent.
    HalfedgeId find_halfedge(VertexId a, VertexId b) const;
    // Either halfedge of the edge {a, b}: a->b if it exists, otherwise b->a; invalid if none.
    HalfedgeId find_edge(VertexId a, VertexId b) const;

    // ---- faces ----
    const std::array<VertexId, 3>& face_vertices(FaceId f) const { return face_vertices_[f.idx]; }
    const FaceType& type(FaceId f) const { return face_type_[f.idx]; }
    int level(FaceId f) const { return face_type_[f.idx].level; }
    Colour colour(FaceId f) const { return face_type_[f.idx].colour; }
    int corner_of(FaceId f, VertexId v) const;  // -1 if v is not a corner of f
    // Colour and level of the edge of h (spec §1.4), derived from its face.
    EdgeType edge_type(HalfedgeId h) const;
    // Topological angle of corner i of f in units of 30 degrees (spec §1.5).
    int angle(FaceId f, int corner) const;

    // ---- vertices ----
    HalfedgeId vertex_halfedge(VertexId v) const { return vertex_halfedge_[v.idx]; }
    int level(VertexId v) const { return vertex_level_[v.idx]; }
    bool is_boundary(VertexId v) const { return vertex_boundary_[v.idx] != 0; }
    // p^l(v) at the vertex's own level l (fixed at insertion).
    const glm::dvec3& insertion_position(VertexId v) const { return insertion_position_[v.idx]; }
    // p^inf(v), once known. It depends only on the base mesh, so once set it is final.
    std::optional<glm::dvec3> limit_position(VertexId v) const;
    bool has_limit(VertexId v) const { return limit_slot_[v.idx] != kNoLimit; }
    // Number of neighbours in the uniform mesh of the vertex's own level (base valence or 6).
    int uniform_valence(VertexId v) const;
    int valence(VertexId v) const;  // in the current mesh

    // Room for this many face and vertex slots, so that a large refinement does not regrow the arrays.
    void reserve(std::size_t faces, std::size_t vertices);

    // ---- observers ----
    void add_observer(MeshObserver* o);
    void remove_observer(MeshObserver* o);

    // ---- low-level editing, used by the operators; these keep adjacency but not RGB invariants ----
    VertexId add_vertex(int level, const glm::dvec3& insertion_position, bool boundary, VertexId a, VertexId b);
    // Caches p^inf(v). Logically const: the limit is a function of the base mesh alone, computed on
    // first need (loop_geometry.h), so caching it never changes what the mesh means.
    void set_limit_position(VertexId v, const glm::dvec3& p) const;
    // Delete `old_faces` (and the listed vertices, which must be used by no new face) and create
    // `new_faces` over the same region. Adjacency with the outside is rebuilt by matching edges.
    // Returns the new face ids in the order given. At most six faces each way.
    FaceList replace_faces(std::span<const FaceId> old_faces, std::span<const NewFace> new_faces,
                                      std::span<const VertexId> removed_vertices = {});

    // Bytes of the core arrays in use (sizes, not reserved capacity), for the memory benchmark.
    std::size_t memory_bytes() const;

private:
    friend struct MeshState capture_state(const Mesh& mesh);
    friend Mesh restore_state(const struct MeshState& state);

    static constexpr std::uint32_t kNoLimit = 0xffffffffu;
    FaceId allocate_face();
    void release_face(FaceId f);
    void release_vertex(VertexId v);
    void update_vertex_halfedge(VertexId v, HalfedgeId any_outgoing);
    // The outgoing halfedge on the boundary reached by turning clockwise from h (h itself if none).
    HalfedgeId boundary_outgoing(HalfedgeId h) const;
    // Whether h, v's outgoing halfedge before a replace, still is one after it (and still on the
    // boundary for a boundary vertex).
    bool reusable_vertex_halfedge(VertexId v, HalfedgeId h) const;
    // v's outgoing halfedge derived from `outgoing`, one of its halfedges in a new face.
    void set_vertex_halfedge(VertexId v, HalfedgeId outgoing);

    // faces
    std::vector<std::array<VertexId, 3>> face_vertices_;
    std::vector<FaceType> face_type_;
    std::vector<HalfedgeId> opposite_;
    std::vector<std::uint8_t> face_alive_;
    std::vector<std::uint32_t> free_faces_;
    std::size_t face_count_ = 0;
    // vertices
    std::vector<glm::dvec3> insertion_position_;
    std::vector<HalfedgeId> vertex_halfedge_;
    std::vector<std::uint8_t> vertex_level_;
    std::vector<std::uint8_t> vertex_boundary_;
    std::vector<std::uint8_t> vertex_alive_;
    mutable std::vector<std::uint32_t> limit_slot_;
    std::vector<std::uint32_t> free_vertices_;
    std::size_t vertex_count_ = 0;
    // Limit points are needed for a minority of vertices (those whose display level exceeds their
    // own), so they live in a pool instead of a dense array: this keeps the mesh under 2x a plain mesh.
    mutable std::vector<glm::dvec3> limit_pool_;
    mutable std::vector<std::uint32_t> free_limit_slots_;
    // Base vertices are never removed, so their ids stay below num_base_vertices().
    std::vector<std::uint16_t> base_valence_;

    std::vector<MeshObserver*> observers_;
};

}  // namespace rgb
