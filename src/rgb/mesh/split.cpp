// Edge splits (spec §2.1, §2.2): the topology. The inserted vertex's Loop position (§4.4) is the
// caller's (values/loop_split.h).
#include <algorithm>
#include <array>
#include <cassert>

#include "rgb/mesh/mesh.h"
#include "rgb/mesh/operators.h"

namespace rgb {

namespace {

// The halfedges of the edge of h, one per incident face (one on the boundary).
InlineVector<HalfedgeId, 2> edge_sides(const Mesh& mesh, HalfedgeId h) {
    InlineVector<HalfedgeId, 2> sides{h};
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

InlineVector<VertexId, 4> split_stencil(const Mesh& mesh, HalfedgeId h) {
    InlineVector<VertexId, 4> s{mesh.from_vertex(h), mesh.to_vertex(h)};
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
    const auto sides = edge_sides(mesh, h);
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

VertexId split_edge_at(Mesh& mesh, HalfedgeId h, const glm::dvec3& position) {
    // Checked once, by split_edge (values/loop_split.h), before it walks the stencil for the position.
    assert(can_split_edge(mesh, h));
    const int l = mesh.edge_type(h).level;
    const VertexId a = mesh.from_vertex(h), b = mesh.to_vertex(h);
    const bool boundary = mesh.is_boundary(h);

    const auto sides = edge_sides(mesh, h);
    FaceList old_faces;
    for (HalfedgeId side : sides) old_faces.push_back(Mesh::face(side));
    const VertexId v = mesh.next_vertex_slot();
    const auto lvl = static_cast<std::uint8_t>(l);
    const FaceType green_fine{Colour::Green, static_cast<std::uint8_t>(l + 1), 0};
    auto red = [&](int red_edge) { return FaceType{Colour::Red, lvl, static_cast<std::uint8_t>(red_edge)}; };
    auto blue = [&](int red_edge) { return FaceType{Colour::Blue, lvl, static_cast<std::uint8_t>(red_edge)}; };
    InlineVector<NewFace, 6> new_faces;
    for (HalfedgeId side : sides) {
        const FaceId f = Mesh::face(side);
        const int i = Mesh::corner(side);
        const VertexId x0 = mesh.from_vertex(side), x1 = mesh.to_vertex(side), x = mesh.opposite_vertex(side);
        if (mesh.colour(f) == Colour::Green) {
            new_faces.push_back({{x0, v, x}, red(1)});
            new_faces.push_back({{v, x1, x}, red(2)});
            continue;
        }
        // A red side (x is its top) becomes a corner G_{l+1} at the endpoint its red edge leaves
        // alone, and a blue beside the triangle across the red edge, which is either the sibling red
        // of the same parent or, if that parent already had two split edges, a blue.
        const bool red_edge_at_x1 = mesh.type(f).red_edge == (i + 1) % 3;
        const HalfedgeId outside = mesh.opposite(Mesh::halfedge(f, red_edge_at_x1 ? (i + 1) % 3 : (i + 2) % 3));
        const FaceId across = Mesh::face(outside);
        const VertexId y = mesh.opposite_vertex(outside);
        new_faces.push_back({red_edge_at_x1 ? std::array{x0, v, x} : std::array{v, x1, x}, green_fine});
        if (mesh.colour(across) == Colour::Blue) {
            // This split completes the parent: the two blues sharing the red edge are BB-swapped into
            // two G_{l+1} (spec §2.1), folded into this one replacement.
            old_faces.push_back(across);
            const VertexId near = red_edge_at_x1 ? x1 : x0;
            new_faces.push_back({red_edge_at_x1 ? std::array{near, y, v} : std::array{y, near, v}, green_fine});
            new_faces.push_back({red_edge_at_x1 ? std::array{y, x, v} : std::array{x, y, v}, green_fine});
        } else if (red_edge_at_x1) {
            // Normal form (spec §3.5): in a parent with two split edges the red triangle's red edge
            // enters its top vertex. Keeping the old red edge x-x1 would break that, so the diagonal
            // of the quadrilateral (v, x1, y, x) is v-y instead (an RB-swap folded into the split).
            old_faces.push_back(across);
            new_faces.push_back({{v, x1, y}, red(2)});
            new_faces.push_back({{v, y, x}, blue(0)});
        } else {
            new_faces.push_back({{x0, v, x}, blue(2)});
        }
    }
    const Mesh::NewVertex added{l + 1, position, boundary, a, b};
    mesh.replace_faces(old_faces, new_faces, {}, &added);
    return v;
}

}  // namespace rgb
