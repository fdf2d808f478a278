#pragma once
// Base meshes for the core's tests: closed and open, valences 3 to 10, and a real scanned mesh.
// Vertex positions are jittered deterministically (except the tetrahedron of spec §9.3), so that
// symmetric cancellations cannot hide a wrong stencil.
#include <ostream>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "rgb/mesh/mesh.h"

namespace rgbtest {

struct TestMesh {
    std::string name;
    std::vector<glm::dvec3> positions;
    std::vector<rgb::Triangle> triangles;
};

// gtest prints parameters with this; the name is enough to tell which mesh failed.
inline void PrintTo(const TestMesh& m, std::ostream* os) { *os << m.name; }

rgb::Mesh make_rgb_mesh(const TestMesh& m);
double bounding_box_diagonal(const std::vector<glm::dvec3>& positions);

// Spec §9.3: v0 = (1,1,1), v1 = (1,-1,-1), v2 = (-1,1,-1), v3 = (-1,-1,1), exact coordinates.
TestMesh tetrahedron();
TestMesh octahedron();
TestMesh icosahedron();
// Two apexes of valence n over an n-gon (n >= 3); the equator vertices have valence 4.
TestMesh bipyramid(int n);
// The pentagonal bipyramid with a tag of every kind: apex 5 a corner (edge 5-0 infinitely sharp, 5-2
// and 5-3 of sharpness 1), equator vertex 0 a crease of sharpness 3 along 0-1.
rgb::BaseMesh tagged_bipyramid();
// An open disc: one interior vertex of valence n, n boundary vertices.
TestMesh fan(int n);
// An open nx-by-ny grid of quads, each cut into two triangles (interior valence 6, boundary 3 or 4,
// corners 2 or 3).
TestMesh grid(int nx, int ny);
// A closed slab of nx-by-ny cells with a square hole through every `every`-th cell in both
// directions: genus = number of holes. Cells are split into two triangles on each face.
TestMesh perforated_slab(int nx, int ny, int every);
// An open grid with a square hole at every `every`-th cell: several boundary loops.
TestMesh grid_with_holes(int nx, int ny, int every);
// One triangle (0, 1, 2): every edge on the boundary.
TestMesh single_triangle();
// A plain ring torus (radii 1 and 0.4), `around` segments around its axis and `tube` around its tube,
// not jittered: the smooth closed surface of genus 1 that users refine to a tolerance.
TestMesh torus(int around, int tube);
// assets/bunny.obj: 1839 vertices, 3674 triangles, closed.
TestMesh bunny();

// The same surface stored differently: each triangle's corners rotated by one, the triangle list
// reversed, or the vertices renumbered by a seeded shuffle.
TestMesh with_rotated_corners(const TestMesh& m);
TestMesh with_reversed_faces(const TestMesh& m);
TestMesh with_shuffled_vertices(const TestMesh& m, std::uint32_t seed);

// The small meshes most tests iterate over: tetrahedron, octahedron, icosahedron, bipyramids
// n = 3..10, fans n = 5, 6, 7, a 3x2 grid, a single triangle.
std::vector<TestMesh> small_meshes();

}  // namespace rgbtest
