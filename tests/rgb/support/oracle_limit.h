#pragma once
// The Loop limit position of a vertex of an adaptive mesh, computed independently of the core: the
// vertex is found in the uniform Loop oracle by its insertion position, and Loop's limit mask (with
// its own copy of the weights) is applied to its ring in the oracle's mesh of its level.
#include <glm/vec3.hpp>

#include "rgb/mesh/mesh.h"
#include "support/uniform_loop_oracle.h"

namespace rgbtest {

glm::dvec3 oracle_limit(const UniformLoopOracle& oracle, const rgb::Mesh& mesh, rgb::VertexId v);

}  // namespace rgbtest
