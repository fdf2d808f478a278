#pragma once
// Operator calls for configuration tests that first check which operator the core says applies.
#include "rgb/mesh/mesh.h"
#include "rgb/mesh/operators.h"

namespace rgbtest {

// Splits the edge {a, b} after expecting split_kind == `expected`;
// returns the new vertex.
rgb::VertexId split_checked(rgb::Mesh& mesh, rgb::VertexId a, rgb::VertexId b, rgb::SplitKind expected);

}  // namespace rgbtest
