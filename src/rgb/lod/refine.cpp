// Recursive edge refinement (spec §3.1) with the extra refinement Loop stencils need (§4.4).
#include "rgb/lod/refine.h"

#include <array>
#include <stdexcept>

#include "rgb/mesh/mesh.h"
#include "rgb/mesh/operators.h"
#include "rgb/values/loop_split.h"

namespace rgb {

namespace {

// The coarse green edge of a red triangle: the one opposite its top vertex.
HalfedgeId coarse_edge_of_red(const Mesh& mesh, FaceId f) {
    for (int i = 0; i < 3; ++i) {
        const HalfedgeId h = Mesh::halfedge(f, i);
        const EdgeType t = mesh.edge_type(h);
        if (t.colour == Colour::Green && t.level == mesh.level(f)) return h;
    }
    return HalfedgeId();
}

bool refine_halfedge(Mesh& mesh, HalfedgeId h);

bool refine_vertices(Mesh& mesh, VertexId a, VertexId b) {
    const HalfedgeId h = mesh.find_edge(a, b);
    return h.valid() && refine_halfedge(mesh, h);
}

bool refine_halfedge(Mesh& mesh, HalfedgeId h) {
    const VertexId a = mesh.from_vertex(h), b = mesh.to_vertex(h);
    const EdgeType e = mesh.edge_type(h);
    if (e.colour != Colour::Green) return false;
    // Bring every incident triangle up to the edge's level first. Each call works on a coarser level,
    // so the recursion ends; it may split this very edge, hence the re-lookups after it. This adds
    // exactly the vertices the RGB topology needs; geometry needs none (loop_geometry.h).
    bool edited = false;
    for (int side = 0; side < 2; ++side) {
        if (edited && !(h = mesh.find_edge(a, b)).valid()) return false;
        const HalfedgeId s = side == 0 ? h : mesh.opposite(h);
        if (!s.valid()) continue;
        const FaceId f = Mesh::face(s);
        if (mesh.level(f) >= e.level) continue;
        const HalfedgeId coarse = edge_refining_face(mesh, f);
        if (!coarse.valid()) throw std::logic_error("refine_edge: a coarser neighbour has no edge to refine (invalid RGB mesh)");
        refine_halfedge(mesh, coarse);
        edited = true;
    }
    if (edited && !(h = mesh.find_edge(a, b)).valid()) return false;
    // A green edge between triangles of its level is splittable (split_edge checks it).
    split_edge(mesh, h);
    return true;
}

}  // namespace

HalfedgeId edge_refining_face(const Mesh& mesh, FaceId f) {
    switch (mesh.colour(f)) {
        case Colour::Green: return Mesh::halfedge(f, 0);
        case Colour::Red: return coarse_edge_of_red(mesh, f);
        case Colour::Blue: break;
    }
    // A blue's red edge is shared with a red of the same parent (two blues would have been swapped).
    const HalfedgeId across = mesh.opposite(Mesh::halfedge(f, mesh.type(f).red_edge));
    return coarse_edge_of_red(mesh, Mesh::face(across));
}

bool refine_edge(Mesh& mesh, VertexId a, VertexId b) { return refine_vertices(mesh, a, b); }

bool refine_edge(Mesh& mesh, HalfedgeId h) { return refine_halfedge(mesh, h); }

namespace {
// A neighbour of v finer than v, if there is one.
VertexId finer_neighbour(const Mesh& mesh, VertexId v) {
    const HalfedgeId start = mesh.vertex_halfedge(v);
    HalfedgeId h = start;
    do {
        for (VertexId w : {mesh.to_vertex(h), mesh.opposite_vertex(h)})
            if (mesh.level(w) > mesh.level(v)) return w;
        h = mesh.ccw_rotated(h);
    } while (h.valid() && h != start);
    return VertexId();
}
}  // namespace

std::size_t remove_with_dependents(Mesh& mesh, VertexId v) {
    if (mesh.level(v) == 0) throw std::logic_error("remove_with_dependents: base vertices are never removed");
    std::size_t removed = 0;
    // A finer neighbour needs v: its parent triangles have v as a corner. Removing it first, and so
    // on recursively, leaves v with no finer neighbour, which makes it removable (spec §2.4).
    for (VertexId u = finer_neighbour(mesh, v); u.valid(); u = finer_neighbour(mesh, v)) removed += remove_with_dependents(mesh, u);
    remove_vertex(mesh, v);
    return removed + 1;
}

}  // namespace rgb
