#pragma once
// The result of reading an OBJ file, before any rgb::Mesh exists: a clean, consistently oriented
// manifold triangle mesh without unreferenced vertices, plus what was fixed along the way.
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "rgb/mesh.h"
#include "rgb/state.h"

namespace rgbio {

struct LoadedMesh {
    std::vector<glm::dvec3> positions;
    std::vector<rgb::Triangle> triangles;
    std::vector<std::string> warnings;  // fixes and ignored content, one readable sentence each
    // Present when the file was saved by rgbsub with its adaptive state: the mesh to restore.
    // positions/triangles then are the file's plain OBJ content (what other programs see).
    std::optional<rgb::MeshState> state;
};

}  // namespace rgbio
