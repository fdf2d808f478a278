#include "rgb/mesh_uvs.h"

#include "rgb/face_location.h"
#include "rgb/loop_geometry.h"
#include "rgb/mesh.h"
#include "rgb/uv_evaluator.h"

namespace rgb {

glm::dvec2 displayed_uv(const Mesh& mesh, UvEvaluator& uvs, FaceId f, int corner) {
    const VertexId v = mesh.face_vertices(f)[static_cast<std::size_t>(corner)];
    const auto p = in_face(mesh.base(), mesh.address(v), base_face_of(mesh, f));
    return uvs.control_uv(*p, display_level(mesh, v));
}

MeshUvs displayed_uvs(const Mesh& mesh, UvEvaluator& uvs) {
    MeshUvs out;
    // Per vertex slot, the values given to its corners so far (more than one only on seams).
    std::vector<std::vector<std::uint32_t>> of_vertex(mesh.vertex_capacity());
    out.corners.assign(mesh.face_capacity(), {0, 0, 0});
    for (FaceId f : mesh.faces()) {
        for (int c = 0; c < 3; ++c) {
            const glm::dvec2 uv = displayed_uv(mesh, uvs, f, c);
            std::vector<std::uint32_t>& known = of_vertex[mesh.face_vertices(f)[static_cast<std::size_t>(c)].idx];
            std::uint32_t id = static_cast<std::uint32_t>(out.values.size());
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
