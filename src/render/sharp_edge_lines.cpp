#include "render/sharp_edge_lines.h"

#include "render/surface_geometry.h"
#include "rgb/mesh/mesh.h"
#include "rgb/mesh/sharp_edges.h"

namespace render {

std::vector<glm::vec3> sharp_edge_lines(const rgb::Mesh& mesh, const SurfaceGeometry& geometry) {
    std::vector<glm::vec3> lines;
    // Semi-sharp edges are drawn too: their tag shapes the surface even where it has run out.
    for (const rgb::MeshSharpEdge& e : rgb::sharp_mesh_edges(mesh)) {
        lines.push_back(geometry.position(mesh.from_vertex(e.halfedge)));
        lines.push_back(geometry.position(mesh.to_vertex(e.halfedge)));
    }
    return lines;
}

}  // namespace render
