// The three swap operators (spec §2.5): edge flips inside one parent triangle.
#include <array>
#include <stdexcept>

#include "rgb/mesh/mesh.h"
#include "rgb/mesh/operators.h"

namespace rgb {

namespace {

struct FlipFrame {
    FaceId f1, f2;
    VertexId p, q, r, s;  // faces (p,q,r) and (q,p,s) share p-q; the flip makes (p,s,r), (s,q,r)
};

std::optional<FlipFrame> flip_frame(const Mesh& mesh, HalfedgeId h) {
    const HalfedgeId o = mesh.opposite(h);
    if (!o.valid()) return std::nullopt;
    // No legality test for the new edge r-s is needed: each swap's colour test confines both
    // triangles to one parent triangle, and r-s runs inside it, so it cannot exist yet.
    return FlipFrame{Mesh::face(h),         Mesh::face(o),           mesh.from_vertex(h),
                     mesh.to_vertex(h),     mesh.opposite_vertex(h), mesh.opposite_vertex(o)};
}

// Replace the two triangles by the flipped pair; the new edge r-s is edge 1 of the first and edge 2
// of the second, which is where red/blue results keep their red edge.
void flip(Mesh& mesh, const FlipFrame& fr, FaceType first, FaceType second) {
    const std::array<FaceId, 2> old{fr.f1, fr.f2};
    const std::array<NewFace, 2> created{NewFace{{fr.p, fr.s, fr.r}, first}, NewFace{{fr.s, fr.q, fr.r}, second}};
    mesh.replace_faces(old, created);
}

bool both_coloured(const Mesh& mesh, const FlipFrame& fr, Colour a, Colour b) {
    const Colour c1 = mesh.colour(fr.f1), c2 = mesh.colour(fr.f2);
    return (c1 == a && c2 == b) || (c1 == b && c2 == a);
}

int high_vertices(const Mesh& mesh, const std::array<VertexId, 3>& t, int level) {
    int n = 0;
    for (VertexId v : t) n += mesh.level(v) > level;
    return n;
}

}  // namespace

bool can_bb_swap(const Mesh& mesh, HalfedgeId h) {
    if (mesh.edge_type(h).colour != Colour::Red) return false;
    const auto fr = flip_frame(mesh, h);
    return fr && both_coloured(mesh, *fr, Colour::Blue, Colour::Blue) && mesh.level(fr->f1) == mesh.level(fr->f2);
}

void bb_swap(Mesh& mesh, HalfedgeId h) {
    if (!can_bb_swap(mesh, h)) throw std::logic_error("bb_swap: not two blues sharing their red edge");
    const auto fr = *flip_frame(mesh, h);
    const FaceType green{Colour::Green, static_cast<std::uint8_t>(mesh.level(fr.f1) + 1), 0};
    flip(mesh, fr, green, green);
}

bool can_gg_swap(const Mesh& mesh, HalfedgeId h) {
    const auto fr = flip_frame(mesh, h);
    if (!fr || !both_coloured(mesh, *fr, Colour::Green, Colour::Green)) return false;
    const int L = mesh.level(fr->f1);
    if (L == 0 || mesh.level(fr->f2) != L) return false;
    if (mesh.level(fr->p) != L || mesh.level(fr->q) != L) return false;
    // One of r, s is the parent's corner, the other a midpoint: a corner and the centre triangle.
    return (mesh.level(fr->r) < L) != (mesh.level(fr->s) < L);
}

void gg_swap(Mesh& mesh, HalfedgeId h) {
    if (!can_gg_swap(mesh, h)) throw std::logic_error("gg_swap: not a corner and the centre of one parent");
    const auto fr = *flip_frame(mesh, h);
    const auto l = static_cast<std::uint8_t>(mesh.level(fr.f1) - 1);
    flip(mesh, fr, FaceType{Colour::Blue, l, 1}, FaceType{Colour::Blue, l, 2});
}

bool can_rb_swap(const Mesh& mesh, HalfedgeId h) {
    if (mesh.edge_type(h).colour != Colour::Red) return false;
    const auto fr = flip_frame(mesh, h);
    return fr && both_coloured(mesh, *fr, Colour::Red, Colour::Blue) && mesh.level(fr->f1) == mesh.level(fr->f2);
}

void rb_swap(Mesh& mesh, HalfedgeId h) {
    if (!can_rb_swap(mesh, h)) throw std::logic_error("rb_swap: not a red and a blue sharing their red edge");
    const auto fr = *flip_frame(mesh, h);
    const int l = mesh.level(fr.f1);
    auto kind = [&](const std::array<VertexId, 3>& t, std::uint8_t red_edge) {
        return FaceType{high_vertices(mesh, t, l) == 2 ? Colour::Blue : Colour::Red, static_cast<std::uint8_t>(l),
                        red_edge};
    };
    flip(mesh, fr, kind({fr.p, fr.s, fr.r}, 1), kind({fr.s, fr.q, fr.r}, 2));
}

}  // namespace rgb
