#pragma once
// Where two adaptive states differ, bit for bit (doubles compared by their bytes, so -0 != +0):
// empty when they are identical. Shared by the tests (mesh_state_compare.h) and the loader's fuzz
// target, which has no GoogleTest.
#include <cstring>
#include <string>

#include "rgb/state.h"

namespace rgbio::test {

inline bool same_bits(const glm::dvec3& a, const glm::dvec3& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

inline std::string vertex_difference(const rgb::VertexState& x, const rgb::VertexState& y) {
    if (x.alive != y.alive) return "alive";
    if (x.level != y.level) return "level";
    if (x.boundary != y.boundary) return "boundary";
    if (!same_bits(x.insertion_position, y.insertion_position)) return "insertion position";
    if (x.limit.has_value() != y.limit.has_value()) return "whether the limit is known";
    if (x.limit && !same_bits(*x.limit, *y.limit)) return "limit position";
    return "";
}

inline std::string state_difference(const rgb::MeshState& a, const rgb::MeshState& b) {
    if (a.vertices.size() != b.vertices.size())
        return "vertex slots: " + std::to_string(a.vertices.size()) + " vs " + std::to_string(b.vertices.size());
    if (a.faces.size() != b.faces.size())
        return "face slots: " + std::to_string(a.faces.size()) + " vs " + std::to_string(b.faces.size());
    for (std::size_t i = 0; i < a.vertices.size(); ++i)
        if (const std::string what = vertex_difference(a.vertices[i], b.vertices[i]); !what.empty())
            return "vertex slot " + std::to_string(i) + ": " + what;
    for (std::size_t i = 0; i < a.faces.size(); ++i) {
        const rgb::FaceState &x = a.faces[i], &y = b.faces[i];
        if (x.alive != y.alive || x.v != y.v || !(x.type == y.type)) return "face slot " + std::to_string(i);
    }
    if (a.base_valence != b.base_valence) return "base valences";
    if (a.free_vertices != b.free_vertices) return "free vertex list";
    if (a.free_faces != b.free_faces) return "free face list";
    return "";
}

}  // namespace rgbio::test
