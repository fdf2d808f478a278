#include "rgb/mesh/mesh.h"

#include <algorithm>
#include <bit>
#include <exception>
#include <stdexcept>
#include <string>

namespace rgb {

Mesh::Mesh() : Mesh(std::make_shared<const BaseMesh>(std::span<const glm::dvec3>(), std::span<const Triangle>())) {}

Mesh::Mesh(std::span<const glm::dvec3> positions, std::span<const Triangle> triangles)
    : Mesh(std::make_shared<const BaseMesh>(positions, triangles)) {}

Mesh::Mesh(std::shared_ptr<const BaseMesh> base) : base_(std::move(base)) { init_base_state(); }

Mesh::Mesh(const Mesh& other) { *this = other; }

Mesh::Mesh(Mesh&& other) noexcept { *this = std::move(other); }

// An assignment frees or hands over the arrays: observers of both meshes hear of it first.
Mesh& Mesh::operator=(const Mesh& other) {
    if (this == &other) return *this;
    announce_arrays_moving();
    auto observers = std::move(observers_);
    base_ = other.base_;
    face_vertices_ = other.face_vertices_;
    opposite_ = other.opposite_;
    face_code_ = other.face_code_;
    free_faces_ = other.free_faces_;
    face_count_ = other.face_count_;
    insertion_position_ = other.insertion_position_;
    vertex_halfedge_ = other.vertex_halfedge_;
    vertex_info_ = other.vertex_info_;
    address_ = other.address_;
    free_vertices_ = other.free_vertices_;
    vertex_count_ = other.vertex_count_;
    limits_ = other.limits_;
    observers_ = std::move(observers);
    return *this;
}

Mesh& Mesh::operator=(Mesh&& other) noexcept {
    if (this == &other) return *this;
    announce_arrays_moving();
    other.announce_arrays_moving();
    auto observers = std::move(observers_);
    base_ = std::move(other.base_);
    face_vertices_ = std::move(other.face_vertices_);
    opposite_ = std::move(other.opposite_);
    face_code_ = std::move(other.face_code_);
    free_faces_ = std::move(other.free_faces_);
    face_count_ = other.face_count_;
    insertion_position_ = std::move(other.insertion_position_);
    vertex_halfedge_ = std::move(other.vertex_halfedge_);
    vertex_info_ = std::move(other.vertex_info_);
    address_ = std::move(other.address_);
    free_vertices_ = std::move(other.free_vertices_);
    vertex_count_ = other.vertex_count_;
    limits_ = std::move(other.limits_);
    observers_ = std::move(observers);
    return *this;
}

void Mesh::init_base_state() {
    const BaseMesh& b = *base_;
    const auto nv = static_cast<std::uint32_t>(b.num_vertices());
    insertion_position_.assign(b.positions().begin(), b.positions().end());
    vertex_info_.resize(nv);
    address_.resize(nv);
    vertex_halfedge_.resize(nv);
    for (std::uint32_t v = 0; v < nv; ++v) {
        vertex_info_[v] = b.is_boundary_vertex(v) ? kBoundaryBit : 0;
        const std::uint32_t h = b.vertex_halfedge(v);
        vertex_halfedge_[v] = HalfedgeId(h);
        const SurfacePoint p = corner_point(h / 3, static_cast<int>(h % 3));
        address_[v] = {p.face, p.a[1], p.a[2]};
    }
    vertex_count_ = nv;
    const std::size_t nf = b.num_faces();
    face_vertices_.resize(nf);
    opposite_.resize(3 * nf);
    face_code_.assign(nf, pack(FaceType{}));
    for (std::uint32_t f = 0; f < nf; ++f) {
        for (int i = 0; i < 3; ++i) face_vertices_[f][i] = VertexId(b.face(f)[i]);
        for (std::uint32_t i = 0; i < 3; ++i) {
            const std::uint32_t o = b.opposite(3 * f + i);
            opposite_[3 * f + i] = o == BaseMesh::kNone ? HalfedgeId() : HalfedgeId(o);
        }
    }
    face_count_ = nf;
}

int Mesh::max_vertex_level() const {
    int m = 0;
    for (VertexId v : vertices()) m = std::max(m, level(v));
    return m;
}

HalfedgeId Mesh::find_halfedge(VertexId a, VertexId b) const {
    if (!is_live(a) || !is_live(b)) return HalfedgeId();
    const HalfedgeId start = vertex_halfedge_[a.idx];
    HalfedgeId h = start;
    do {
        if (to_vertex(h) == b) return h;
        h = ccw_rotated(h);
    } while (h.valid() && h != start);
    return HalfedgeId();
}

// One walk around a rather than a walk around each end: every face at a that holds the edge holds it
// as a->b (h itself) or as b->a (the halfedge before h, whose opposite is a->b where there is one), so
// the walk stops at the edge's first face, and an edge missing costs one ring instead of two.
HalfedgeId Mesh::find_edge(VertexId a, VertexId b) const {
    if (!is_live(a) || !is_live(b)) return HalfedgeId();
    const HalfedgeId start = vertex_halfedge_[a.idx];
    HalfedgeId h = start;
    do {
        const std::array<VertexId, 3>& corners = face_vertices_[h.idx / 3];
        const std::uint32_t corner = h.idx % 3;
        const HalfedgeId before = prev(h), turned = opposite(before);  // turned: ccw_rotated(h)
        if (corners[(corner + 1) % 3] == b) return h;
        if (corners[(corner + 2) % 3] == b) return turned.valid() ? turned : before;  // before is b->a
        h = turned;
    } while (h.valid() && h != start);
    return HalfedgeId();
}

int Mesh::corner_of(FaceId f, VertexId v) const {
    const auto& fv = face_vertices_[f.idx];
    for (int i = 0; i < 3; ++i)
        if (fv[i] == v) return i;
    return -1;
}

int Mesh::angle(FaceId f, int c) const {
    const FaceType t = type(f);
    if (t.colour == Colour::Green) return 2;
    const bool on_red = c == t.red_edge || c == (t.red_edge + 1) % 3;
    const bool high = level(face_vertices_[f.idx][c]) > t.level;
    if (t.colour == Colour::Red) return high ? 3 : (on_red ? 1 : 2);
    return (!on_red && high) ? 4 : 1;
}

int Mesh::uniform_valence(VertexId v) const {
    if (is_base_vertex(v)) return base_->valence(v.idx);
    return is_boundary(v) ? 4 : 6;
}

int Mesh::valence(VertexId v) const {
    const HalfedgeId start = vertex_halfedge_[v.idx];
    HalfedgeId h = start;
    int n = 0;
    do {
        ++n;
        h = ccw_rotated(h);
    } while (h.valid() && h != start);
    return is_boundary(v) ? n + 1 : n;
}

namespace {
// Capacity for `more` elements beyond the size, growing geometrically like push_back would.
template <class Vector>
void grow_for(Vector& v, std::size_t more) {
    if (v.capacity() - v.size() < more) v.reserve(std::max(2 * v.capacity(), v.size() + more));
}
}  // namespace

// The same for the face and vertex arrays (those room_ahead hands out), whose observers hear first
// that they move.
template <class Vector>
void Mesh::room_for(Vector& v, std::size_t more) {
    if (v.capacity() - v.size() >= more) return;
    announce_arrays_moving();
    grow_for(v, more);
}

void Mesh::announce_arrays_moving() const {
    for (MeshObserver* o : observers_) o->arrays_moving(*this);
}

// Geometric like the rest: a string of reservations a little larger each time (one per brush dab)
// must not copy the whole mesh each time.
void Mesh::reserve(std::size_t faces, std::size_t vertices) {
    const auto up_to = [this](auto& v, std::size_t n) { room_for(v, n > v.size() ? n - v.size() : 0); };
    up_to(face_vertices_, faces);
    up_to(face_code_, faces);
    up_to(opposite_, 3 * faces);
    up_to(insertion_position_, vertices);
    up_to(vertex_halfedge_, vertices);
    up_to(vertex_info_, vertices);
    up_to(address_, vertices);
}

std::vector<std::span<std::byte>> Mesh::room_ahead(std::size_t faces, std::size_t vertices) {
    std::vector<std::span<std::byte>> room;
    const auto ahead = [&room](auto& v, std::size_t n) {
        const std::size_t count = std::min(n, v.capacity() - v.size());
        room.push_back(std::as_writable_bytes(std::span(v.data() + v.size(), count)));
    };
    ahead(face_vertices_, faces);
    ahead(face_code_, faces);
    ahead(opposite_, 3 * faces);
    ahead(insertion_position_, vertices);
    ahead(vertex_halfedge_, vertices);
    ahead(vertex_info_, vertices);
    ahead(address_, vertices);
    return room;
}

void Mesh::add_observer(MeshObserver* o) { observers_.push_back(o); }

void Mesh::remove_observer(MeshObserver* o) { std::erase(observers_, o); }

namespace {
// The most recently freed slot, or `size` (the next slot at the end, which the caller then appends).
std::uint32_t take_slot(std::vector<std::uint32_t>& free_slots, std::size_t size) {
    if (free_slots.empty()) return static_cast<std::uint32_t>(size);
    const std::uint32_t slot = free_slots.back();
    free_slots.pop_back();
    return slot;
}
}  // namespace

VertexId Mesh::next_vertex_slot() const {
    return VertexId(free_vertices_.empty() ? static_cast<std::uint32_t>(vertex_info_.size()) : free_vertices_.back());
}

SurfacePoint Mesh::new_vertex_address(const NewVertex& added) const {
    if (added.level > kMaxLevel)
        throw std::length_error("vertex level " + std::to_string(added.level) + " is beyond the supported maximum " +
                                std::to_string(kMaxLevel));
    // Stored in the canonical of its addresses, so equal points have equal records whatever history made them.
    return added.address ? canonical(*base_, *added.address)
                         : canonical(*base_, midpoint(*base_, address(added.a), address(added.b)));
}


void Mesh::make_room(std::size_t faces_released, std::size_t faces_added, std::size_t vertices_released, bool vertex_added) {
    grow_for(free_faces_, faces_released);
    if (vertices_released > 0) grow_for(free_vertices_, vertices_released);
    const std::size_t reusable = free_faces_.size() + faces_released;
    if (faces_added > reusable) {
        const std::size_t appended_faces = faces_added - reusable;
        room_for(face_vertices_, appended_faces);
        room_for(face_code_, appended_faces);
        room_for(opposite_, 3 * appended_faces);
    }
    if (vertex_added && free_vertices_.size() + vertices_released == 0) {
        room_for(insertion_position_, 1);
        room_for(vertex_halfedge_, 1);
        room_for(vertex_info_, 1);
        room_for(address_, 1);
    }
}

VertexId Mesh::allocate_vertex(const NewVertex& added, const SurfacePoint& m) {
    const VertexId v(take_slot(free_vertices_, vertex_info_.size()));
    if (v.idx == vertex_info_.size()) {
        insertion_position_.emplace_back();
        vertex_halfedge_.emplace_back();
        vertex_info_.push_back(kDead);
        address_.emplace_back();
    }
    insertion_position_[v.idx] = added.insertion_position;
    vertex_halfedge_[v.idx] = HalfedgeId();
    vertex_info_[v.idx] = static_cast<std::uint8_t>(added.level | (added.boundary ? kBoundaryBit : 0));
    address_[v.idx] = {m.face, m.a[1], m.a[2]};
    ++vertex_count_;
    return v;
}

FaceId Mesh::allocate_face() {
    const FaceId f(take_slot(free_faces_, face_code_.size()));
    if (f.idx == face_code_.size()) {
        face_vertices_.emplace_back();
        face_code_.push_back(kDead);
        for (int i = 0; i < 3; ++i) opposite_.emplace_back();
    }
    ++face_count_;
    return f;
}

void Mesh::release_face(FaceId f) {
    face_code_[f.idx] = kDead;
    for (int i = 0; i < 3; ++i) opposite_[3 * f.idx + i] = HalfedgeId();
    free_faces_.push_back(f.idx);
    --face_count_;
}

void Mesh::release_vertex(VertexId v) {
    if (vertex_info_[v.idx] & kLimitBit) limits_.erase(v.idx);
    vertex_info_[v.idx] = kDead;
    vertex_halfedge_[v.idx] = HalfedgeId();
    free_vertices_.push_back(v.idx);
    --vertex_count_;
}

HalfedgeId Mesh::boundary_outgoing(HalfedgeId h) const {
    // Turn clockwise to the boundary, if there is one, so that ccw turns from it see the whole star.
    const HalfedgeId start = h;
    for (HalfedgeId c = cw_rotated(h); c.valid() && c != start; c = cw_rotated(c)) h = c;
    return h;
}

bool Mesh::reusable_vertex_halfedge(VertexId v, HalfedgeId h) const {
    return face_code_[h.idx / 3] != kDead && from_vertex(h) == v && (!is_boundary(v) || is_boundary(h));
}

void Mesh::set_vertex_halfedge(VertexId v, HalfedgeId outgoing) {
    vertex_halfedge_[v.idx] = is_boundary(v) ? boundary_outgoing(outgoing) : outgoing;
}

FaceList Mesh::replace_faces(std::span<const FaceId> old_faces, std::span<const NewFace> new_faces,
                             std::span<const VertexId> removed_vertices, const NewVertex* added) {
    // Halfedges are matched by their directed vertex pair packed into one integer.
    auto key = [](VertexId a, VertexId b) { return (std::uint64_t(a.idx) << 32) | b.idx; };
    // Outside halfedges that face the region, keyed by the directed edge as seen from inside.
    struct Border {
        std::uint64_t key;
        HalfedgeId outside;
    };
    InlineVector<Border, 18> border;
    // Vertices whose outgoing halfedge is in a replaced face. Any other vertex keeps its halfedge: that
    // halfedge's face, vertices and boundary status are untouched.
    struct Stale {
        VertexId v;
        HalfedgeId was;
    };
    InlineVector<Stale, 18> stale;
    // A plain loop: there are at most six faces, too few for std::find's unrolling to pay.
    auto in_old = [&](FaceId f) {
        for (FaceId g : old_faces)
            if (g == f) return true;
        return false;
    };
    for (FaceId f : old_faces) {
        const auto& fv = face_vertices_[f.idx];
        for (int i = 0; i < 3; ++i) {
            if (vertex_halfedge_[fv[i].idx] == halfedge(f, i)) {
                stale.push_back({fv[i], halfedge(f, i)});
                vertex_halfedge_[fv[i].idx] = HalfedgeId();
            }
            const HalfedgeId o = opposite_[3 * f.idx + i];
            if (o.valid() && in_old(face(o))) continue;
            border.push_back({key(fv[i], fv[(i + 1) % 3]), o});
        }
    }
    // Whatever can fail is done before the mesh changes: a replacement happens whole or not at all
    // (an undo journal relies on that).
    const std::optional<SurfacePoint> added_address = added ? std::optional(new_vertex_address(*added)) : std::nullopt;
    make_room(old_faces.size(), new_faces.size(), removed_vertices.size(), added != nullptr);
    // A failure here leaves the mesh unchanged (observers told so far heard of removals that did not happen).
    for (FaceId f : old_faces)
        for (MeshObserver* o : observers_) o->face_removed(*this, f);
    for (VertexId v : removed_vertices)
        for (MeshObserver* o : observers_) o->vertex_removed(*this, v);
    // Released last to first, so that the free list hands the slots back first to first: the first
    // new faces take the old faces' slots in order, keeping the region together in memory.
    for (auto it = old_faces.rbegin(); it != old_faces.rend(); ++it) release_face(*it);
    for (VertexId v : removed_vertices) release_vertex(v);
    // From here on the mesh has changed, so every observer hears of every addition even if another
    // fails; the first failure is rethrown once all have been told.
    std::exception_ptr failure;
    auto tell = [&](auto&& event) {
        for (MeshObserver* o : observers_) {
            try {
                event(o);
            } catch (...) {
                if (!failure) failure = std::current_exception();
            }
        }
    };
    VertexId added_vertex;
    if (added) {
        added_vertex = allocate_vertex(*added, *added_address);
        tell([&](MeshObserver* o) { o->vertex_added(*this, added_vertex, added->a, added->b); });
    }

    FaceList created;
    std::array<std::uint64_t, 18> new_keys;
    std::array<HalfedgeId, 18> new_halfedges;
    for (std::size_t k = 0; k < new_faces.size(); ++k) {
        const NewFace& nf = new_faces[k];
        const FaceId f = allocate_face();
        face_vertices_[f.idx] = nf.v;
        face_code_[f.idx] = pack(nf.type);
        created.push_back(f);
        for (int i = 0; i < 3; ++i) {
            new_keys[3 * k + i] = key(nf.v[i], nf.v[(i + 1) % 3]);
            new_halfedges[3 * k + i] = halfedge(f, i);
        }
    }
    // Pair the new halfedges with each other, then with the border. A bit per new halfedge still
    // unpaired; pairs are linked from their first member, so the partner can only come later.
    std::uint32_t unpaired = (std::uint32_t(1) << (3 * new_faces.size())) - 1;
    while (unpaired != 0) {
        const int k = std::countr_zero(unpaired);
        unpaired &= unpaired - 1;
        const std::uint64_t reverse = std::rotl(new_keys[k], 32);
        HalfedgeId match;
        for (std::uint32_t later = unpaired; later != 0; later &= later - 1) {
            const int j = std::countr_zero(later);
            if (new_keys[j] == reverse) {
                match = new_halfedges[j];
                unpaired &= ~(std::uint32_t(1) << j);
                break;
            }
        }
        if (!match.valid())
            for (const Border& e : border)
                if (e.key == new_keys[k]) {
                    match = e.outside;
                    break;
                }
        const HalfedgeId h = new_halfedges[k];
        opposite_[h.idx] = match;
        if (match.valid()) opposite_[match.idx] = h;
    }
    // New and stale vertices take their first new corner, unless a stale halfedge is valid again (its
    // slot reused with the vertex at the same corner).
    for (std::size_t k = 0; k < new_faces.size(); ++k)
        for (int i = 0; i < 3; ++i) {
            const VertexId v = new_faces[k].v[i];
            if (!vertex_halfedge_[v.idx].valid()) set_vertex_halfedge(v, new_halfedges[3 * k + i]);
        }
    for (const Stale& s : stale)
        if (reusable_vertex_halfedge(s.v, s.was)) vertex_halfedge_[s.v.idx] = s.was;
    for (FaceId f : created) tell([&](MeshObserver* o) { o->face_added(*this, f); });
    if (failure) std::rethrow_exception(failure);
    return created;
}

std::size_t Mesh::memory_bytes() const {
    auto bytes = [](const auto& vec) { return vec.size() * sizeof(vec[0]); };
    return bytes(face_vertices_) + bytes(face_code_) + bytes(opposite_) + bytes(free_faces_) + bytes(insertion_position_) +
           bytes(vertex_halfedge_) + bytes(vertex_info_) + bytes(free_vertices_) + limits_.memory_bytes() +
           base_->memory_bytes();
}

void Mesh::retag(std::shared_ptr<const BaseMesh> base, std::vector<glm::dvec3> insertion_positions) {
    base_ = std::move(base);
    insertion_position_ = std::move(insertion_positions);
    for (VertexId v : vertices())
        if (vertex_info_[v.idx] & kLimitBit) {
            limits_.erase(v.idx);
            vertex_info_[v.idx] &= static_cast<std::uint8_t>(~kLimitBit);
        }
}

}  // namespace rgb
