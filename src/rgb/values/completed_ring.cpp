#include "rgb/values/completed_ring.h"

#include <array>
#include <optional>

#include "rgb/mesh/base_mesh.h"
#include "rgb/mesh/mesh.h"
#include "rgb/mesh/navigation.h"
#include "rgb/rules/loop_rules.h"
#include "rgb/values/loop_geometry.h"

namespace rgb {

namespace {

bool is_edge(EdgeType t, Colour colour, int level) { return t.colour == colour && t.level == level; }

// The halfedge of the coarse green edge of a red face (the one of its own level), or invalid.
HalfedgeId coarse_edge(const Mesh& mesh, FaceId f) {
    for (int i = 0; i < 3; ++i)
        if (is_edge(mesh.edge_type(Mesh::halfedge(f, i)), Colour::Green, mesh.level(f))) return Mesh::halfedge(f, i);
    return HalfedgeId();
}

// The ring point of v (level l) lying inside the face of h, a face of level l - 1: the edge point of
// an edge (p, q) of Σ(l-1) that the mesh has not split. If the face is a red with v on top, (p, q) is
// its coarse edge; if a blue, the coarse edge of the red beyond its red edge. The point follows from
// p, q, v's other parent (the opposite vertex on v's side) and the opposite vertex across (p, q).
// Angles are in 30-degree units (spec §1.5).
std::optional<glm::dvec3> missing_ring_point(const Mesh& mesh, VertexId v, HalfedgeId h) {
    const int l = mesh.level(v);
    const FaceId f = Mesh::face(h);
    if (mesh.level(f) != l - 1) return std::nullopt;
    HalfedgeId coarse;
    if (mesh.colour(f) == Colour::Red) {
        coarse = Mesh::next(h);  // opposite v, its top
    } else if (mesh.colour(f) == Colour::Blue) {
        const HalfedgeId beyond = mesh.opposite(Mesh::halfedge(f, mesh.type(f).red_edge));
        if (beyond.valid() && mesh.colour(Mesh::face(beyond)) == Colour::Red && mesh.level(Mesh::face(beyond)) == l - 1)
            coarse = coarse_edge(mesh, Mesh::face(beyond));
    }
    if (!coarse.valid() || !is_edge(mesh.edge_type(coarse), Colour::Green, l - 1)) return std::nullopt;
    const VertexId p = mesh.from_vertex(coarse), q = mesh.to_vertex(coarse);
    // v's parent in this face is joined to it by a green edge and is coarser (a red's red edge leads
    // to the apex, a blue's other corner is v's sibling); the other parent lies straight on, past
    // finer vertices.
    auto parent_along = [&](HalfedgeId edge, VertexId w) {
        return mesh.edge_type(edge).colour == Colour::Green && mesh.level(w) < l;
    };
    std::optional<VertexId> parent;
    if (parent_along(h, mesh.to_vertex(h)))
        parent = mesh.to_vertex(h);
    else if (parent_along(Mesh::prev(h), mesh.opposite_vertex(h)))
        parent = mesh.opposite_vertex(h);
    const auto ahead = parent ? turn_ccw(mesh, v, *parent, 6) : std::nullopt;
    const auto other_parent = ahead ? walk_straight(mesh, v, *ahead, l - 1) : std::nullopt;
    // Across (p, q): the third corner of its triangle in Σ(l-1), itself or through the top of the red
    // half of it that holds (p, q).
    const HalfedgeId across = mesh.opposite(coarse);  // q -> p
    if (!other_parent || !across.valid()) return std::nullopt;
    const FaceId g = Mesh::face(across);
    if (mesh.level(g) != l - 1) return std::nullopt;
    std::optional<VertexId> far;
    if (mesh.colour(g) == Colour::Green) {
        far = mesh.opposite_vertex(across);
    } else if (mesh.colour(g) == Colour::Red && is_edge(mesh.edge_type(across), Colour::Green, l - 1)) {
        // The red (p, q, top) is half of (p, q, far) split on the edge from far to the corner that
        // is not on the red's red edge.
        const VertexId top = mesh.opposite_vertex(across);
        const VertexId on_split_edge = mesh.edge_type(Mesh::next(across)).colour == Colour::Red ? q : p;
        far = walk_straight(mesh, on_split_edge, top, l - 1);
    }
    if (!far) return std::nullopt;
    return interior_edge_point(control_point(mesh, p, l - 1), control_point(mesh, q, l - 1),
                               control_point(mesh, *other_parent, l - 1), control_point(mesh, *far, l - 1));
}

}  // namespace

std::optional<glm::dvec3> limit_from_completed_ring(const Mesh& mesh, VertexId v) {
    const int l = mesh.level(v);
    if (l == 0 || mesh.is_boundary(v) || mesh.base().has_sharp_features()) return std::nullopt;
    // Green edges point along ring directions (red ones 30 degrees off them): start at one.
    const HalfedgeId first = mesh.vertex_halfedge(v);
    HalfedgeId start = first;
    while (mesh.edge_type(start).colour != Colour::Green) {
        start = mesh.ccw_rotated(start);
        if (start == first) return std::nullopt;
    }
    std::array<glm::dvec3, 6> ring;
    std::size_t n = 0;
    auto add = [&](const std::optional<glm::dvec3>& point) {
        if (!point || n == ring.size()) return false;
        ring[n++] = *point;
        return true;
    };
    // Around v counter-clockwise: face(h) spans the directions [direction, direction + its angle].
    int direction = 0;
    HalfedgeId h = start;
    do {
        const int span = mesh.angle(Mesh::face(h), Mesh::corner(h));
        if (direction % 2 == 0) {
            const auto w = walk_straight(mesh, v, mesh.to_vertex(h), l);
            if (!add(w ? std::optional(control_point(mesh, *w, l)) : std::nullopt)) return std::nullopt;
        }
        for (int d = direction + 1; d < direction + span; ++d)
            if (d % 2 == 0 && !add(missing_ring_point(mesh, v, h))) return std::nullopt;
        direction += span;
        h = mesh.ccw_rotated(h);
    } while (h.valid() && h != start);
    if (n != ring.size() || direction != 12) return std::nullopt;
    return interior_limit(mesh.insertion_position(v), ring);
}

}  // namespace rgb
