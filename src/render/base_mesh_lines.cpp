#include "render/base_mesh_lines.h"

#include <algorithm>
#include <utility>

#include "rgb/mesh/mesh.h"
#include "rgb/mesh/navigation.h"

namespace render {

std::vector<glm::vec3> base_mesh_lines(const rgb::Mesh& mesh) {
    // The uniform ring at level 0 lists a base vertex's base neighbours however refined the mesh is
    // now. A boundary vertex's ring holds only its boundary neighbours, so collect the edges from both
    // ends: an edge joining two boundary vertices through the interior is the one kind not drawn.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (std::uint32_t i = 0; i < mesh.num_base_vertices(); ++i)
        for (rgb::VertexId u : rgb::uniform_ring(mesh, rgb::VertexId(i))) edges.emplace_back(std::min(i, u.idx), std::max(i, u.idx));
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());

    std::vector<glm::vec3> lines;
    lines.reserve(2 * edges.size());
    for (const auto& [a, b] : edges) {
        lines.emplace_back(mesh.insertion_position(rgb::VertexId(a)));
        lines.emplace_back(mesh.insertion_position(rgb::VertexId(b)));
    }
    return lines;
}

}  // namespace render
