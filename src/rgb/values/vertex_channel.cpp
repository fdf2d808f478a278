#include "rgb/values/vertex_channel.h"

#include <memory>
#include <stdexcept>
#include <string>

#include "rgb/mesh/address_index.h"
#include "rgb/mesh/base_mesh.h"
#include "rgb/mesh/mesh.h"
#include "rgb/support/parallel.h"
#include "rgb/values/hierarchy_evaluator.h"
#include "rgb/values/hierarchy_positions.h"
#include "rgb/values/loop_geometry.h"

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

}  // namespace

VertexChannel::VertexChannel(const BaseMesh& base, std::span<const glm::dvec3> base_values)
    : channel_(channel_mesh(base, base_values)) {}

VertexChannel::~VertexChannel() = default;

glm::dvec3 VertexChannel::value(const Mesh& mesh, VertexId v, ChannelLevel level) {
    if (!evaluator_ || evaluator_->cached_values() > kMaxCachedValues) evaluator_ = std::make_unique<HierarchyEvaluator>(channel_);
    const SurfacePoint p = mesh.address(v);
    return level == ChannelLevel::Limit ? evaluator_->limit_position(p) : evaluator_->control_point(p, display_level(mesh, v));
}

std::vector<glm::dvec3> vertex_channel_values(const Mesh& mesh, std::span<const glm::dvec3> base_values, ChannelLevel level) {
    const BaseMesh& base = mesh.base();
    const BaseMesh channel = channel_mesh(base, base_values);
    // The live vertices, numbered densely in slot order; base vertices keep their slots 0..n0-1, as
    // hierarchy_values needs.
    std::vector<std::uint32_t> slots;
    slots.reserve(mesh.num_vertices());
    for (VertexId v : mesh.vertices()) slots.push_back(v.idx);
    std::vector<SurfacePoint> points(slots.size());
    std::vector<std::uint8_t> levels(slots.size());
    parallel_for(slots.size(), std::size_t(1) << 15, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            const VertexId v(slots[i]);
            points[i] = mesh.address(v);  // canonical, as the mesh stores them
            levels[i] = level == ChannelLevel::Limit ? kLimitLevel : static_cast<std::uint8_t>(display_level(mesh, v));
        }
    });
    // A mesh holds the parent triangles of each of its vertices, so no value is missing.
    const std::vector<glm::dvec3> dense = hierarchy_values(channel, points, AddressIndex(points, base.num_faces()), levels);
    std::vector<glm::dvec3> values(mesh.vertex_capacity(), glm::dvec3(0.0));
    for (std::size_t i = 0; i < slots.size(); ++i) values[slots[i]] = dense[i];
    return values;
}

}  // namespace rgb
