#include "rgb/values/mesh_uvs.h"

#include <algorithm>
#include <unordered_map>

#include "rgb/mesh/face_location.h"
#include "rgb/mesh/mesh.h"
#include "rgb/mesh/vertex_rules.h"
#include "rgb/values/loop_geometry.h"
#include "rgb/values/uv_evaluator.h"

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
    constexpr std::uint32_t kNone = MeshUvs::kNone;
    const std::vector<std::uint32_t>& untextured = uvs.layout().channel().faces_without_uvs;
    MeshUvs out;
    // About one value per vertex, and as many for the coarser vertices their formulas read.
    uvs.reserve(2 * mesh.num_vertices());
    // Per vertex slot, the first value given to its corners: the only one for a vertex inside a base
    // face (computed once); a vertex on a seam has more, kept apart.
    std::vector<std::uint32_t> first(mesh.vertex_capacity(), kNone);
    std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> more;
    out.corners.assign(mesh.face_capacity(), {kNone, kNone, kNone});
    for (FaceId f : mesh.faces()) {
        if (!untextured.empty() && std::binary_search(untextured.begin(), untextured.end(), base_face_of(mesh, f))) continue;
        for (int c = 0; c < 3; ++c) {
            const VertexId v = mesh.face_vertices(f)[static_cast<std::size_t>(c)];
            std::uint32_t& id = out.corners[f.idx][static_cast<std::size_t>(c)];
            const bool single = !on_base_edge_or_vertex(mesh.address(v));
            if (first[v.idx] != kNone && single) {
                id = first[v.idx];
                continue;
            }
            const glm::dvec2 uv = limit ? limit_uv(mesh, uvs, f, c) : displayed_uv(mesh, uvs, f, c);
            id = static_cast<std::uint32_t>(out.values.size());
            if (first[v.idx] == kNone) {
                first[v.idx] = id;
            } else if (out.values[first[v.idx]] == uv) {
                id = first[v.idx];
                continue;
            } else {
                std::vector<std::uint32_t>& others = more[v.idx];
                const auto known = std::find_if(others.begin(), others.end(), [&](std::uint32_t k) { return out.values[k] == uv; });
                if (known != others.end()) {
                    id = *known;
                    continue;
                }
                others.push_back(id);
            }
            out.values.push_back(uv);
        }
    }
    return out;
}

}  // namespace rgb
