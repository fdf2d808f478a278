#pragma once
// Crease tags from the shape of the base mesh (issue 13's --sharp-angle): every interior base edge
// whose two face normals differ by more than a given angle, the convention of Blender's auto smooth
// (a flat edge has angle 0, a right-angled one 90).
#include <vector>

#include "rgb/mesh/base_mesh.h"

namespace rgb {

// The angle in degrees between the normals of the two faces of the interior edge of halfedge h;
// 0 if either face has no area (no normal to compare).
double dihedral_angle_degrees(const BaseMesh& base, std::uint32_t h);

// Infinitely sharp tags on the interior edges whose angle exceeds `degrees`, each once, sorted.
std::vector<EdgeSharpness> edges_sharper_than(const BaseMesh& base, double degrees);

}  // namespace rgb
