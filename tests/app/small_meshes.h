#pragma once
// Meshes built in code for the editor's tests, small enough to reason about by hand.
#include <filesystem>
#include <string>

#include "rgb/mesh/mesh.h"

namespace app::test {

// The corner tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1), oriented outwards.
rgb::Mesh tetrahedron();

// Two separate n x n grids of the square [-1,1]^2, at y = 0 and y = gap, both facing +y: a sheet
// lying right under another, as a folded or layered surface has.
rgb::Mesh stacked_sheets(int n, double gap);

// A slightly bumpy torus of 2 * n * m triangles (n around the hole, m around the tube), written as
// `folder`/torus_<triangles>.obj; returns its path. A dense mesh for the cage tests.
std::string write_torus(const std::filesystem::path& folder, int n, int m);

}  // namespace app::test
