#pragma once
// The edges of an adaptive mesh that lie on tagged interior base edges: what the renderer draws as
// sharp lines and what an OBJ file's tag lines describe. Boundary edges are sharp without a tag and
// are not listed.
#include <vector>

#include "rgb/mesh/handles.h"

namespace rgb {

class Mesh;

struct MeshSharpEdge {
    HalfedgeId halfedge;   // one of the edge's halfedges
    int base_sharpness;    // the tag of the base edge it lies on (1-10)
    int sharpness;         // at the edge's level by uniform creasing: 10 stays 10, else the tag minus
                           // the level (0 and below: no longer sharp)
};

// Each such edge once, in face slot order. Empty (and cheap) for a base mesh without tagged edges.
std::vector<MeshSharpEdge> sharp_mesh_edges(const Mesh& mesh);

}  // namespace rgb
