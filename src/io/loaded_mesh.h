#pragma once
// The result of reading an OBJ file: a clean, consistently oriented manifold triangle mesh without
// unreferenced vertices, plus what was fixed along the way, and the adaptive mesh when the file holds
// an rgbsub state that reproduces it exactly.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "rgb/mesh.h"

namespace rgbio {

struct LoadedMesh {
    std::vector<glm::dvec3> positions;
    std::vector<rgb::Triangle> triangles;
    std::vector<std::string> warnings;  // fixes and ignored content, one readable sentence each
    // Present when the file was saved by rgbsub with its adaptive state and the state gives back the
    // file's v and f lines exactly: the adaptive mesh. positions/triangles then are the file's plain
    // OBJ content (what other programs see).
    std::shared_ptr<rgb::Mesh> adaptive;
};

}  // namespace rgbio
