#pragma once
// The edges of the base mesh Σ0 as line segments (GL-free), for the base mesh overlay. Base vertices
// are never removed and keep their level-0 positions, so the cage is fixed for a mesh's lifetime.
#include <vector>

#include <glm/vec3.hpp>

namespace rgb {
class Mesh;
}

namespace render {

// Endpoint pairs, one pair per base edge, ordered by vertex ids.
std::vector<glm::vec3> base_mesh_lines(const rgb::Mesh& mesh);

}  // namespace render
