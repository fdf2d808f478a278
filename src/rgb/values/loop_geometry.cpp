#include "rgb/values/loop_geometry.h"

#include <algorithm>
#include <array>
#include <memory>
#include <vector>

#include "rgb/mesh/detail_positions.h"
#include "rgb/mesh/mesh.h"
#include "rgb/mesh/navigation.h"
#include "rgb/mesh/vertex_rules.h"
#include "rgb/rules/loop_rules.h"
#include "rgb/values/hierarchy_evaluator.h"

namespace rgb {

namespace {

// The limit from v's ring in the current mesh, if the mesh holds that ring.
std::optional<glm::dvec3> limit_from_ring(const Mesh& mesh, VertexId v) {
    const std::vector<VertexId> ring = uniform_ring(mesh, v);
    if (ring.empty()) return std::nullopt;
    const int l = mesh.level(v);
    const glm::dvec3& centre = mesh.insertion_position(v);
    if (mesh.is_boundary(v)) return boundary_limit(centre, control_point(mesh, ring[0], l), control_point(mesh, ring[1], l));
    std::vector<glm::dvec3> points;
    points.reserve(ring.size());
    for (VertexId w : ring) points.push_back(control_point(mesh, w, l));
    return interior_limit(centre, points);
}

// One evaluator per thread and base mesh, kept between calls: neighbouring vertices share most of
// the hierarchy values they need. Its values are only a cache, so it starts afresh when it grows large.
HierarchyEvaluator& shared_evaluator(const BaseMesh& base) {
    constexpr std::size_t kMaxValues = std::size_t(1) << 18;
    thread_local std::unique_ptr<HierarchyEvaluator> evaluator;
    thread_local std::uint64_t serial = 0;
    if (!evaluator || serial != base.serial() || evaluator->cached_values() > kMaxValues) {
        evaluator = std::make_unique<HierarchyEvaluator>(base);
        serial = base.serial();
    }
    return *evaluator;
}

// Whether the base mesh's tags change v's rules (vertex_rules.h). Such a vertex takes its values
// from the hierarchy evaluator, so that they do not depend on what the mesh holds around it.
bool tagged(const Mesh& mesh, VertexId v) {
    return mesh.base().has_sharp_features() && !follows_untagged_rules(mesh.base(), mesh.address(v));
}

// p^k(v) for k > level(v), the limit given by `limit` (cached or not).
template <class Limit>
glm::dvec3 later_control_point(const Mesh& mesh, VertexId v, int k, Limit&& limit) {
    if (!tagged(mesh, v)) return untagged_control_point(mesh, v, k, limit());
    const int l = mesh.level(v);
    // One rule with a two-term closed form (a crease or corner for ever): spec §4.2's form with the
    // rule's eigenvalue, from the cached limit. Otherwise the closed forms of several regimes or a
    // dart's mask: the evaluator's, which computes the same bits for the single-rule case.
    const Regimes regimes = vertex_regimes(mesh.base(), mesh.address(v));
    const VertexRule rule = regimes[0].rule;
    if (regimes.size() == 1 && (rule == VertexRule::Crease || rule == VertexRule::Corner))
        return closed_form(mesh.insertion_position(v), limit(), rule == VertexRule::Crease ? loop_gamma(0, true) : 0.0, k - l);
    return shared_evaluator(mesh.base()).control_point(mesh.address(v), k);
}

}  // namespace

glm::dvec3 limit_position_uncached(const Mesh& mesh, VertexId v) {
    if (auto known = mesh.cached_limit(v)) return *known;
    if (!tagged(mesh, v))
        if (auto limit = limit_from_ring(mesh, v)) return *limit;
    return shared_evaluator(mesh.base()).limit_position(mesh.address(v));
}

glm::dvec3 limit_position(const Mesh& mesh, VertexId v) {
    if (auto known = mesh.cached_limit(v)) return *known;
    const glm::dvec3 limit = limit_position_uncached(mesh, v);
    mesh.cache_limit(v, limit);
    return limit;
}

void limit_position_where_uniform(const Mesh& mesh, VertexId v) {
    if (!mesh.has_cached_limit(v) && ring_is_direct(mesh, v)) limit_position(mesh, v);
}

glm::dvec3 untagged_control_point(const Mesh& mesh, VertexId v, int k, const glm::dvec3& limit) {
    return closed_form(mesh.insertion_position(v), limit, loop_gamma(mesh.uniform_valence(v), mesh.is_boundary(v)), k - mesh.level(v));
}

glm::dvec3 control_point(const Mesh& mesh, VertexId v, int k) {
    if (k <= mesh.level(v)) return mesh.insertion_position(v);
    return later_control_point(mesh, v, k, [&] { return limit_position(mesh, v); });
}

glm::dvec3 control_point(const Mesh& mesh, VertexId v, int k, const glm::dvec3& limit) {
    if (k <= mesh.level(v)) return mesh.insertion_position(v);
    return later_control_point(mesh, v, k, [&] { return limit; });
}

int display_level(const Mesh& mesh, VertexId v) {
    int lowest = 255;
    const HalfedgeId start = mesh.vertex_halfedge(v);
    HalfedgeId h = start;
    do {
        lowest = std::min({lowest, mesh.edge_type(h).level, mesh.edge_type(Mesh::prev(h)).level});
        h = mesh.ccw_rotated(h);
    } while (h.valid() && h != start);
    return std::max(mesh.level(v), lowest);
}

std::vector<std::uint8_t> display_levels(const Mesh& mesh) {
    // The lowest edge level at each corner (its two edges), kept per vertex; then raised to the
    // vertex's own level, as display_level does.
    std::vector<std::uint8_t> levels(mesh.vertex_capacity(), 0xff);
    for (FaceId f : mesh.faces()) {
        std::array<int, 3> edge{};
        for (int i = 0; i < 3; ++i) edge[static_cast<std::size_t>(i)] = mesh.edge_type(Mesh::halfedge(f, i)).level;
        for (std::size_t c = 0; c < 3; ++c) {
            std::uint8_t& lowest = levels[mesh.face_vertices(f)[c].idx];
            lowest = static_cast<std::uint8_t>(std::min({int(lowest), edge[c], edge[(c + 2) % 3]}));
        }
    }
    for (std::uint32_t i = 0; i < levels.size(); ++i) {
        const VertexId v(i);
        levels[i] = mesh.is_live(v) ? static_cast<std::uint8_t>(std::max(mesh.level(v), int(levels[i]))) : 0;
    }
    return levels;
}

glm::dvec3 displayed_position(const Mesh& mesh, VertexId v) { return displayed_position(mesh, v, display_level(mesh, v)); }

glm::dvec3 displayed_position(const Mesh& mesh, VertexId v, int k) {
    if (const DetailPositions* detail = mesh.base().detail()) return detail->position(mesh.base(), mesh.address(v));
    if (k <= mesh.level(v)) return mesh.insertion_position(v);
    return later_control_point(mesh, v, k, [&] { return limit_position_uncached(mesh, v); });
}

}  // namespace rgb
