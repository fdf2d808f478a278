#pragma once
// The mesh's edges along tagged base edges (rgb/mesh/sharp_edges.h) as line segments at the positions the
// surface shows (GL-free), so that creases are drawn as coloured lines over the surface.
#include <vector>

#include <glm/vec3.hpp>

namespace rgb {
class Mesh;
}

namespace render {

class SurfaceGeometry;

// Endpoint pairs, one pair per edge; empty for a base mesh without tagged edges.
std::vector<glm::vec3> sharp_edge_lines(const rgb::Mesh& mesh, const SurfaceGeometry& geometry);

}  // namespace render
