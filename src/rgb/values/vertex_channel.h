#pragma once
// Vertex data that subdivides exactly as positions do (vertex colours, `v x y z r g b`): Loop's vertex
// rules are linear in the values, so a channel's value at any vertex of the hierarchy is what the
// position formulas give with the base vertices' channel values in place of their positions: the
// same stencils, crease rules and closed forms, the same order independence. The values are
// computed from the base mesh by the hierarchy evaluator (hierarchy_evaluator.h), never carried
// through the operators, so no operator knows about channels.
#include <memory>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "rgb/mesh/base_mesh.h"
#include "rgb/mesh/handles.h"

namespace rgb {

class HierarchyEvaluator;
class Mesh;

enum class ChannelLevel {
    Displayed,  // at each vertex's display level, as displayed_position
    Limit,      // the limit, as limit_position
};

// A channel's value at single vertices, for callers that follow a changing mesh (the editor's
// display): the same bits as vertex_channel_values. Valid for meshes over the base mesh it was made
// for (the same faces and tags).
class VertexChannel {
public:
    // Throws std::invalid_argument if base_values does not have one value per base vertex.
    VertexChannel(const BaseMesh& base, std::span<const glm::dvec3> base_values);
    ~VertexChannel();
    VertexChannel(const VertexChannel&) = delete;
    VertexChannel& operator=(const VertexChannel&) = delete;

    // v's value (v live); not thread-safe (it caches what it computes).
    glm::dvec3 value(const Mesh& mesh, VertexId v, ChannelLevel level);

private:
    BaseMesh channel_;
    std::unique_ptr<HierarchyEvaluator> evaluator_;
};

// One value per vertex slot of `mesh` (dead slots get 0), from one value per base vertex. Throws
// std::invalid_argument if base_values does not have one value per base vertex.
std::vector<glm::dvec3> vertex_channel_values(const Mesh& mesh, std::span<const glm::dvec3> base_values, ChannelLevel level);

}  // namespace rgb
