#include "rgb/state.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "rgb/face_location.h"
#include "rgb/invariants.h"
#include "rgb/loop_geometry.h"
#include "rgb/loop_rules.h"
#include "rgb/mesh.h"
#include "rgb/vertex_rules.h"

namespace rgb {

MeshState capture_state(const Mesh& mesh) {
    MeshState s;
    s.base_positions.assign(mesh.base().positions().begin(), mesh.base().positions().end());
    s.base_triangles.assign(mesh.base().faces().begin(), mesh.base().faces().end());
    s.sharp_features = mesh.base().sharp_features();
    std::vector<std::uint32_t> index(mesh.vertex_capacity(), BaseMesh::kNone);
    s.vertices.reserve(mesh.num_vertices());
    for (VertexId v : mesh.vertices()) {
        index[v.idx] = static_cast<std::uint32_t>(s.vertices.size());
        s.vertices.push_back(mesh.address(v));
    }
    s.faces.reserve(mesh.num_faces());
    for (FaceId f : mesh.faces()) {
        const auto& c = mesh.face_vertices(f);
        s.faces.push_back({index[c[0].idx], index[c[1].idx], index[c[2].idx]});
    }
    return s;
}

namespace {

[[noreturn]] void fail(const std::string& what) { throw std::invalid_argument("invalid RGB state: " + what); }

struct AddressKey {
    std::uint32_t face, a0, a1;
    int level;
    friend bool operator==(const AddressKey&, const AddressKey&) = default;
};
struct AddressHash {
    std::size_t operator()(const AddressKey& k) const noexcept {
        return (std::size_t(k.face) * 0x9e3779b97f4a7c15ull) ^ (std::size_t(k.a0) << 21) ^ (std::size_t(k.a1) << 7) ^
               std::size_t(k.level);
    }
};

}  // namespace

Mesh with_sharp_features(const Mesh& mesh, const SharpFeatures& features) {
    // Checked up front, so that a bad tag is reported as such and not as an invalid state.
    const BaseMesh check(mesh.base().positions(), mesh.base().faces(), features);
    MeshState state = capture_state(mesh);
    state.sharp_features = features;
    return restore_state(state);
}

// Rebuilt through the same members the operators use, so the restored mesh is indistinguishable from
// one the operators made: faces typed by their place in the hierarchy, insertion positions by the
// split formula level by level.
Mesh restore_state(const MeshState& s) {
    std::shared_ptr<const BaseMesh> base_mesh;
    try {
        base_mesh = std::make_shared<const BaseMesh>(s.base_positions, s.base_triangles, s.sharp_features);
    } catch (const std::invalid_argument& e) {
        fail(std::string("base mesh: ") + e.what());
    }
    const BaseMesh& base = *base_mesh;
    Mesh m(base_mesh);
    const std::size_t n0 = base.num_vertices(), nv = s.vertices.size();
    if (nv < n0) fail("fewer vertices than the base mesh has");
    // Vertices: addresses checked and made canonical, so equal points compare equal.
    std::unordered_map<AddressKey, std::uint32_t, AddressHash> by_address;
    by_address.reserve(nv);
    std::vector<SurfacePoint> points(nv);
    for (std::uint32_t i = 0; i < nv; ++i) {
        SurfacePoint p = s.vertices[i];
        const std::string name = "vertex " + std::to_string(i);
        if (p.face >= base.num_faces() || p.level < 0 || p.level > kMaxLevel ||
            std::uint64_t(p.a[0]) + p.a[1] + p.a[2] != (std::uint64_t(1) << p.level) || reduced(p) != p)
            fail(name + " has an invalid address");
        if ((i < n0) != (p.level == 0) || (i < n0 && base_vertex(base, p) != i))
            fail(name + ": the base vertices come first, in base order, and only they have level 0");
        p = canonical(base, p);
        if (!by_address.emplace(AddressKey{p.face, p.a[0], p.a[1], p.level}, i).second) fail(name + " repeats another vertex");
        points[i] = p;
    }
    m.insertion_position_.resize(nv);
    m.vertex_halfedge_.assign(nv, HalfedgeId());
    m.vertex_info_.resize(nv);
    m.address_.resize(nv);
    for (std::uint32_t i = 0; i < nv; ++i) {
        m.vertex_info_[i] = static_cast<std::uint8_t>(points[i].level | (is_boundary(base, points[i]) ? Mesh::kBoundaryBit : 0));
        m.address_[i] = {points[i].face, points[i].a[1], points[i].a[2]};
    }
    m.vertex_count_ = nv;
    // Faces: their colour, level and red edge follow from where their corners are (spec §1.3).
    const std::size_t nf = s.faces.size();
    m.face_vertices_.resize(nf);
    m.face_code_.assign(nf, Mesh::kDead);
    m.opposite_.assign(3 * nf, HalfedgeId());
    for (std::uint32_t f = 0; f < nf; ++f) {
        for (int c = 0; c < 3; ++c) {
            if (s.faces[f][c] >= nv) fail("face " + std::to_string(f) + " uses a missing vertex");
            m.face_vertices_[f][c] = VertexId(s.faces[f][c]);
        }
        m.face_code_[f] = 0;  // live; typed below, once adjacency exists
    }
    m.face_count_ = nf;
    std::vector<std::pair<std::uint64_t, HalfedgeId>> directed;
    directed.reserve(3 * nf);
    for (std::uint32_t f = 0; f < nf; ++f) {
        const Triangle& t = s.faces[f];
        if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) fail("face " + std::to_string(f) + " repeats a vertex");
        for (int c = 0; c < 3; ++c)
            directed.emplace_back((std::uint64_t(t[c]) << 32) | t[(c + 1) % 3], Mesh::halfedge(FaceId(f), c));
    }
    std::sort(directed.begin(), directed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (std::size_t i = 1; i < directed.size(); ++i)
        if (directed[i].first == directed[i - 1].first)
            fail("face " + std::to_string(Mesh::face(directed[i].second).idx) + " repeats a directed edge (non-manifold)");
    for (const auto& [k, h] : directed) {
        const std::uint64_t reverse = (k << 32) | (k >> 32);
        const auto it = std::lower_bound(directed.begin(), directed.end(), reverse,
                                         [](const auto& e, std::uint64_t x) { return e.first < x; });
        if (it != directed.end() && it->first == reverse) m.opposite_[h.idx] = it->second;
    }
    for (const auto& [k, h] : directed) {
        const VertexId from(static_cast<std::uint32_t>(k >> 32));
        if (!m.vertex_halfedge_[from.idx].valid()) m.set_vertex_halfedge(from, h);
    }
    for (std::uint32_t v = 0; v < nv; ++v)
        if (!m.vertex_halfedge_[v].valid()) fail("vertex " + std::to_string(v) + " is used by no face");
    for (std::uint32_t f = 0; f < nf; ++f) {
        const FaceId face(f);
        int level = 0;
        for (VertexId v : m.face_vertices(face)) level = std::max(level, m.level(v));
        // A face's level is its finest corner's for a green face, one less for a red or blue one;
        // try green first, as its parent triangle is the face itself.
        FaceType type;
        bool typed = false;
        try {
            const std::uint32_t b = base_face_of(m, face);
            for (int l : {level, level - 1}) {
                if (l < 0) continue;
                m.face_code_[f] = Mesh::pack(FaceType{Colour::Green, static_cast<std::uint8_t>(l), 0});
                const auto parent = parent_triangle(m, face, b);
                int corners = 0, off_corner = -1;
                for (int c = 0; c < 3; ++c) {
                    const auto p = in_face(base, m.address(m.face_vertices(face)[c]), b);
                    const bool is_corner = p && std::find(parent.begin(), parent.end(), *p) != parent.end();
                    corners += is_corner;
                    if (!is_corner) off_corner = c;
                }
                if (l == level && corners == 3) {
                    type = {Colour::Green, static_cast<std::uint8_t>(l), 0};
                } else if (l == level - 1 && corners == 2) {
                    // Red: the red edge runs from the top (the midpoint) to the far corner, through
                    // the parent's interior: of the top's two edges, the one that is not half of a
                    // parent edge, i.e. whose other end is not adjacent to the top along the parent.
                    const VertexId top = m.face_vertices(face)[off_corner];
                    const PointStencil st = parent_stencil(base, m.address(top));
                    const int next = (off_corner + 1) % 3;
                    const auto n = in_face(base, m.address(m.face_vertices(face)[next]), b);
                    const bool next_on_parent_edge = n && (in_face(base, st.ends[0], b) == n || in_face(base, st.ends[1], b) == n);
                    type = {Colour::Red, static_cast<std::uint8_t>(l),
                            static_cast<std::uint8_t>(next_on_parent_edge ? (off_corner + 2) % 3 : off_corner)};
                } else if (l == level - 1 && corners == 1) {
                    // Blue: the red edge joins the low corner and the midpoint of the opposite parent edge.
                    int low = 0;
                    for (int c = 0; c < 3; ++c)
                        if (m.level(m.face_vertices(face)[c]) <= l) low = c;
                    const VertexId after = m.face_vertices(face)[(low + 1) % 3];
                    const PointStencil st = parent_stencil(base, m.address(after));
                    const auto lowp = in_face(base, m.address(m.face_vertices(face)[low]), b);
                    const bool after_touches_low = lowp && (in_face(base, st.ends[0], b) == lowp || in_face(base, st.ends[1], b) == lowp);
                    type = {Colour::Blue, static_cast<std::uint8_t>(l),
                            static_cast<std::uint8_t>(after_touches_low ? (low + 2) % 3 : low)};
                } else {
                    continue;
                }
                typed = true;
                break;
            }
        } catch (const std::logic_error&) {
            typed = false;
        }
        if (!typed) fail("face " + std::to_string(f) + " is no piece of a triangle of the hierarchy");
        m.face_code_[f] = Mesh::pack(type);
    }
    // Insertion positions, coarsest first, by the split formula on the (present) parent stencil.
    std::vector<std::uint32_t> order(nv);
    for (std::uint32_t i = 0; i < nv; ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return points[a].level < points[b].level; });
    for (std::uint32_t i = 0; i < n0; ++i) m.insertion_position_[i] = base.position(i);
    auto vertex_at = [&](const SurfacePoint& p) {
        const SurfacePoint c = canonical(base, p);
        const auto it = by_address.find({c.face, c.a[0], c.a[1], c.level});
        if (it == by_address.end()) fail("a vertex's parent triangles are not all present");
        return VertexId(it->second);
    };
    for (std::uint32_t i : order) {
        if (i < n0) continue;
        const PointStencil st = parent_stencil(base, points[i]);
        const int l = points[i].level - 1;
        const glm::dvec3 a = control_point(m, vertex_at(st.ends[0]), l), b = control_point(m, vertex_at(st.ends[1]), l);
        const bool midpoint = st.boundary || (base.has_sharp_features() && inserted_at_midpoint(base, points[i]));
        m.insertion_position_[i] = midpoint ? boundary_edge_point(a, b)
                                               : interior_edge_point(a, b, control_point(m, vertex_at(st.opposite[0]), l),
                                                                     control_point(m, vertex_at(st.opposite[1]), l));
    }
    if (const InvariantReport report = check_invariants(m, 1); !report.ok()) fail(report.violations.front());
    if (const InvariantReport report = check_normal_form(m, 1); !report.ok()) fail(report.violations.front());
    return m;
}

}  // namespace rgb
