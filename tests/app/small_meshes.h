#pragma once
// Meshes built in code for the editor's tests, small enough to reason about by hand.
#include "rgb/mesh/mesh.h"

namespace app::test {

// The corner tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1), oriented outwards.
rgb::Mesh tetrahedron();

// Two separate n x n grids of the square [-1,1]^2, at y = 0 and y = gap, both facing +y: a sheet
// lying right under another, as a folded or layered surface has.
rgb::Mesh stacked_sheets(int n, double gap);

}  // namespace app::test
