#pragma once
// Two adaptive meshes compared as what a user gets: the same triangles (each with its colour, level
// and red edge) over the same displayed positions, bit for bit, whatever the vertex and face slots.
// Positions are the only identity that survives a different storage order of the input, so faces
// are matched by their corners' positions.
#include <gtest/gtest.h>

#include "rgb/mesh/mesh.h"

namespace rgbtest {

testing::AssertionResult same_mesh(const rgb::Mesh& a, const rgb::Mesh& b);

}  // namespace rgbtest
