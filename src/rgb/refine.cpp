// Recursive edge refinement (spec §3.1) with the extra refinement Loop stencils need (§4.4).
#include "rgb/refine.h"

#include <array>

#include "rgb/loop_geometry.h"
#include "rgb/mesh.h"
#include "rgb/navigation.h"
#include "rgb/operators.h"

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
    // so the recursion ends; it may split this very edge, hence the re-lookups.
    for (int side = 0; side < 2; ++side) {
        h = mesh.find_edge(a, b);
        if (!h.valid()) return false;
        const HalfedgeId s = side == 0 ? h : mesh.opposite(h);
        if (!s.valid()) continue;
        const FaceId f = Mesh::face(s);
        if (mesh.level(f) >= e.level) continue;
        const HalfedgeId coarse = edge_refining_face(mesh, f);
        refine_vertices(mesh, mesh.from_vertex(coarse), mesh.to_vertex(coarse));
    }
    while (true) {
        h = mesh.find_edge(a, b);
        if (!h.valid() || !can_split_edge(mesh, h)) return false;
        bool complete = true;
        for (VertexId w : split_stencil(mesh, h)) {
            if (mesh.level(w) >= e.level || try_limit_position(mesh, w)) continue;
            complete = false;
            // The stencil needs the limit of a coarser vertex: refine around it (§4.4).
            if (!ensure_limit(mesh, w)) return false;
        }
        if (complete) break;
    }
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

bool ensure_limit(Mesh& mesh, VertexId v) {
    while (!try_limit_position(mesh, v)) {
        const std::vector<VertexId> ring = uniform_ring(mesh, v);
        bool advanced = false;
        if (!ring.empty()) {
            for (VertexId w : ring)
                if (mesh.level(w) < mesh.level(v) && !try_limit_position(mesh, w)) advanced = ensure_limit(mesh, w) || advanced;
        } else {
            // Split the coarse green edges around v until its ring at its own level exists.
            const HalfedgeId start = canonical_outgoing(mesh, v);
            HalfedgeId h = start;
            do {
                for (HalfedgeId e : {h, Mesh::prev(h)}) {
                    const EdgeType t = mesh.edge_type(e);
                    if (!advanced && t.colour == Colour::Green && t.level <= mesh.level(v))
                        advanced = refine_vertices(mesh, mesh.from_vertex(e), mesh.to_vertex(e));
                }
                if (advanced) break;
                h = mesh.ccw_rotated(h);
            } while (h.valid() && h != start);
        }
        if (!advanced) return false;
    }
    return true;
}

}  // namespace rgb
