#pragma once
// Comparing a mesh's vertex positions with a list of expected ones (the v lines of a saved file) bit
// for bit, on all cores. Loop positions fill the mesh's limit cache on demand (loop_geometry.h), which
// threads must not race on, so the limits the comparison needs are cached first, on one thread (a
// restored mesh has them already: state.h).
#include <cstddef>
#include <span>

#include <glm/vec3.hpp>

namespace rgb {

class Mesh;

// How many live vertices, in slot order, have a displayed position (limit_positions: a limit
// position) other than expected[i]. Requires expected.size() == mesh.num_vertices().
std::size_t count_differing_positions(const Mesh& mesh, std::span<const glm::dvec3> expected, bool limit_positions);

}  // namespace rgb
