#pragma once
// Building blocks for randomised tests: seeded choices of live elements and full coarsening.
#include <cstdint>
#include <random>

#include "rgb/mesh/mesh.h"

namespace rgbtest {

// A uniformly random live face / vertex (by slot), drawn from the raw mt19937 stream.
rgb::FaceId random_live_face(const rgb::Mesh& mesh, std::mt19937& rng);
rgb::VertexId random_live_vertex(const rgb::Mesh& mesh, std::mt19937& rng);

// Removes removable vertices, pass after pass in slot order, until a pass removes nothing.
// Returns the number of removals.
std::size_t remove_everything_removable(rgb::Mesh& mesh);

}  // namespace rgbtest
