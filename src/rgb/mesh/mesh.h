#pragma once
// Layer rgb/mesh (topology: base and adaptive mesh, addresses, operators, journal, invariants,
// navigation, state): stores values, computes none; includes rgb/rules and rgb/support only.
// docs/architecture.md draws the layers.
// The adaptive RGB mesh: a triangle mesh in flat arrays (faces, one opposite halfedge per face
// corner, per-vertex attributes) with the colour/level codes of RGB subdivision and the per-vertex
// Loop data of spec §4.3, over an immutable base mesh (base_mesh.h). There is no hierarchy: what the
// coarser levels hold is derived, from the codes or from each vertex's address in the hierarchy.
//
// Halfedge 3f+i goes from corner i to corner i+1 of face f. Only opposites are stored. Each vertex
// keeps one outgoing halfedge; for a boundary vertex it is the one without an opposite, so that
// turning counter-clockwise from it visits the whole star.
//
// This class owns storage and navigation only. The operators (operators.h), refinement (refine.h)
// and Loop geometry (loop_geometry.h) are free functions on top of it.
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "rgb/mesh/base_mesh.h"
#include "rgb/mesh/handles.h"
#include "rgb/mesh/observer.h"
#include "rgb/mesh/surface_point.h"
#include "rgb/rules/face_type.h"
#include "rgb/support/inline_vector.h"
#include "rgb/support/limit_cache.h"

namespace rgb {

// The finest level a request may ask for (levels are stored in five bits, addresses in 32).
inline constexpr int kMaxLevel = 20;

// Live-slot ranges: iterate with `for (FaceId f : mesh.faces())`.
template <class Id>
class LiveRange {
public:
    static constexpr std::uint8_t kDead = 0xff;
    class iterator {
    public:
        iterator(const std::vector<std::uint8_t>* codes, std::uint32_t i) : codes_(codes), i_(i) { skip(); }
        Id operator*() const { return Id(i_); }
        iterator& operator++() { ++i_; skip(); return *this; }
        bool operator!=(const iterator& o) const { return i_ != o.i_; }
        bool operator==(const iterator& o) const { return i_ == o.i_; }
    private:
        void skip() { while (i_ < codes_->size() && (*codes_)[i_] == kDead) ++i_; }
        const std::vector<std::uint8_t>* codes_;
        std::uint32_t i_;
    };
    explicit LiveRange(const std::vector<std::uint8_t>& codes) : codes_(&codes) {}
    iterator begin() const { return iterator(codes_, 0); }
    iterator end() const { return iterator(codes_, static_cast<std::uint32_t>(codes_->size())); }
private:
    const std::vector<std::uint8_t>* codes_;
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
    Mesh();
    // The base mesh Σ0: every triangle green, every vertex level 0. See BaseMesh for what it requires.
    Mesh(std::span<const glm::dvec3> positions, std::span<const Triangle> triangles);
    explicit Mesh(std::shared_ptr<const BaseMesh> base);
    // Copies and moves carry the mesh, not its observers: an observer follows one object.
    Mesh(const Mesh& other);
    Mesh(Mesh&& other) noexcept;
    Mesh& operator=(const Mesh& other);
    Mesh& operator=(Mesh&& other) noexcept;
    ~Mesh() = default;

    const BaseMesh& base() const { return *base_; }
    const std::shared_ptr<const BaseMesh>& shared_base() const { return base_; }

    // ---- sizes and liveness ----
    std::size_t num_vertices() const { return vertex_count_; }
    std::size_t num_faces() const { return face_count_; }
    std::size_t vertex_capacity() const { return vertex_info_.size(); }
    std::size_t face_capacity() const { return face_code_.size(); }
    // Face slots the arrays hold without growing (reserve).
    std::size_t reserved_face_slots() const { return face_code_.capacity(); }
    std::size_t num_base_vertices() const { return base_->num_vertices(); }
    bool is_live(VertexId v) const { return v.idx < vertex_info_.size() && vertex_info_[v.idx] != kDead; }
    bool is_live(FaceId f) const { return f.idx < face_code_.size() && face_code_[f.idx] != kDead; }
    LiveRange<VertexId> vertices() const { return LiveRange<VertexId>(vertex_info_); }
    LiveRange<FaceId> faces() const { return LiveRange<FaceId>(face_code_); }
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
    // Outgoing halfedge a->b, or invalid if a and b are not adjacent (or either is not live).
    HalfedgeId find_halfedge(VertexId a, VertexId b) const;
    // Either halfedge of the edge {a, b}: a->b if it exists, otherwise b->a; invalid if none.
    HalfedgeId find_edge(VertexId a, VertexId b) const;

    // ---- faces ----
    const std::array<VertexId, 3>& face_vertices(FaceId f) const { return face_vertices_[f.idx]; }
    FaceType type(FaceId f) const { return unpack(face_code_[f.idx]); }
    int level(FaceId f) const { return face_code_[f.idx] >> 3; }
    Colour colour(FaceId f) const { return colour_of(face_code_[f.idx]); }
    int corner_of(FaceId f, VertexId v) const;  // -1 if v is not a corner of f
    // Colour and level of the edge of h (spec §1.4), derived from its face.
    EdgeType edge_type(HalfedgeId h) const {
        const FaceType t = type(face(h));
        const int i = corner(h);
        if (t.colour == Colour::Green) return {Colour::Green, t.level};
        if (i == t.red_edge) return {Colour::Red, t.level};
        if (t.colour == Colour::Blue) return {Colour::Green, t.level + 1};
        // Red: the half of the split edge touches the top vertex (the one of level l+1).
        const bool touches_top = level(from_vertex(h)) > t.level || level(to_vertex(h)) > t.level;
        return {Colour::Green, touches_top ? t.level + 1 : t.level};
    }
    // Topological angle of corner i of f in units of 30 degrees (spec §1.5).
    int angle(FaceId f, int corner) const;

    // ---- vertices ----
    HalfedgeId vertex_halfedge(VertexId v) const { return vertex_halfedge_[v.idx]; }
    // Asks the processor for what a walk around v reads first (its halfedge, level and position; with
    // `around`, the first face too, which needs the halfedge loaded), for a caller that knows which
    // vertices it visits next.
    void prefetch(VertexId v, bool around) const {
        __builtin_prefetch(&vertex_halfedge_[v.idx]);
        __builtin_prefetch(&vertex_info_[v.idx]);
        __builtin_prefetch(&insertion_position_[v.idx]);
        if (around && vertex_halfedge_[v.idx].valid()) {
            __builtin_prefetch(&face_vertices_[vertex_halfedge_[v.idx].idx / 3]);
            __builtin_prefetch(&opposite_[vertex_halfedge_[v.idx].idx]);
        }
    }
    int level(VertexId v) const { return vertex_info_[v.idx] & kLevelMask; }
    bool is_boundary(VertexId v) const { return (vertex_info_[v.idx] & kBoundaryBit) != 0; }
    bool is_base_vertex(VertexId v) const { return v.idx < base_->num_vertices(); }
    // p^l(v) at the vertex's own level l (fixed at insertion).
    const glm::dvec3& insertion_position(VertexId v) const { return insertion_position_[v.idx]; }
    // The vertex's address in the uniform hierarchy (surface_point.h): its identity, from which its
    // base-space position, parent edge and stencil follow.
    SurfacePoint address(VertexId v) const {
        const PackedAddress& p = address_[v.idx];
        SurfacePoint s;
        s.face = p.face;
        s.level = level(v);
        s.a = {(std::uint32_t(1) << s.level) - p.a1 - p.a2, p.a1, p.a2};
        return s;
    }
    // Spec §3.5: the vertex under midpoint subdivision of the base mesh; it never moves.
    glm::dvec3 base_space_position(VertexId v) const { return rgb::base_space_position(*base_, address(v)); }
    // p^inf(v) if it has been computed (see loop_geometry.h, which computes it on demand).
    std::optional<glm::dvec3> cached_limit(VertexId v) const {
        // The flag answers the common "not cached" without a probe into the table.
        if (!has_cached_limit(v)) return std::nullopt;
        return limits_.find(v.idx);
    }
    // Asks the processor for where the table of limits keeps (or will keep) v's, ahead of a lookup.
    void prefetch_limit(VertexId v) const { limits_.prefetch(v.idx); }
    // Whether cached_limit has a value, from the flag alone: for callers that only ask.
    bool has_cached_limit(VertexId v) const { return (vertex_info_[v.idx] & kLimitBit) != 0; }
    // Number of neighbours in the uniform mesh of the vertex's own level (base valence or 6).
    int uniform_valence(VertexId v) const;
    int valence(VertexId v) const;  // in the current mesh

    // Room for this many face and vertex slots, so that a large refinement does not regrow the arrays.
    void reserve(std::size_t faces, std::size_t vertices);
    // The reserved memory that appending this many face and vertex slots will write first, per array
    // (for Prefault; valid until observers hear arrays_moving).
    std::vector<std::span<std::byte>> room_ahead(std::size_t faces, std::size_t vertices);

    // ---- observers ----
    void add_observer(MeshObserver* o);
    void remove_observer(MeshObserver* o);

    // ---- low-level editing, used by the operators; these keep adjacency but not RGB invariants ----
    // A vertex to be inserted on the edge (a, b) of the next coarser uniform level.
    struct NewVertex {
        int level;
        glm::dvec3 insertion_position;
        bool boundary;
        VertexId a, b;
        // Where it is, when known (an undo putting back a removed vertex); else the midpoint of a and b.
        std::optional<SurfacePoint> address = std::nullopt;
    };
    // The slot the next added vertex will take, so that new faces can name it before it exists.
    VertexId next_vertex_slot() const;
    // Caches p^inf(v). Logically const: the limit is a function of the base mesh alone, so caching it
    // never changes what the mesh means.
    void cache_limit(VertexId v, const glm::dvec3& p) const {
        if (vertex_info_[v.idx] & kLimitBit) return;
        if (limits_.insert_grows()) announce_arrays_moving();
        limits_.insert(v.idx, p);
        vertex_info_[v.idx] |= kLimitBit;
    }
    // Room for `count` cached limits in all, made at once (a growth moves the entries a few at a time
    // over later inserts, each a cache miss): for a caller that knows about how many it will cache.
    void reserve_limits(std::size_t count) const {
        if (limits_.reserve_grows(count)) announce_arrays_moving();
        limits_.reserve(count);
    }
    // The table of limits' memory, to be faulted in ahead (Prefault) while it is still untouched.
    std::span<std::byte> limit_table() const { return limits_.table(); }
    // Delete `old_faces` (and the listed vertices, which must be used by no new face), add `added` (in
    // slot next_vertex_slot()) and create `new_faces` over the same region. Adjacency with the outside
    // is rebuilt by matching edges. Observers hear of it in the order observer.h states. Returns the
    // new face ids in the order given. At most six faces each way. Whole or nothing: a failure
    // (out of memory, a level beyond kMaxLevel, an observer throwing while told of a removal)
    // leaves the mesh unchanged; an observer throwing while told of an addition is rethrown after
    // the replacement is complete and every observer has been told.
    FaceList replace_faces(std::span<const FaceId> old_faces, std::span<const NewFace> new_faces,
                           std::span<const VertexId> removed_vertices = {}, const NewVertex* added = nullptr);

    // A face's type in one byte (as stored here and in the undo journal): bits 0-2 are 0 for green,
    // 1 + red edge for red, 4 + red edge for blue; bits 3-7 the level. 0xff marks a dead slot.
    static std::uint8_t pack(const FaceType& t) {
        const int kind = t.colour == Colour::Green ? 0 : (t.colour == Colour::Red ? 1 : 4) + t.red_edge;
        return static_cast<std::uint8_t>(kind | (t.level << 3));
    }
    static Colour colour_of(std::uint8_t code) {
        const int kind = code & 7;
        return kind == 0 ? Colour::Green : (kind <= 3 ? Colour::Red : Colour::Blue);
    }
    static FaceType unpack(std::uint8_t code) {
        const int kind = code & 7;
        return {colour_of(code), static_cast<std::uint8_t>(code >> 3),
                static_cast<std::uint8_t>(kind == 0 ? 0 : (kind <= 3 ? kind - 1 : kind - 4))};
    }

    // ---- values computed elsewhere (values/restore_state.h): the mesh stores them, never computes them ----
    // Every vertex slot's p^l at once, for a restore that computed them from the addresses.
    void assign_insertion_positions(std::vector<glm::dvec3> positions) { insertion_position_ = std::move(positions); }
    // Another base mesh with the same positions and faces but other tags, and every vertex slot's p^l
    // under its rules: the vertex set, faces and slots stay, every cached limit goes (they followed the
    // old rules). Observers are not told: every position changes.
    void retag(std::shared_ptr<const BaseMesh> base, std::vector<glm::dvec3> insertion_positions);

    // Bytes of the core arrays in use (sizes, not reserved capacity): connectivity, positions, RGB
    // codes and limit points, for the memory benchmark. The vertex addresses are counted apart.
    std::size_t memory_bytes() const;
    std::size_t address_bytes() const { return address_.size() * sizeof(PackedAddress); }

private:
    friend struct MeshState capture_state(const Mesh& mesh);
    friend struct RestoredTopology restore_topology(const struct MeshState& state, std::shared_ptr<const BaseMesh> base,
                                                    const class ProgressSpan& progress);

    static constexpr std::uint8_t kDead = 0xff;
    static constexpr std::uint8_t kLevelMask = 0x3f;
    static constexpr std::uint8_t kBoundaryBit = 0x40;
    static constexpr std::uint8_t kLimitBit = 0x80;  // the limit is in limits_ (a live level is below 63)
    struct PackedAddress {
        std::uint32_t face, a1, a2;  // a0 = 2^level - a1 - a2
    };

    void init_base_state();
    // Checks the level and gives the canonical address (throws before anything changes).
    SurfacePoint new_vertex_address(const NewVertex& added) const;
    // Grows the arrays so that a replacement of this size cannot fail for lack of memory half-way.
    void make_room(std::size_t faces_released, std::size_t faces_added, std::size_t vertices_released, bool vertex_added);
    template <class Vector>
    void room_for(Vector& v, std::size_t more);
    // Tells the observers that the face or vertex arrays or the table of limits are about to move.
    void announce_arrays_moving() const;
    VertexId allocate_vertex(const NewVertex& added, const SurfacePoint& address);
    FaceId allocate_face();
    void release_face(FaceId f);
    void release_vertex(VertexId v);
    // The outgoing halfedge on the boundary reached by turning clockwise from h (h itself if none).
    HalfedgeId boundary_outgoing(HalfedgeId h) const;
    // Whether h, v's outgoing halfedge before a replace, still is one after it (and still on the
    // boundary for a boundary vertex).
    bool reusable_vertex_halfedge(VertexId v, HalfedgeId h) const;
    // v's outgoing halfedge derived from `outgoing`, one of its halfedges in a new face.
    void set_vertex_halfedge(VertexId v, HalfedgeId outgoing);

    std::shared_ptr<const BaseMesh> base_;
    // faces
    std::vector<std::array<VertexId, 3>> face_vertices_;
    std::vector<HalfedgeId> opposite_;
    std::vector<std::uint8_t> face_code_;
    std::vector<std::uint32_t> free_faces_;
    std::size_t face_count_ = 0;
    // vertices
    std::vector<glm::dvec3> insertion_position_;
    std::vector<HalfedgeId> vertex_halfedge_;
    // level (bits 0-5), boundary (bit 6), limit cached (bit 7); 0xff: dead slot. Mutable for the cache flag.
    mutable std::vector<std::uint8_t> vertex_info_;
    std::vector<PackedAddress> address_;
    std::vector<std::uint32_t> free_vertices_;
    std::size_t vertex_count_ = 0;
    mutable LimitCache limits_;

    std::vector<MeshObserver*> observers_;
};

}  // namespace rgb
