#include "rgb/vertex_channel.h"

#include <memory>
#include <stdexcept>
#include <string>

#include "rgb/base_mesh.h"
#include "rgb/hierarchy_evaluator.h"
#include "rgb/loop_geometry.h"
#include "rgb/mesh.h"
#include "rgb/parallel.h"

namespace rgb {

namespace {

// The evaluator's values are only a cache: started afresh when large, so memory stays bounded.
constexpr std::size_t kMaxCachedValues = std::size_t(1) << 18;

// The channel's values stand in for the positions: same faces, same tags, so the same rules.
BaseMesh channel_mesh(const BaseMesh& base, std::span<const glm::dvec3> base_values) {
    if (base_values.size() != base.num_vertices())
        throw std::invalid_argument("a vertex channel needs one value per base vertex (" + std::to_string(base.num_vertices()) +
                                    "), not " + std::to_string(base_values.size()));
    return BaseMesh(base_values, base.faces(), base.sharp_features());
}

// v's value through `evaluator` over `channel`, replaced first when it holds too much.
glm::dvec3 evaluate(std::unique_ptr<HierarchyEvaluator>& evaluator, const BaseMesh& channel, const Mesh& mesh, VertexId v,
                    ChannelLevel level) {
    if (!evaluator || evaluator->cached_values() > kMaxCachedValues) evaluator = std::make_unique<HierarchyEvaluator>(channel);
    const SurfacePoint p = mesh.address(v);
    return level == ChannelLevel::Limit ? evaluator->limit_position(p) : evaluator->control_point(p, display_level(mesh, v));
}

}  // namespace

VertexChannel::VertexChannel(const BaseMesh& base, std::span<const glm::dvec3> base_values)
    : channel_(channel_mesh(base, base_values)) {}

VertexChannel::~VertexChannel() = default;

glm::dvec3 VertexChannel::value(const Mesh& mesh, VertexId v, ChannelLevel level) {
    return evaluate(evaluator_, channel_, mesh, v, level);
}

std::vector<glm::dvec3> vertex_channel_values(const Mesh& mesh, std::span<const glm::dvec3> base_values, ChannelLevel level) {
    const BaseMesh channel = channel_mesh(mesh.base(), base_values);
    std::vector<glm::dvec3> values(mesh.vertex_capacity(), glm::dvec3(0.0));
    // Blocks of consecutive slots: vertices made together are neighbours and share the values their
    // formulas need, which each block's evaluator caches.
    parallel_for(mesh.vertex_capacity(), std::size_t(1) << 14, [&](std::size_t begin, std::size_t end) {
        std::unique_ptr<HierarchyEvaluator> evaluator;
        for (std::size_t i = begin; i < end; ++i) {
            const VertexId v(static_cast<std::uint32_t>(i));
            if (mesh.is_live(v)) values[i] = evaluate(evaluator, channel, mesh, v, level);
        }
    });
    return values;
}

}  // namespace rgb
