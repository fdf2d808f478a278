#pragma once
// Two meshes compared slot by slot: the same live face slots with the same corners, types and
// adjacency, the same live vertex slots with the same level, boundary flag, address and insertion
// position (bits). Stronger than same_mesh: what an exact undo must give back. Dead slots past the
// end of either mesh's arrays count as dead; a vertex's choice of outgoing halfedge is not compared
// (it is a navigation start, not part of what the mesh is).
#include <gtest/gtest.h>

#include "rgb/mesh/mesh.h"

namespace rgbtest {

testing::AssertionResult same_slots(const rgb::Mesh& a, const rgb::Mesh& b);

}  // namespace rgbtest
