#pragma once
// The UVs an adaptive mesh displays (docs/loop-face-varying.md): a corner shows its vertex's UV
// value on the side of the base face its triangle lies in, at the vertex's display level
// (loop_geometry.h), so a mesh's UVs are those of the uniform mesh its vertices are displayed at.
#include <array>
#include <vector>

#include <glm/vec2.hpp>

#include "rgb/mesh/handles.h"

namespace rgb {

class Mesh;
class UvEvaluator;

glm::dvec2 displayed_uv(const Mesh& mesh, UvEvaluator& uvs, FaceId f, int corner);
// The same corner's UV on the limit surface (beside limit positions).
glm::dvec2 limit_uv(const Mesh& mesh, UvEvaluator& uvs, FaceId f, int corner);

// The UVs of a mesh as face-varying data: distinct values, and per face slot (dead slots included)
// the value of each corner, or kNone for the faces of a base face without UVs
// (UvChannel::faces_without_uvs). Corners of one vertex share a value where their UVs are the same bits.
struct MeshUvs {
    static constexpr std::uint32_t kNone = 0xffffffffu;
    std::vector<glm::dvec2> values;
    std::vector<std::array<std::uint32_t, 3>> corners;
};
// `limit`: limit UVs instead of displayed ones.
MeshUvs mesh_uvs(const Mesh& mesh, UvEvaluator& uvs, bool limit = false);

}  // namespace rgb
