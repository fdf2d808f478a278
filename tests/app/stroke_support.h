#pragma once
// What the editor's end-to-end tests share: counting faces near a stroke.
#include <cstddef>
#include <span>

#include <glm/vec3.hpp>

#include "rgb/mesh/mesh.h"

namespace app::test {

// Faces with a corner within `radius` of one of `points` (displayed positions).
std::size_t faces_near(const rgb::Mesh& mesh, std::span<const glm::dvec3> points, double radius);

}  // namespace app::test
