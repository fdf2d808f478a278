#include "rgb/values/restore_state.h"

#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "rgb/mesh/detail_positions.h"
#include "rgb/support/parallel.h"
#include "rgb/values/hierarchy_evaluator.h"
#include "rgb/values/hierarchy_positions.h"
#include "rgb/values/loop_geometry.h"

namespace rgb {

void set_sharp_features(Mesh& mesh, const SharpFeatures& features) {
    auto base = std::make_shared<const BaseMesh>(mesh.base().positions(), mesh.base().faces(), features, mesh.base().shared_detail());
    // Insertion positions by the new rules, from the base mesh (the evaluator caches what a vertex's
    // parents need, so this is linear in the vertices). Dead slots keep theirs.
    std::vector<glm::dvec3> insertion(mesh.vertex_capacity());
    for (std::uint32_t i = 0; i < insertion.size(); ++i) insertion[i] = mesh.insertion_position(VertexId(i));
    {
        HierarchyEvaluator evaluator(*base);
        for (VertexId v : mesh.vertices()) insertion[v.idx] = evaluator.insertion_position(mesh.address(v));
    }
    mesh.retag(std::move(base), std::move(insertion));
    // As restore_state leaves it: the limits the displayed positions need are cached.
    for (VertexId v : mesh.vertices())
        if (display_level(mesh, v) > mesh.level(v)) limit_position(mesh, v);
}

Mesh with_sharp_features(const Mesh& mesh, const SharpFeatures& features) {
    Mesh copy = mesh;
    set_sharp_features(copy, features);
    return copy;
}

// The topology first (mesh/state.h), then the insertion positions, coarsest first, by the split
// formula level by level, and last the invariants.
Mesh restore_state(const MeshState& s, const ProgressSpan& progress, RestoredChannel* channel, RestoredPositions* positions) {
    std::shared_ptr<const BaseMesh> base_mesh = restored_base_mesh(s);
    if (channel && channel->base_values.size() != s.base_positions.size())
        invalid_state("a vertex channel needs one value per base vertex (" + std::to_string(s.base_positions.size()) + "), not " +
                      std::to_string(channel->base_values.size()));
    const BaseMesh& base = *base_mesh;
    RestoredTopology topology = restore_topology(s, base_mesh, progress);
    Mesh& m = topology.mesh;
    const std::vector<SurfacePoint>& points = topology.points;
    const AddressIndex& index = topology.index;
    const std::size_t nv = s.vertices.size();
    // Insertion positions, coarsest first, by the split formula on the (present) parent stencil; and
    // the limits of the vertices displayed above their own level, which a viewer (and the loader's
    // check of a file's positions) needs at once.
    // The levels of a channel's values and of the positions asked for (vertex_channel.h).
    std::vector<std::uint8_t> displayed_above_own_level(nv), channel_levels(channel ? nv : 0), position_levels(positions ? nv : 0);
    auto level_of = [](ChannelLevel level, int shown) { return level == ChannelLevel::Limit ? kLimitLevel : static_cast<std::uint8_t>(shown); };
    parallel_for(nv, 1 << 15, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            const VertexId v(static_cast<std::uint32_t>(i));
            const int shown = display_level(m, v);
            displayed_above_own_level[i] = shown > m.level(v);
            if (channel) channel_levels[i] = level_of(channel->level, shown);
            if (positions) position_levels[i] = level_of(positions->level, shown);
        }
    });
    try {
        HierarchyPositions values =
            channel ? hierarchy_positions(base, points, index, displayed_above_own_level, position_levels,
                                          BaseMesh(channel->base_values, base.faces(), base.sharp_features()), channel_levels, channel->values)
                    : hierarchy_positions(base, points, index, displayed_above_own_level, position_levels);
        m.assign_insertion_positions(std::move(values.insertion));
        m.reserve_limits(values.limits.size());
        for (const HierarchyPositions::Limit& l : values.limits) m.cache_limit(VertexId(l.vertex), l.position);
        if (positions) positions->values = std::move(values.at_levels);
        // A cage with detail displays every vertex at its detail position (loop_geometry.h).
        if (positions && positions->level == ChannelLevel::Displayed && base.detail())
            parallel_for(nv, 1 << 12, [&](std::size_t begin, std::size_t end) {
                for (std::size_t i = begin; i < end; ++i) positions->values[i] = base.detail()->position(base, points[i]);
            });
    } catch (const std::invalid_argument& e) {
        invalid_state(e.what());
    }
    progress.reach(kRestorePositioned);
    check_restored(m, progress);
    progress.done();
    return std::move(m);
}

}  // namespace rgb
