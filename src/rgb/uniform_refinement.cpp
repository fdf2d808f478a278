// Uniform refinement (the fast path of a whole-surface request): level by level, every green edge of
// the level is split, with no recursion, since no triangle is coarser than the level being split.
#include <algorithm>
#include <vector>

#include "rgb/mesh.h"
#include "rgb/operators.h"
#include "rgb/refine.h"

namespace rgb {

void refine_uniform(Mesh& mesh, int level) {
    // Room for the final mesh at once, so that no level copies the arrays: a face of level k becomes
    // 4^(level - k) faces; an interior split adds one vertex per two faces, a boundary one (at most
    // 2^steps per boundary edge) one per face.
    std::size_t new_faces = 0, new_boundary_vertices = 0;
    for (FaceId f : mesh.faces()) {
        const int steps = std::clamp(level - mesh.level(f), 0, kMaxLevel);
        new_faces += (std::size_t(1) << (2 * steps)) - 1;
        for (int c = 0; c < 3; ++c)
            if (mesh.is_boundary(Mesh::halfedge(f, c))) new_boundary_vertices += (std::size_t(1) << steps) - 1;
    }
    mesh.reserve(mesh.face_capacity() + new_faces, mesh.vertex_capacity() + new_faces / 2 + new_boundary_vertices);
    std::vector<FaceId> front;
    for (int l = 0; l < level; ++l) {
        // Only a G_l or R_l triangle can have a green edge of level l.
        auto splittable_edge = [&](FaceId f) {
            const FaceType& t = mesh.type(f);
            if (!mesh.is_live(f) || t.level != l || t.colour == Colour::Blue) return HalfedgeId();
            for (int c = 0; c < 3; ++c) {
                const HalfedgeId h = Mesh::halfedge(f, c);
                const EdgeType e = mesh.edge_type(h);
                if (e.colour == Colour::Green && e.level == l) return h;
            }
            return HalfedgeId();
        };
        // Every face a split creates contains the new vertex; the new R_l ones (the only ones with an
        // edge left to split) go on a stack that is worked off before the sweep moves on. So the
        // refinement spreads from face to neighbour while their data is still in cache, and slots the
        // sweep has passed (reused ones) are not missed.
        for (std::uint32_t i = 0; i < mesh.face_capacity(); ++i) {
            front.push_back(FaceId(i));
            while (!front.empty()) {
                const FaceId f = front.back();
                front.pop_back();
                const HalfedgeId h = splittable_edge(f);
                if (!h.valid()) continue;
                front.push_back(f);
                const VertexId v = split_edge(mesh, h);
                const HalfedgeId start = mesh.vertex_halfedge(v);
                HalfedgeId o = start;
                do {
                    const FaceId g = Mesh::face(o);
                    if (mesh.colour(g) == Colour::Red && mesh.level(g) == l) front.push_back(g);
                    o = mesh.ccw_rotated(o);
                } while (o.valid() && o != start);
            }
        }
    }
}

}  // namespace rgb
