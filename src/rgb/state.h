#pragma once
// The complete adaptive state of a Mesh as plain arrays, slot for slot (dead slots and free-list
// order included), so that a restored mesh behaves bit for bit like the original under any further
// operation. Used by io (persistence in OBJ comments) and by the editor (undo snapshots).
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "rgb/face_type.h"

namespace rgb {

class Mesh;

struct VertexState {
    bool alive = false;
    int level = 0;
    bool boundary = false;
    glm::dvec3 insertion_position{0.0};
    std::optional<glm::dvec3> limit;
};

struct FaceState {
    bool alive = false;
    std::array<std::uint32_t, 3> v{};
    FaceType type;
};

struct MeshState {
    std::vector<VertexState> vertices;        // by slot
    std::vector<FaceState> faces;             // by slot
    std::vector<std::uint16_t> base_valence;  // one per base vertex (slots 0..n0-1)
    std::vector<std::uint32_t> free_vertices; // free lists, in order
    std::vector<std::uint32_t> free_faces;
};

MeshState capture_state(const Mesh& mesh);
// Rebuilds adjacency from the faces. Throws std::invalid_argument with a readable reason if the state
// is not a valid RGB triangulation (io turns that into a file error).
Mesh restore_state(const MeshState& state);

}  // namespace rgb
