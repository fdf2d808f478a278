#pragma once
// The setting of the operator tests: an octahedron (every edge interior, every vertex of valence 4)
// and one of its edges a-b with the two faces (a, b, x) and (b, a, y), as in spec §2.1.
#include <utility>

#include "rgb/mesh/mesh.h"
#include "support/test_meshes.h"

namespace rgbtest {

struct OctahedronEdge {
    TestMesh base = octahedron();
    rgb::Mesh mesh = make_rgb_mesh(base);
    rgb::VertexId a{0}, b{2};
    rgb::VertexId x = mesh.opposite_vertex(mesh.find_halfedge(a, b));
    rgb::VertexId y = mesh.opposite_vertex(mesh.find_halfedge(b, a));

    // Makes both sides of a-b red: the side (a,b,x) by splitting b-x (its red edge then reaches a-b
    // at a), the side (b,a,y) by splitting a-y (red edge at b: the RR-split "opposite" case) or y-b
    // (red edge at a: the "same" case). Returns the midpoints of b-x and of the second edge.
    std::pair<rgb::VertexId, rgb::VertexId> make_both_sides_red(bool same);
};

}  // namespace rgbtest
