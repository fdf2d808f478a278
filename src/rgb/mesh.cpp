#include "rgb/mesh.h"

#include <algorithm>
#include <bit>
#include <map>
#include <stdexcept>
#include <string>

#include "rgb/loop_geometry.h"

namespace rgb {

Mesh::Mesh(std::span<const glm::dvec3> positions, std::span<const Triangle> triangles) {
    const auto nv = static_cast<std::uint32_t>(positions.size());
    if (nv > 0xffffu * 0x10000u) throw std::invalid_argument("too many vertices");
    insertion_position_.assign(positions.begin(), positions.end());
    vertex_halfedge_.assign(nv, HalfedgeId());
    vertex_level_.assign(nv, 0);
    vertex_boundary_.assign(nv, 0);
    vertex_alive_.assign(nv, 1);
    limit_slot_.assign(nv, kNoLimit);
    vertex_count_ = nv;

    const auto nf = triangles.size();
    face_vertices_.resize(nf);
    face_type_.assign(nf, FaceType{});
    opposite_.assign(3 * nf, HalfedgeId());
    face_alive_.assign(nf, 1);
    face_count_ = nf;

    // Directed edge -> halfedge, to pair opposites and reject non-manifold or inconsistent input.
    std::map<std::pair<std::uint32_t, std::uint32_t>, HalfedgeId> directed;
    std::vector<int> incident(nv, 0);
    for (std::size_t f = 0; f < nf; ++f) {
        const Triangle& t = triangles[f];
        for (int i = 0; i < 3; ++i) {
            if (t[i] >= nv) throw std::invalid_argument("triangle " + std::to_string(f) + " uses missing vertex " + std::to_string(t[i]));
            face_vertices_[f][i] = VertexId(t[i]);
            ++incident[t[i]];
        }
        if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0])
            throw std::invalid_argument("triangle " + std::to_string(f) + " repeats a vertex");
        for (int i = 0; i < 3; ++i) {
            const HalfedgeId h = halfedge(FaceId(static_cast<std::uint32_t>(f)), i);
            auto [it, inserted] = directed.emplace(std::make_pair(t[i], t[(i + 1) % 3]), h);
            if (!inserted)
                throw std::invalid_argument("edge " + std::to_string(t[i]) + "-" + std::to_string(t[(i + 1) % 3]) +
                                            " is used twice in the same direction (non-manifold or inconsistent orientation)");
        }
    }
    for (const auto& [key, h] : directed) {
        auto it = directed.find({key.second, key.first});
        if (it != directed.end()) opposite_[h.idx] = it->second;
    }
    for (const auto& [key, h] : directed) {
        const VertexId v(key.first);
        if (!vertex_halfedge_[v.idx].valid()) update_vertex_halfedge(v, h);
    }
    base_valence_.assign(nv, 0);
    for (std::uint32_t v = 0; v < nv; ++v) {
        if (!vertex_halfedge_[v].valid()) throw std::invalid_argument("vertex " + std::to_string(v) + " is used by no triangle");
        // A vertex whose star does not close up or reach every incident face is non-manifold.
        int fan = 0;
        HalfedgeId h = vertex_halfedge_[v];
        do {
            ++fan;
            h = ccw_rotated(h);
        } while (h.valid() && h != vertex_halfedge_[v]);
        if (fan != incident[v]) throw std::invalid_argument("vertex " + std::to_string(v) + " is non-manifold (bow-tie)");
        vertex_boundary_[v] = is_boundary(vertex_halfedge_[v]) ? 1 : 0;
        base_valence_[v] = static_cast<std::uint16_t>(valence(VertexId(v)));
    }
    for (std::uint32_t v = 0; v < nv; ++v) try_limit_position(*this, VertexId(v));
}

int Mesh::max_vertex_level() const {
    int m = 0;
    for (VertexId v : vertices()) m = std::max(m, level(v));
    return m;
}

HalfedgeId Mesh::find_halfedge(VertexId a, VertexId b) const {
    const HalfedgeId start = vertex_halfedge_[a.idx];
    HalfedgeId h = start;
    do {
        if (to_vertex(h) == b) return h;
        h = ccw_rotated(h);
    } while (h.valid() && h != start);
    return HalfedgeId();
}

HalfedgeId Mesh::find_edge(VertexId a, VertexId b) const {
    HalfedgeId h = find_halfedge(a, b);
    return h.valid() ? h : find_halfedge(b, a);
}

int Mesh::corner_of(FaceId f, VertexId v) const {
    const auto& fv = face_vertices_[f.idx];
    for (int i = 0; i < 3; ++i)
        if (fv[i] == v) return i;
    return -1;
}

EdgeType Mesh::edge_type(HalfedgeId h) const {
    const FaceId f = face(h);
    const FaceType& t = face_type_[f.idx];
    const int i = corner(h);
    if (t.colour == Colour::Green) return {Colour::Green, t.level};
    if (i == t.red_edge) return {Colour::Red, t.level};
    if (t.colour == Colour::Blue) return {Colour::Green, t.level + 1};
    // Red: the half of the split edge touches the top vertex (the one of level l+1).
    const bool touches_top = level(from_vertex(h)) > t.level || level(to_vertex(h)) > t.level;
    return {Colour::Green, touches_top ? t.level + 1 : t.level};
}

int Mesh::angle(FaceId f, int c) const {
    const FaceType& t = face_type_[f.idx];
    if (t.colour == Colour::Green) return 2;
    const bool on_red = c == t.red_edge || c == (t.red_edge + 1) % 3;
    const bool high = level(face_vertices_[f.idx][c]) > t.level;
    if (t.colour == Colour::Red) return high ? 3 : (on_red ? 1 : 2);
    return (!on_red && high) ? 4 : 1;
}

std::optional<glm::dvec3> Mesh::limit_position(VertexId v) const {
    const std::uint32_t s = limit_slot_[v.idx];
    if (s == kNoLimit) return std::nullopt;
    return limit_pool_[s];
}

int Mesh::uniform_valence(VertexId v) const {
    if (v.idx < base_valence_.size()) return base_valence_[v.idx];
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

void Mesh::reserve(std::size_t faces, std::size_t vertices) {
    face_vertices_.reserve(faces);
    face_type_.reserve(faces);
    opposite_.reserve(3 * faces);
    face_alive_.reserve(faces);
    insertion_position_.reserve(vertices);
    vertex_halfedge_.reserve(vertices);
    vertex_level_.reserve(vertices);
    vertex_boundary_.reserve(vertices);
    vertex_alive_.reserve(vertices);
    limit_slot_.reserve(vertices);
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

VertexId Mesh::add_vertex(int lvl, const glm::dvec3& p, bool boundary, VertexId a, VertexId b) {
    const VertexId v(take_slot(free_vertices_, vertex_alive_.size()));
    if (v.idx == vertex_alive_.size()) {
        insertion_position_.emplace_back();
        vertex_halfedge_.emplace_back();
        vertex_level_.push_back(0);
        vertex_boundary_.push_back(0);
        vertex_alive_.push_back(0);
        limit_slot_.push_back(kNoLimit);
    }
    insertion_position_[v.idx] = p;
    vertex_halfedge_[v.idx] = HalfedgeId();
    vertex_level_[v.idx] = static_cast<std::uint8_t>(lvl);
    vertex_boundary_[v.idx] = boundary ? 1 : 0;
    vertex_alive_[v.idx] = 1;
    limit_slot_[v.idx] = kNoLimit;
    ++vertex_count_;
    for (MeshObserver* o : observers_) o->vertex_added(*this, v, a, b);
    return v;
}

void Mesh::set_limit_position(VertexId v, const glm::dvec3& p) const {
    if (limit_slot_[v.idx] != kNoLimit) return;
    const std::uint32_t s = take_slot(free_limit_slots_, limit_pool_.size());
    if (s == limit_pool_.size()) limit_pool_.push_back(p);
    else limit_pool_[s] = p;
    limit_slot_[v.idx] = s;
}

FaceId Mesh::allocate_face() {
    const FaceId f(take_slot(free_faces_, face_alive_.size()));
    if (f.idx == face_alive_.size()) {
        face_vertices_.emplace_back();
        face_type_.emplace_back();
        face_alive_.push_back(0);
        for (int i = 0; i < 3; ++i) opposite_.emplace_back();
    }
    face_alive_[f.idx] = 1;
    ++face_count_;
    return f;
}

void Mesh::release_face(FaceId f) {
    face_alive_[f.idx] = 0;
    for (int i = 0; i < 3; ++i) opposite_[3 * f.idx + i] = HalfedgeId();
    free_faces_.push_back(f.idx);
    --face_count_;
}

void Mesh::release_vertex(VertexId v) {
    vertex_alive_[v.idx] = 0;
    if (limit_slot_[v.idx] != kNoLimit) free_limit_slots_.push_back(limit_slot_[v.idx]);
    limit_slot_[v.idx] = kNoLimit;
    vertex_halfedge_[v.idx] = HalfedgeId();
    free_vertices_.push_back(v.idx);
    --vertex_count_;
}

void Mesh::update_vertex_halfedge(VertexId v, HalfedgeId h) { vertex_halfedge_[v.idx] = boundary_outgoing(h); }

HalfedgeId Mesh::boundary_outgoing(HalfedgeId h) const {
    // Turn clockwise to the boundary, if there is one, so that ccw turns from it see the whole star.
    const HalfedgeId start = h;
    for (HalfedgeId c = cw_rotated(h); c.valid() && c != start; c = cw_rotated(c)) h = c;
    return h;
}

bool Mesh::reusable_vertex_halfedge(VertexId v, HalfedgeId h) const {
    return face_alive_[h.idx / 3] && from_vertex(h) == v && (!vertex_boundary_[v.idx] || is_boundary(h));
}

void Mesh::set_vertex_halfedge(VertexId v, HalfedgeId outgoing) {
    vertex_halfedge_[v.idx] = vertex_boundary_[v.idx] ? boundary_outgoing(outgoing) : outgoing;
}

FaceList Mesh::replace_faces(std::span<const FaceId> old_faces, std::span<const NewFace> new_faces,
                             std::span<const VertexId> removed_vertices) {
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
    for (FaceId f : old_faces)
        for (MeshObserver* o : observers_) o->face_removed(*this, f);
    // Released last to first, so that the free list hands the slots back first to first: the first
    // new faces take the old faces' slots in order, keeping the region together in memory.
    for (auto it = old_faces.rbegin(); it != old_faces.rend(); ++it) release_face(*it);
    for (VertexId v : removed_vertices) {
        for (MeshObserver* o : observers_) o->vertex_removed(*this, v);
        release_vertex(v);
    }

    FaceList created;
    std::array<std::uint64_t, 18> new_keys;
    std::array<HalfedgeId, 18> new_halfedges;
    for (std::size_t k = 0; k < new_faces.size(); ++k) {
        const NewFace& nf = new_faces[k];
        const FaceId f = allocate_face();
        face_vertices_[f.idx] = nf.v;
        face_type_[f.idx] = nf.type;
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
    for (FaceId f : created)
        for (MeshObserver* o : observers_) o->face_added(*this, f);
    return created;
}

std::size_t Mesh::memory_bytes() const {
    auto bytes = [](const auto& vec) { return vec.size() * sizeof(vec[0]); };
    return bytes(face_vertices_) + bytes(face_type_) + bytes(opposite_) + bytes(face_alive_) + bytes(free_faces_) +
           bytes(insertion_position_) + bytes(vertex_halfedge_) + bytes(vertex_level_) + bytes(vertex_boundary_) +
           bytes(vertex_alive_) + bytes(limit_slot_) + bytes(free_vertices_) + bytes(limit_pool_) +
           bytes(free_limit_slots_) + bytes(base_valence_);
}

}  // namespace rgb
