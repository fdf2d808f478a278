// Edge splits (spec §2.1, §2.2) and the Loop position of the inserted vertex (§4.4).
#include <array>
#include <stdexcept>
#include <vector>

#include "rgb/loop_geometry.h"
#include "rgb/mesh.h"
#include "rgb/operators.h"

namespace rgb {

namespace {

// The halfedges of the edge of h, one per incident face (one on the boundary).
std::vector<HalfedgeId> edge_sides(const Mesh& mesh, HalfedgeId h) {
    std::vector<HalfedgeId> sides{h};
    if (!mesh.is_boundary(h)) sides.push_back(mesh.opposite(h));
    return sides;
}

// For a red triangle containing the halfedge h as its coarse edge: the endpoint of h that its red edge
// reaches.
VertexId red_edge_endpoint(const Mesh& mesh, HalfedgeId h) {
    const int red = mesh.type(Mesh::face(h)).red_edge;
    return red == (Mesh::corner(h) + 1) % 3 ? mesh.to_vertex(h) : mesh.from_vertex(h);
}

// Vertex opposite the edge of h in the uniform mesh of the edge's level, found from the triangle of h
// even when that triangle is only half of its parent (spec §4.4).
VertexId stencil_opposite(const Mesh& mesh, HalfedgeId h) {
    while (true) {
        const FaceId t = Mesh::face(h);
        if (mesh.colour(t) == Colour::Green) return mesh.opposite_vertex(h);
        // t is red: look across its red edge, at the other half of the parent.
        const HalfedgeId across = mesh.opposite(Mesh::halfedge(t, mesh.type(t).red_edge));
        const FaceId g = Mesh::face(across);
        if (mesh.colour(g) == Colour::Red) return mesh.opposite_vertex(across);
        // g is blue: the vertex is the corner of the parent beyond the blue's mid-segment.
        const int lvl = mesh.level(g);
        HalfedgeId mid = across;
        for (int i = 0; i < 3; ++i, mid = Mesh::next(mid))
            if (mesh.level(mesh.from_vertex(mid)) > lvl && mesh.level(mesh.to_vertex(mid)) > lvl) break;
        h = mesh.opposite(mid);
    }
}

}  // namespace

std::vector<VertexId> split_stencil(const Mesh& mesh, HalfedgeId h) {
    std::vector<VertexId> s{mesh.from_vertex(h), mesh.to_vertex(h)};
    if (!mesh.is_boundary(h)) {
        s.push_back(stencil_opposite(mesh, h));
        s.push_back(stencil_opposite(mesh, mesh.opposite(h)));
    }
    return s;
}

const char* split_kind_name(SplitKind k) {
    switch (k) {
        case SplitKind::GG: return "GG-split";
        case SplitKind::RG: return "RG-split";
        case SplitKind::RR_Opposite: return "RR-split (opposite)";
        case SplitKind::RR_Same: return "RR-split (same)";
        case SplitKind::BoundaryG: return "boundary G-bisection";
        case SplitKind::BoundaryR: return "boundary R-bisection";
    }
    return "?";
}

std::optional<SplitKind> split_kind(const Mesh& mesh, HalfedgeId h) {
    const EdgeType e = mesh.edge_type(h);
    if (e.colour != Colour::Green) return std::nullopt;
    const std::vector<HalfedgeId> sides = edge_sides(mesh, h);
    int reds = 0;
    for (HalfedgeId s : sides) {
        const FaceId f = Mesh::face(s);
        if (mesh.level(f) != e.level) return std::nullopt;
        reds += mesh.colour(f) == Colour::Red;
    }
    if (sides.size() == 1) return reds ? SplitKind::BoundaryR : SplitKind::BoundaryG;
    if (reds == 0) return SplitKind::GG;
    if (reds == 1) return SplitKind::RG;
    return red_edge_endpoint(mesh, sides[0]) == red_edge_endpoint(mesh, sides[1]) ? SplitKind::RR_Same
                                                                                 : SplitKind::RR_Opposite;
}

bool can_split_edge(const Mesh& mesh, HalfedgeId h) { return split_kind(mesh, h).has_value(); }

bool has_split_stencil(const Mesh& mesh, HalfedgeId h) {
    const int l = mesh.edge_type(h).level;
    for (VertexId w : split_stencil(mesh, h))
        if (mesh.level(w) < l && !try_limit_position(mesh, w)) return false;
    return true;
}

VertexId split_edge(Mesh& mesh, HalfedgeId h) {
    if (!can_split_edge(mesh, h)) throw std::logic_error("split_edge: the edge is not splittable");
    if (!has_split_stencil(mesh, h)) throw std::logic_error("split_edge: the Loop stencil is incomplete");
    const int l = mesh.edge_type(h).level;
    const std::vector<VertexId> s = split_stencil(mesh, h);
    const VertexId a = s[0], b = s[1];
    const bool boundary = s.size() == 2;
    const glm::dvec3 pa = control_point(mesh, a, l), pb = control_point(mesh, b, l);
    const glm::dvec3 position = boundary ? 0.5 * (pa + pb)
                                         : 0.375 * (pa + pb) + 0.125 * (control_point(mesh, s[2], l) +
                                                                        control_point(mesh, s[3], l));

    const std::vector<HalfedgeId> sides = edge_sides(mesh, h);
    std::vector<FaceId> old_faces;
    std::vector<std::array<VertexId, 3>> corners;  // (x0, x1, x) with the split edge x0->x1
    std::vector<FaceType> old_types;
    std::vector<int> red_at;  // 0: green, 1: red edge reaches x1, 2: red edge reaches x0
    for (HalfedgeId side : sides) {
        const FaceId f = Mesh::face(side);
        old_faces.push_back(f);
        corners.push_back({mesh.from_vertex(side), mesh.to_vertex(side), mesh.opposite_vertex(side)});
        old_types.push_back(mesh.type(f));
        const int i = Mesh::corner(side);
        red_at.push_back(mesh.colour(f) == Colour::Green ? 0 : (old_types.back().red_edge == (i + 1) % 3 ? 1 : 2));
    }

    const VertexId v = mesh.add_vertex(l + 1, position, boundary, a, b);
    const auto lvl = static_cast<std::uint8_t>(l);
    const FaceType red_first{Colour::Red, lvl, 1}, red_second{Colour::Red, lvl, 2};
    const FaceType green_fine{Colour::Green, static_cast<std::uint8_t>(l + 1), 0};
    const FaceType blue_first{Colour::Blue, lvl, 2}, blue_second{Colour::Blue, lvl, 1};
    std::vector<NewFace> new_faces;
    for (std::size_t k = 0; k < sides.size(); ++k) {
        const auto [x0, x1, x] = corners[k];
        const std::array<VertexId, 3> t1{x0, v, x}, t2{v, x1, x};
        switch (red_at[k]) {
            case 0: new_faces.push_back({t1, red_first}); new_faces.push_back({t2, red_second}); break;
            case 1: new_faces.push_back({t1, green_fine}); new_faces.push_back({t2, blue_second}); break;
            default: new_faces.push_back({t1, blue_first}); new_faces.push_back({t2, green_fine}); break;
        }
    }
    const std::vector<FaceId> created = mesh.replace_faces(old_faces, new_faces);

    // Completing the third edge of a parent leaves two blues on one red edge: swap them (§2.1).
    for (FaceId f : created) {
        if (!mesh.is_live(f) || mesh.colour(f) != Colour::Blue) continue;
        const HalfedgeId red = Mesh::halfedge(f, mesh.type(f).red_edge);
        if (can_bb_swap(mesh, red)) bb_swap(mesh, red);
    }
    return v;
}

}  // namespace rgb
