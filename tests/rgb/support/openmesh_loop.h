#pragma once
// Uniform Loop subdivision by OpenMesh's LoopT (original weights, like the spec), in double precision,
// as an external reference for refine_uniform.
#include "support/test_meshes.h"

namespace rgbtest {

// k steps of OpenMesh::Subdivider::Uniform::LoopT on the mesh; returns the subdivided mesh.
TestMesh openmesh_loop(const TestMesh& base, int k);

}  // namespace rgbtest
