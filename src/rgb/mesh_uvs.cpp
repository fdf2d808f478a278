#include "rgb/mesh_uvs.h"

#include "rgb/face_location.h"
#include "rgb/loop_geometry.h"
#include "rgb/mesh.h"
#include "rgb/uv_evaluator.h"
#include "rgb/vertex_rules.h"

namespace rgb {

namespace {

// The address of a corner's vertex in the base face of the corner's triangle: it names the corner's
// UV value (uv_evaluator.h).
SurfacePoint corner_address(const Mesh& mesh, FaceId f, int corner) {
    const VertexId v = mesh.face_vertices(f)[static_cast<std::size_t>(corner)];
    return *in_face(mesh.base(), mesh.address(v), base_face_of(mesh, f));
}

}  // namespace

glm::dvec2 displayed_uv(const Mesh& mesh, UvEvaluator& uvs, FaceId f, int corner) {
    return uvs.control_uv(corner_address(mesh, f, corner), display_level(mesh, mesh.face_vertices(f)[static_cast<std::size_t>(corner)]));
}

glm::dvec2 limit_uv(const Mesh& mesh, UvEvaluator& uvs, FaceId f, int corner) {
    return uvs.limit_uv(corner_address(mesh, f, corner));
}

MeshUvs mesh_uvs(const Mesh& mesh, UvEvaluator& uvs, bool limit) {
    MeshUvs out;
    // Per vertex slot, the values given to its corners so far: one for a vertex inside a base face,
    // whose corners all share it (computed once), more only on seams.
    std::vector<std::vector<std::uint32_t>> of_vertex(mesh.vertex_capacity());
    out.corners.assign(mesh.face_capacity(), {0, 0, 0});
    for (FaceId f : mesh.faces()) {
        for (int c = 0; c < 3; ++c) {
            const VertexId v = mesh.face_vertices(f)[static_cast<std::size_t>(c)];
            std::vector<std::uint32_t>& known = of_vertex[v.idx];
            if (!known.empty() && !on_base_edge_or_vertex(mesh.address(v))) {
                out.corners[f.idx][static_cast<std::size_t>(c)] = known.front();
                continue;
            }
            const glm::dvec2 uv = limit ? limit_uv(mesh, uvs, f, c) : displayed_uv(mesh, uvs, f, c);
            auto id = static_cast<std::uint32_t>(out.values.size());
            for (std::uint32_t k : known)
                if (out.values[k] == uv) id = k;
            if (id == out.values.size()) {
                out.values.push_back(uv);
                known.push_back(id);
            }
            out.corners[f.idx][static_cast<std::size_t>(c)] = id;
        }
    }
    return out;
}

}  // namespace rgb
