#pragma once
// Where two adaptive states differ: empty when they are identical. Base positions are compared bit
// for bit (by their bytes, so -0 != +0 and a changed last bit shows), then the base triangles, the
// crease and corner tags with the boundary rule, each vertex's address in the hierarchy and the faces. Shared by the io tests and the loader's fuzz
// target, which has no GoogleTest.
#include <cstring>
#include <string>

#include "rgb/mesh/state.h"

namespace rgbio::test {

inline bool same_bits(const glm::dvec3& a, const glm::dvec3& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

inline std::string state_difference(const rgb::MeshState& a, const rgb::MeshState& b) {
    const auto count = [](const char* what, std::size_t x, std::size_t y) {
        return std::string(what) + ": " + std::to_string(x) + " vs " + std::to_string(y);
    };
    if (a.base_positions.size() != b.base_positions.size()) return count("base vertices", a.base_positions.size(), b.base_positions.size());
    if (a.base_triangles.size() != b.base_triangles.size()) return count("base triangles", a.base_triangles.size(), b.base_triangles.size());
    if (a.vertices.size() != b.vertices.size()) return count("vertices", a.vertices.size(), b.vertices.size());
    if (a.faces.size() != b.faces.size()) return count("faces", a.faces.size(), b.faces.size());
    for (std::size_t i = 0; i < a.base_positions.size(); ++i)
        if (!same_bits(a.base_positions[i], b.base_positions[i])) return "base vertex " + std::to_string(i) + "'s position";
    for (std::size_t i = 0; i < a.base_triangles.size(); ++i)
        if (a.base_triangles[i] != b.base_triangles[i]) return "base triangle " + std::to_string(i);
    if (a.sharp_features.edges != b.sharp_features.edges) return "crease tags";
    if (a.sharp_features.corners != b.sharp_features.corners) return "corner tags";
    if (a.sharp_features.boundary != b.sharp_features.boundary) return "boundary rule";
    for (std::size_t i = 0; i < a.vertices.size(); ++i)
        if (!(a.vertices[i] == b.vertices[i])) return "vertex " + std::to_string(i) + "'s address";
    for (std::size_t i = 0; i < a.faces.size(); ++i)
        if (a.faces[i] != b.faces[i]) return "face " + std::to_string(i);
    return "";
}

}  // namespace rgbio::test
