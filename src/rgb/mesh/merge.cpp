// Vertex removal (spec §2.3, §2.4): the merges that undo one split, and the normalising swaps that
// bring any removable vertex into a mergeable configuration.
#include <array>
#include <stdexcept>
#include <vector>

#include "rgb/mesh/mesh.h"
#include "rgb/mesh/navigation.h"
#include "rgb/mesh/operators.h"

namespace rgb {

namespace {

enum class HalfKind { RR, GB, GGG, GBR };

// The faces around v between its two parents a and b, in ccw order.
struct Half {
    std::vector<HalfedgeId> out;  // outgoing halfedges of v, one per face
    HalfKind kind;
};

struct StarOfRemovable {
    std::vector<Half> halves;  // two for an interior vertex, one on the boundary
};

std::optional<HalfKind> classify(const Mesh& mesh, const std::vector<HalfedgeId>& out) {
    int g = 0, r = 0, b = 0;
    for (HalfedgeId h : out) {
        switch (mesh.colour(Mesh::face(h))) {
            case Colour::Green: ++g; break;
            case Colour::Red: ++r; break;
            case Colour::Blue: ++b; break;
        }
    }
    if (out.size() == 2 && r == 2) return HalfKind::RR;
    if (out.size() == 2 && g == 1 && b == 1) return HalfKind::GB;
    if (out.size() == 3 && g == 3) return HalfKind::GGG;
    if (out.size() == 3 && g == 1 && b == 1 && r == 1) return HalfKind::GBR;
    return std::nullopt;
}

std::optional<StarOfRemovable> analyse(const Mesh& mesh, VertexId v) {
    const int L = mesh.level(v);
    if (L == 0) return std::nullopt;
    std::vector<HalfedgeId> out;
    const HalfedgeId start = canonical_outgoing(mesh, v);
    HalfedgeId h = start;
    do {
        const FaceId f = Mesh::face(h);
        const int want = mesh.colour(f) == Colour::Green ? L : L - 1;
        if (mesh.level(f) != want) return std::nullopt;
        out.push_back(h);
        h = mesh.ccw_rotated(h);
    } while (h.valid() && h != start);
    const bool boundary = mesh.is_boundary(v);

    // Parents: the coarser neighbours joined to v by green edges of v's level.
    auto is_parent_edge = [&](HalfedgeId e, VertexId w) {
        const EdgeType t = mesh.edge_type(e);
        return t.colour == Colour::Green && t.level == L && mesh.level(w) < L;
    };
    std::vector<std::size_t> parents;
    for (std::size_t i = 0; i < out.size(); ++i)
        if (is_parent_edge(out[i], mesh.to_vertex(out[i]))) parents.push_back(i);
    if (boundary && is_parent_edge(Mesh::prev(out.back()), mesh.from_vertex(Mesh::prev(out.back()))))
        parents.push_back(out.size());

    StarOfRemovable star;
    if (boundary) {
        if (parents.size() != 2 || parents[0] != 0 || parents[1] != out.size()) return std::nullopt;
        star.halves.push_back({out, HalfKind::RR});
    } else {
        if (parents.size() != 2) return std::nullopt;
        star.halves.push_back({{out.begin() + parents[0], out.begin() + parents[1]}, HalfKind::RR});
        std::vector<HalfedgeId> rest(out.begin() + parents[1], out.end());
        rest.insert(rest.end(), out.begin(), out.begin() + parents[0]);
        star.halves.push_back({rest, HalfKind::RR});
    }
    for (Half& half : star.halves) {
        const auto kind = classify(mesh, half.out);
        if (!kind) return std::nullopt;
        half.kind = *kind;
    }
    return star;
}

bool mergeable(const StarOfRemovable& star) {
    for (const Half& h : star.halves)
        if (h.kind != HalfKind::RR && h.kind != HalfKind::GB) return false;
    return true;
}

// Turn a GGG or GBR half into GB with one swap that does not involve v's parents.
void normalise(Mesh& mesh, VertexId v, const Half& half) {
    const int L = mesh.level(v);
    if (half.kind == HalfKind::GGG) {
        // Flip the edge between the centre triangle and a corner triangle.
        for (HalfedgeId h : half.out) {
            const VertexId w = mesh.to_vertex(h);
            if (mesh.level(w) == L && can_gg_swap(mesh, h)) {
                gg_swap(mesh, h);
                return;
            }
        }
    } else if (half.kind == HalfKind::GBR) {
        for (HalfedgeId h : half.out) {
            const FaceId f = Mesh::face(h);
            if (mesh.colour(f) != Colour::Red) continue;
            const HalfedgeId red = Mesh::halfedge(f, mesh.type(f).red_edge);
            if (can_rb_swap(mesh, red)) {
                rb_swap(mesh, red);
                return;
            }
        }
    }
    throw std::logic_error("remove_vertex: could not normalise a half of the star");
}

}  // namespace

const char* merge_kind_name(MergeKind k) {
    switch (k) {
        case MergeKind::R4: return "R4-merge";
        case MergeKind::R2GB: return "R2GB-merge";
        case MergeKind::GBGB: return "GBGB-merge";
        case MergeKind::G2B2: return "G2B2-merge";
        case MergeKind::BoundaryR2: return "boundary R2-merge";
        case MergeKind::BoundaryGB: return "boundary GB-merge";
    }
    return "?";
}

std::optional<MergeKind> merge_kind(const Mesh& mesh, VertexId v) {
    const auto star = analyse(mesh, v);
    if (!star || !mergeable(*star)) return std::nullopt;
    const auto& hs = star->halves;
    if (hs.size() == 1) return hs[0].kind == HalfKind::RR ? MergeKind::BoundaryR2 : MergeKind::BoundaryGB;
    const int rr = (hs[0].kind == HalfKind::RR) + (hs[1].kind == HalfKind::RR);
    if (rr == 2) return MergeKind::R4;
    if (rr == 1) return MergeKind::R2GB;
    // Both halves GB: the blues either touch (G,B,B,G around v) or alternate with the greens.
    std::vector<Colour> ring;
    for (const Half& h : hs)
        for (HalfedgeId e : h.out) ring.push_back(mesh.colour(Mesh::face(e)));
    for (std::size_t i = 0; i < ring.size(); ++i)
        if (ring[i] == Colour::Blue && ring[(i + 1) % ring.size()] == Colour::Blue) return MergeKind::G2B2;
    return MergeKind::GBGB;
}

bool can_merge_vertex(const Mesh& mesh, VertexId v) { return merge_kind(mesh, v).has_value(); }

namespace {

FaceList merge_star(Mesh& mesh, VertexId v) {
    const auto star = analyse(mesh, v);
    if (!star || !mergeable(*star)) throw std::logic_error("merge_vertex: the star of the vertex is not mergeable");
    const int L = mesh.level(v);
    FaceList old_faces;
    InlineVector<NewFace, 2> new_faces;
    for (const Half& half : star->halves) {
        // The half is (v,p,x), (v,x,other); it becomes (p,x,other) one level coarser.
        const VertexId p = mesh.to_vertex(half.out[0]);
        const VertexId x = mesh.to_vertex(half.out[1]);
        const VertexId other = mesh.opposite_vertex(half.out[1]);
        FaceType type{Colour::Green, static_cast<std::uint8_t>(L - 1), 0};
        if (mesh.level(x) >= L) {
            // x is the other midpoint of the parent: a red whose red edge runs to the blue's low corner.
            VertexId low = p;
            for (HalfedgeId h : half.out) {
                const FaceId f = Mesh::face(h);
                if (mesh.colour(f) != Colour::Blue) continue;
                for (VertexId c : mesh.face_vertices(f))
                    if (mesh.level(c) < L) low = c;
            }
            type = FaceType{Colour::Red, static_cast<std::uint8_t>(L - 1), static_cast<std::uint8_t>(low == other ? 1 : 0)};
        }
        for (HalfedgeId h : half.out) old_faces.push_back(Mesh::face(h));
        new_faces.push_back({{p, x, other}, type});
    }
    const std::array<VertexId, 1> removed{v};
    return mesh.replace_faces(old_faces, new_faces, removed);
}

// The red triangle across f's red edge from a blue, and whether f's red edge leaves its top vertex
// (the diagonal the normal form does not use).
bool breaks_normal_form(const Mesh& mesh, FaceId f) {
    if (mesh.colour(f) != Colour::Red) return false;
    const FaceType t = mesh.type(f);
    const HalfedgeId red = Mesh::halfedge(f, t.red_edge);
    const HalfedgeId across = mesh.opposite(red);
    if (!across.valid() || mesh.colour(Mesh::face(across)) != Colour::Blue) return false;
    return mesh.level(mesh.from_vertex(red)) > t.level;
}

}  // namespace

void merge_vertex(Mesh& mesh, VertexId v) { merge_star(mesh, v); }

bool in_normal_form(const Mesh& mesh, FaceId f) { return !breaks_normal_form(mesh, f); }

bool can_remove_vertex(const Mesh& mesh, VertexId v) { return mesh.is_live(v) && analyse(mesh, v).has_value(); }

void remove_vertex(Mesh& mesh, VertexId v) {
    auto star = analyse(mesh, v);
    if (!star) throw std::logic_error("remove_vertex: the vertex is not removable");
    // Each half needs at most one swap; more would mean the star is not what removability promised.
    for (int swaps = 0; !mergeable(*star); ++swaps) {
        if (swaps == 2) throw std::logic_error("remove_vertex: the star does not normalise");
        for (const Half& half : star->halves)
            if (half.kind == HalfKind::GGG || half.kind == HalfKind::GBR) {
                normalise(mesh, v, half);
                break;
            }
        star = analyse(mesh, v);
        if (!star) throw std::logic_error("remove_vertex: a normalising swap broke the star");
    }
    // A parent that had all three edges split keeps two: the GG-swap's choice of diagonal may not be
    // the normal form's (spec §3.5), in which case one RB-swap corrects it.
    for (FaceId f : merge_star(mesh, v))
        if (mesh.is_live(f) && breaks_normal_form(mesh, f)) rb_swap(mesh, Mesh::halfedge(f, mesh.type(f).red_edge));
}

}  // namespace rgb

