#include "rgb/mesh/sharp_edges.h"

#include "rgb/mesh/mesh.h"
#include "rgb/mesh/vertex_rules.h"

namespace rgb {

std::vector<MeshSharpEdge> sharp_mesh_edges(const Mesh& mesh) {
    std::vector<MeshSharpEdge> edges;
    const BaseMesh& base = mesh.base();
    if (base.sharp_features().edges.empty()) return edges;
    for (FaceId f : mesh.faces())
        for (int i = 0; i < 3; ++i) {
            const HalfedgeId h = Mesh::halfedge(f, i);
            if (mesh.is_boundary(h) || mesh.opposite(h).idx < h.idx) continue;
            const auto on = base_edge_between(base, mesh.address(mesh.from_vertex(h)), mesh.address(mesh.to_vertex(h)));
            if (!on) continue;
            const int s = base.edge_sharpness(*on);
            if (s == 0) continue;
            const int level = mesh.edge_type(h).level;
            edges.push_back({h, s, s >= kInfiniteSharpness ? s : s - level});
        }
    return edges;
}

}  // namespace rgb
