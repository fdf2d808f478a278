#include "rgb/state.h"

#include <stdexcept>
#include <string>
#include <unordered_map>

#include "rgb/invariants.h"
#include "rgb/mesh.h"

namespace rgb {

MeshState capture_state(const Mesh& mesh) {
    MeshState s;
    s.vertices.resize(mesh.vertex_capacity());
    for (std::uint32_t i = 0; i < s.vertices.size(); ++i) {
        const VertexId v(i);
        VertexState& vs = s.vertices[i];
        vs.alive = mesh.is_live(v);
        if (!vs.alive) continue;
        vs.level = mesh.level(v);
        vs.boundary = mesh.is_boundary(v);
        vs.insertion_position = mesh.insertion_position(v);
        vs.limit = mesh.limit_position(v);
    }
    s.faces.resize(mesh.face_capacity());
    for (std::uint32_t i = 0; i < s.faces.size(); ++i) {
        const FaceId f(i);
        FaceState& fs = s.faces[i];
        fs.alive = mesh.is_live(f);
        if (!fs.alive) continue;
        for (int c = 0; c < 3; ++c) fs.v[c] = mesh.face_vertices(f)[c].idx;
        fs.type = mesh.type(f);
    }
    s.base_valence = mesh.base_valence_;
    s.free_vertices = mesh.free_vertices_;
    s.free_faces = mesh.free_faces_;
    return s;
}

namespace {
[[noreturn]] void fail(const std::string& what) { throw std::invalid_argument("invalid RGB state: " + what); }
}  // namespace

Mesh restore_state(const MeshState& s) {
    Mesh m;
    const std::size_t nv = s.vertices.size(), nf = s.faces.size();
    if (s.base_valence.size() > nv) fail("more base vertices than vertices");
    m.insertion_position_.resize(nv);
    m.vertex_halfedge_.assign(nv, HalfedgeId());
    m.vertex_level_.assign(nv, 0);
    m.vertex_boundary_.assign(nv, 0);
    m.vertex_alive_.assign(nv, 0);
    m.limit_slot_.assign(nv, Mesh::kNoLimit);
    for (std::uint32_t i = 0; i < nv; ++i) {
        const VertexState& vs = s.vertices[i];
        if (!vs.alive) {
            if (i < s.base_valence.size()) fail("base vertex " + std::to_string(i) + " is missing");
            continue;
        }
        if (vs.level < 0 || vs.level > 254) fail("vertex " + std::to_string(i) + " has level " + std::to_string(vs.level));
        if ((vs.level == 0) != (i < s.base_valence.size()))
            fail("vertex " + std::to_string(i) + ": level 0 exactly for the base vertices");
        m.vertex_alive_[i] = 1;
        m.vertex_level_[i] = static_cast<std::uint8_t>(vs.level);
        m.vertex_boundary_[i] = vs.boundary ? 1 : 0;
        m.insertion_position_[i] = vs.insertion_position;
        if (vs.limit) m.set_limit_position(VertexId(i), *vs.limit);
        ++m.vertex_count_;
    }
    m.face_vertices_.resize(nf);
    m.face_type_.resize(nf);
    m.opposite_.assign(3 * nf, HalfedgeId());
    m.face_alive_.assign(nf, 0);
    std::unordered_map<std::uint64_t, HalfedgeId> directed;
    auto key = [](std::uint32_t a, std::uint32_t b) { return (std::uint64_t(a) << 32) | b; };
    for (std::uint32_t f = 0; f < nf; ++f) {
        const FaceState& fs = s.faces[f];
        if (!fs.alive) continue;
        const std::string name = "face " + std::to_string(f);
        if (fs.type.colour > Colour::Blue || fs.type.red_edge > 2) fail(name + " has an unknown type");
        for (int c = 0; c < 3; ++c) {
            if (fs.v[c] >= nv || !s.vertices[fs.v[c]].alive) fail(name + " uses a missing vertex");
            m.face_vertices_[f][c] = VertexId(fs.v[c]);
        }
        if (fs.v[0] == fs.v[1] || fs.v[1] == fs.v[2] || fs.v[2] == fs.v[0]) fail(name + " repeats a vertex");
        m.face_type_[f] = fs.type;
        m.face_alive_[f] = 1;
        ++m.face_count_;
        for (int c = 0; c < 3; ++c)
            if (!directed.emplace(key(fs.v[c], fs.v[(c + 1) % 3]), Mesh::halfedge(FaceId(f), c)).second)
                fail(name + " repeats a directed edge (non-manifold)");
    }
    for (const auto& [k, h] : directed) {
        auto it = directed.find((k << 32) | (k >> 32));
        if (it != directed.end()) m.opposite_[h.idx] = it->second;
    }
    // Only once every opposite is known can a boundary vertex find its boundary halfedge.
    for (const auto& [k, h] : directed) {
        const VertexId from(static_cast<std::uint32_t>(k >> 32));
        if (!m.vertex_halfedge_[from.idx].valid()) m.update_vertex_halfedge(from, h);
    }
    for (VertexId v : m.vertices())
        if (!m.vertex_halfedge_[v.idx].valid()) fail("vertex " + std::to_string(v.idx) + " is used by no face");
    m.base_valence_ = s.base_valence;
    auto check_free = [](const std::vector<std::uint32_t>& list, std::size_t n, auto alive, const char* what) {
        std::vector<std::uint8_t> seen(n, 0);
        for (std::uint32_t i : list) {
            if (i >= n || alive(i) || seen[i]) fail(std::string("bad free ") + what + " slot " + std::to_string(i));
            seen[i] = 1;
        }
        std::size_t dead = 0;
        for (std::size_t i = 0; i < n; ++i) dead += !alive(static_cast<std::uint32_t>(i));
        if (dead != list.size()) fail(std::string("free ") + what + " list does not cover the dead slots");
    };
    check_free(s.free_vertices, nv, [&](std::uint32_t i) { return s.vertices[i].alive; }, "vertex");
    check_free(s.free_faces, nf, [&](std::uint32_t i) { return s.faces[i].alive; }, "face");
    m.free_vertices_ = s.free_vertices;
    m.free_faces_ = s.free_faces;
    const InvariantReport report = check_invariants(m, 1);
    if (!report.ok()) fail(report.violations.front());
    return m;
}

}  // namespace rgb
