#pragma once
// Small meshes built in code for the renderer tests.
#include "rgb/mesh/mesh.h"

namespace render_test {

// A unit icosahedron subdivided `subdivisions` times by edge midpoints pushed onto the unit sphere,
// then scaled by `scale`.
rgb::Mesh icosphere(int subdivisions, double scale = 1.0);
// An n x n grid of quads (two triangles each) covering [-1, 1]^2 in the plane y = 0, facing +y.
rgb::Mesh grid(int n);

}  // namespace render_test
