#pragma once
// Two adaptive meshes compared as what a user gets: the same triangles (each with its colour, level
// and red edge) over the same displayed positions, bit for bit, whatever the vertex and face slots.
// Positions are the only identity that survives a different storage order of the input, so faces
// are matched by their corners' positions.
#include <set>
#include <tuple>

#include <gtest/gtest.h>

#include "rgb/mesh/mesh.h"

namespace rgbtest {

testing::AssertionResult same_mesh(const rgb::Mesh& a, const rgb::Mesh& b);

// The vertex set of a mesh as base-space points (x, y, z), comparable across storages and histories.
using BaseSpacePoint = std::tuple<double, double, double>;
std::set<BaseSpacePoint> base_space_vertex_set(const rgb::Mesh& mesh);

}  // namespace rgbtest
