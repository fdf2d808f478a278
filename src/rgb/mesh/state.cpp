#include "rgb/mesh/state.h"

#include <algorithm>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>

#include "rgb/mesh/address_index.h"
#include "rgb/mesh/face_location.h"
#include "rgb/mesh/invariants.h"
#include "rgb/mesh/mesh.h"
#include "rgb/mesh/outgoing_halfedges.h"
#include "rgb/support/parallel.h"

namespace rgb {

MeshState capture_state(const Mesh& mesh) {
    MeshState s;
    s.base_positions.assign(mesh.base().positions().begin(), mesh.base().positions().end());
    s.base_triangles.assign(mesh.base().faces().begin(), mesh.base().faces().end());
    s.sharp_features = mesh.base().sharp_features();
    s.detail = mesh.base().shared_detail();
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

void invalid_state(const std::string& what) { throw std::invalid_argument("invalid RGB state: " + what); }

namespace {

[[noreturn]] void fail(const std::string& what) { invalid_state(what); }

// The address of vertex i if it is a valid one for its place in the state, else why not.
std::optional<std::string> address_problem(const BaseMesh& base, std::uint32_t i, const SurfacePoint& p) {
    // Named only for a report: this runs for every vertex of every file loaded.
    auto name = [i] { return "vertex " + std::to_string(i); };
    if (p.face >= base.num_faces() || p.level < 0 || p.level > kMaxLevel ||
        std::uint64_t(p.a[0]) + p.a[1] + p.a[2] != (std::uint64_t(1) << p.level) || reduced(p) != p)
        return name() + " has an invalid address";
    const bool base_slot = i < base.num_vertices();
    if (base_slot != (p.level == 0) || (base_slot && base_vertex(base, p) != i))
        return name() + ": the base vertices come first, in base order, and only they have level 0";
    return std::nullopt;
}

// Spec §1.3: a green face of level l is a triangle of Σl; a red one has two corners of the triangle of
// Σl it lies in and, as its top, the midpoint of the edge between them; a blue one has one corner.
// The level is the finest corner's for a green face, one less otherwise. Nothing when the corners fit
// no such place. The red edge of a red face runs from the top through the triangle's interior to its
// far corner; that of a blue face joins the coarse corner and the midpoint of the opposite edge.
std::optional<FaceType> type_from_corners(const Mesh& m, FaceId face) {
    FaceCorners place;
    try {
        place = face_corners(m, face);
    } catch (const std::logic_error&) {
        return std::nullopt;
    }
    const int top = place.top;
    // Whether the edge of Σ(k-1) through point q (numerators over 2^(l+1), of level k >= 1) ends at r.
    auto on_parent_edge_end = [](const std::array<std::uint32_t, 3>& q, int shift, const std::array<std::uint32_t, 3>& r) {
        // At its own level q has exactly one even numerator, opposite the edge's direction.
        int e = 0;
        for (int c = 0; c < 3; ++c)
            if ((q[c] >> shift) % 2 == 0) e = c;
        const int i = (e + 1) % 3, j = (e + 2) % 3;
        // Both numerators along the edge are odd at q's level, so neither end goes below zero.
        const std::uint32_t step = std::uint32_t(1) << shift;
        std::array<std::uint32_t, 3> towards_i = q, towards_j = q;
        towards_i[i] += step;
        towards_i[j] -= step;
        towards_j[i] -= step;
        towards_j[j] += step;
        return r == towards_i || r == towards_j;
    };
    for (int l : {top, top - 1}) {
        if (l < 0) continue;
        const CornerNumerators parent = parent_corners(place, l), corners = corners_at(place, l + 1);
        int count = 0, off_corner = -1;
        for (int c = 0; c < 3; ++c) {
            const bool is_corner = std::find(parent.begin(), parent.end(), corners[c]) != parent.end();
            count += is_corner;
            if (!is_corner) off_corner = c;
        }
        const auto level = static_cast<std::uint8_t>(l);
        if (l == top && count == 3) return FaceType{Colour::Green, level, 0};
        if (l != top - 1) continue;
        if (count == 2) {
            // The top is the finest corner, at level l + 1.
            const int next = (off_corner + 1) % 3;
            const bool next_on_parent_edge = on_parent_edge_end(corners[off_corner], 0, corners[next]);
            return FaceType{Colour::Red, level, static_cast<std::uint8_t>(next_on_parent_edge ? (off_corner + 2) % 3 : off_corner)};
        }
        if (count == 1) {
            int low = 0;
            for (int c = 0; c < 3; ++c)
                if (m.level(m.face_vertices(face)[c]) <= l) low = c;
            const int after = (low + 1) % 3;
            const int after_level = m.level(m.face_vertices(face)[after]);
            if (after_level == 0) return std::nullopt;  // a base vertex sits on no parent edge
            const bool after_touches_low = on_parent_edge_end(corners[after], l + 1 - after_level, corners[low]);
            return FaceType{Colour::Blue, level, static_cast<std::uint8_t>(after_touches_low ? (low + 2) % 3 : low)};
        }
    }
    return std::nullopt;
}

// Vertices: addresses checked and made canonical (points), so that equal points compare equal, in
// parallel blocks that stop at their first problem. The first problem in vertex order is reported,
// a bad address or a repeat of an earlier vertex.
AddressIndex checked_addresses(const BaseMesh& base, const std::vector<SurfacePoint>& vertices, std::vector<SurfacePoint>& points) {
    const std::size_t nv = vertices.size();
    std::vector<std::uint32_t> first_problem(parallel_blocks(nv, 1 << 15), BaseMesh::kNone);
    parallel_blocks_for(nv, first_problem.size(), [&](std::size_t b, std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            const auto v = static_cast<std::uint32_t>(i);
            if (address_problem(base, v, vertices[v])) {
                first_problem[b] = v;
                return;
            }
            points[v] = canonical(base, vertices[v]);
        }
    });
    const auto problem = std::find_if(first_problem.begin(), first_problem.end(), [](std::uint32_t v) { return v != BaseMesh::kNone; });
    const std::uint32_t checked = problem == first_problem.end() ? static_cast<std::uint32_t>(nv) : *problem;
    AddressIndex index(std::span<const SurfacePoint>(points).first(checked), base.num_faces());
    if (const auto repeat = index.first_repeat()) fail("vertex " + std::to_string(*repeat) + " repeats another vertex");
    if (checked < nv) fail(*address_problem(base, checked, vertices[checked]));
    return index;
}

// The faces checked, and their adjacency: each halfedge's opposite (3f+i: corner i of face f), and
// the outgoing halfedges grouped by vertex for the vertices' own halfedges. The first face with a
// missing vertex is reported, else the first that repeats a vertex (each parallel block finds its
// own first ones), else the first repeated directed edge.
OutgoingHalfedges matched_halfedges(const std::vector<Triangle>& faces, std::size_t nv, std::vector<HalfedgeId>& opposite) {
    const std::size_t nf = faces.size();
    const std::size_t blocks = parallel_blocks(nf, 1 << 16);
    std::vector<std::uint32_t> missing(blocks, BaseMesh::kNone), repeating(blocks, BaseMesh::kNone);
    parallel_blocks_for(nf, blocks, [&](std::size_t b, std::size_t begin, std::size_t end) {
        for (std::size_t f = begin; f < end; ++f) {
            const Triangle& t = faces[f];
            if (missing[b] == BaseMesh::kNone && (t[0] >= nv || t[1] >= nv || t[2] >= nv)) missing[b] = static_cast<std::uint32_t>(f);
            if (repeating[b] == BaseMesh::kNone && (t[0] == t[1] || t[1] == t[2] || t[2] == t[0])) repeating[b] = static_cast<std::uint32_t>(f);
        }
    });
    for (std::uint32_t f : missing)
        if (f != BaseMesh::kNone) fail("face " + std::to_string(f) + " uses a missing vertex");
    for (std::uint32_t f : repeating)
        if (f != BaseMesh::kNone) fail("face " + std::to_string(f) + " repeats a vertex");
    OutgoingHalfedges out = outgoing_halfedges(faces, nv);
    if (out.repeating) fail("face " + std::to_string(out.repeating->face) + " repeats a directed edge (non-manifold)");
    opposite.assign(3 * nf, HalfedgeId());
    pair_halfedges(out, nv, [&](std::uint32_t h, std::uint32_t reverse) { opposite[h] = HalfedgeId(reverse); });
    return out;
}

}  // namespace

std::shared_ptr<const BaseMesh> restored_base_mesh(const MeshState& s) {
    try {
        return std::make_shared<const BaseMesh>(s.base_positions, s.base_triangles, s.sharp_features, s.detail);
    } catch (const std::invalid_argument& e) {
        fail(std::string("base mesh: ") + e.what());
    }
}

// Rebuilt into the members the operators use, so the restored mesh is indistinguishable from one the
// operators made: faces typed by their place in the hierarchy. Every pass is linear (a table of
// addresses, halfedges grouped by vertex), and the per-face ones run in parallel.
RestoredTopology restore_topology(const MeshState& s, std::shared_ptr<const BaseMesh> base_mesh, const ProgressSpan& progress) {
    const BaseMesh& base = *base_mesh;
    Mesh m(base_mesh);
    progress.reach(kRestoreBaseBuilt);
    const std::size_t n0 = base.num_vertices(), nv = s.vertices.size(), nf = s.faces.size();
    if (nv < n0) fail("fewer vertices than the base mesh has");
    // Vertices and faces are checked and stored side by side (they meet only in the vertices'
    // halfedges below); a problem with the vertices is reported first, as in a plain sequence.
    std::vector<SurfacePoint> points(nv);
    std::optional<AddressIndex> index;
    OutgoingHalfedges out;
    parallel_invoke(
        [&] {
            index.emplace(checked_addresses(base, s.vertices, points));
            m.vertex_halfedge_.assign(nv, HalfedgeId());
            m.vertex_info_.resize(nv);
            m.address_.resize(nv);
            parallel_for(nv, 1 << 15, [&](std::size_t begin, std::size_t end) {
                for (std::size_t i = begin; i < end; ++i) {
                    m.vertex_info_[i] = static_cast<std::uint8_t>(points[i].level | (is_boundary(base, points[i]) ? Mesh::kBoundaryBit : 0));
                    m.address_[i] = {points[i].face, points[i].a[1], points[i].a[2]};
                }
            });
            m.vertex_count_ = nv;
        },
        [&] {
            out = matched_halfedges(s.faces, nv, m.opposite_);
            m.face_vertices_.resize(nf);
            parallel_for(nf, 1 << 16, [&](std::size_t begin, std::size_t end) {
                for (std::size_t f = begin; f < end; ++f)
                    for (int c = 0; c < 3; ++c) m.face_vertices_[f][c] = VertexId(s.faces[f][c]);
            });
            m.face_code_.assign(nf, 0);  // live; typed below
            m.face_count_ = nf;
        });
    progress.reach(kRestoreMatched);
    // Each vertex's outgoing halfedge (a boundary vertex's takes a walk round it), in parallel: a
    // block stops at its first unused vertex and the lowest block's is reported, the first in order.
    parallel_for(nv, 1 << 15, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            const auto v = static_cast<std::uint32_t>(i);
            const auto group = out.of(v);
            if (group.empty()) fail("vertex " + std::to_string(v) + " is used by no face");
            m.set_vertex_halfedge(VertexId(v), HalfedgeId(OutgoingHalfedges::halfedge(group.front())));
        }
    });
    out = {};
    // Faces: their colour, level and red edge follow from where their corners are (spec §1.3).
    std::vector<std::uint32_t> untyped(parallel_blocks(nf, 1 << 14), BaseMesh::kNone);
    parallel_blocks_for(nf, untyped.size(), [&](std::size_t block, std::size_t begin, std::size_t end) {
        for (std::size_t f = begin; f < end; ++f) {
            const auto type = type_from_corners(m, FaceId(static_cast<std::uint32_t>(f)));
            if (!type) {
                untyped[block] = static_cast<std::uint32_t>(f);
                return;
            }
            m.face_code_[f] = Mesh::pack(*type);
        }
    });
    for (std::uint32_t f : untyped)
        if (f != BaseMesh::kNone) fail("face " + std::to_string(f) + " is no piece of a triangle of the hierarchy");
    progress.reach(kRestoreTyped);
    return {std::move(m), std::move(points), std::move(*index)};
}

void check_restored(const Mesh& m, const ProgressSpan& progress) {
    // Typing put every face in its place in the hierarchy or failed.
    if (const InvariantReport report = check_invariants(m, 1, {.hierarchy_place = true}); !report.ok()) fail(report.violations.front());
    progress.reach(kRestoreChecked);
    if (const InvariantReport report = check_normal_form(m, 1); !report.ok()) fail(report.violations.front());
}

}  // namespace rgb
