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

std::vector<glm::dvec3> vertex_channel_values(const Mesh& mesh, std::span<const glm::dvec3> base_values, ChannelLevel level) {
    const BaseMesh& base = mesh.base();
    if (base_values.size() != base.num_vertices())
        throw std::invalid_argument("a vertex channel needs one value per base vertex (" + std::to_string(base.num_vertices()) +
                                    "), not " + std::to_string(base_values.size()));
    // The channel's values stand in for the positions: same faces, same tags, so the same rules.
    const BaseMesh channel(base_values, base.faces(), base.sharp_features());
    std::vector<glm::dvec3> values(mesh.vertex_capacity(), glm::dvec3(0.0));
    // Blocks of consecutive slots: vertices made together are neighbours and share the values their
    // formulas need, which each block's evaluator caches.
    parallel_for(mesh.vertex_capacity(), std::size_t(1) << 14, [&](std::size_t begin, std::size_t end) {
        // Its values are only a cache: started afresh when large, so memory stays bounded.
        constexpr std::size_t kMaxValues = std::size_t(1) << 18;
        std::unique_ptr<HierarchyEvaluator> evaluator;
        for (std::size_t i = begin; i < end; ++i) {
            const VertexId v(static_cast<std::uint32_t>(i));
            if (!mesh.is_live(v)) continue;
            if (!evaluator || evaluator->cached_values() > kMaxValues) evaluator = std::make_unique<HierarchyEvaluator>(channel);
            const SurfacePoint p = mesh.address(v);
            values[i] = level == ChannelLevel::Limit ? evaluator->limit_position(p) : evaluator->control_point(p, display_level(mesh, v));
        }
    });
    return values;
}

}  // namespace rgb
