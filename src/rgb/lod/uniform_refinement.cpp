// Uniform refinement (the fast path of a whole-surface request): level by level, every green edge of
// the level is split, with no recursion, since no triangle is coarser than the level being split.
#include <algorithm>
#include <vector>

#include "rgb/lod/refine.h"
#include "rgb/mesh/mesh.h"
#include "rgb/mesh/mesh_room_prefault.h"
#include "rgb/mesh/operators.h"
#include "rgb/values/loop_geometry.h"
#include "rgb/values/loop_split.h"

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
    const MeshRoomPrefault room_ahead(mesh, new_faces, new_faces / 2 + new_boundary_vertices);
    std::vector<FaceId> front;
    for (int l = 0; l < level; ++l) {
        // The vertices of level l are stencil points of the splits of every later pass, and right now,
        // where the mesh is uniform around them, their ring at their own level is their neighbours:
        // their limits cost least now.
        if (l + 1 < level)
            for (VertexId v : mesh.vertices())
                if (mesh.level(v) == l) limit_position_where_uniform(mesh, v);
        // Only a G_l or R_l triangle has a green edge of level l: any edge of the green one, the edge
        // opposite the top (the vertex of level l+1) of the red one.
        auto splittable_edge = [&](FaceId f) {
            if (!mesh.is_live(f) || mesh.level(f) != l) return HalfedgeId();
            const Colour colour = mesh.colour(f);
            if (colour == Colour::Green) return Mesh::halfedge(f, 0);
            if (colour == Colour::Blue) return HalfedgeId();
            for (int c = 0; c < 3; ++c)
                if (mesh.level(mesh.face_vertices(f)[c]) > l) return Mesh::halfedge(f, (c + 1) % 3);
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
