#include "app/crease_tool.h"

#include <algorithm>
#include <limits>
#include <unordered_set>

#include <glm/geometric.hpp>

#include "render/surface_geometry.h"
#include "rgb/mesh/sharp_angle.h"
#include "rgb/mesh/vertex_rules.h"
#include "rgb/support/triangle_geometry.h"

namespace app {

namespace {

double distance_to_segment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 ab = b - a;
    const double length2 = glm::dot(ab, ab);
    const double t = length2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
    return glm::distance(p, a + t * ab);
}

// The sharpness the tags give the edge now (0: untagged).
int tag_of(const rgb::SharpFeatures& features, const BaseEdge& edge) {
    for (const rgb::EdgeSharpness& e : features.edges)
        if (e.a == edge.first && e.b == edge.second) return e.sharpness;
    return 0;
}

// Live faces that come within `radius` of `centre` as drawn and are connected to `seed` through such
// faces: the few faces around the cursor.
std::vector<rgb::FaceId> faces_within(const rgb::Mesh& mesh, const render::SurfaceGeometry& geometry, rgb::FaceId seed,
                                      const glm::dvec3& centre, double radius) {
    std::vector<rgb::FaceId> found;
    if (!mesh.is_live(seed) || seed.idx >= geometry.face_slots()) return found;
    std::unordered_set<std::uint32_t> visited{seed.idx};
    found.push_back(seed);
    for (std::size_t next = 0; next < found.size(); ++next) {
        for (int i = 0; i < 3; ++i) {
            const rgb::HalfedgeId opposite = mesh.opposite(rgb::Mesh::halfedge(found[next], i));
            if (!opposite.valid()) continue;
            const rgb::FaceId g = rgb::Mesh::face(opposite);
            if (!visited.insert(g.idx).second) continue;
            const auto t = geometry.corners(g);
            if (rgb::distance_to_triangle(centre, t[0], t[1], t[2]) <= radius) found.push_back(g);
        }
    }
    return found;
}

}  // namespace

std::optional<BaseEdge> base_edge_near(const rgb::Mesh& mesh, const render::SurfaceGeometry& geometry,
                                       const SurfaceHit& hit, double reach_world) {
    const rgb::BaseMesh& base = mesh.base();
    std::optional<BaseEdge> nearest;
    double best = std::numeric_limits<double>::infinity();
    for (rgb::FaceId f : faces_within(mesh, geometry, hit.face, hit.point, reach_world)) {
        const std::array<glm::dvec3, 3> drawn = geometry.corners(f);
        for (int i = 0; i < 3; ++i) {
            const rgb::HalfedgeId h = rgb::Mesh::halfedge(f, i);
            if (mesh.is_boundary(h)) continue;  // boundary edges are sharp already
            const auto on = rgb::base_edge_between(base, mesh.address(mesh.from_vertex(h)), mesh.address(mesh.to_vertex(h)));
            if (!on) continue;
            const double d = distance_to_segment(hit.point, drawn[i], drawn[(i + 1) % 3]);
            if (d > reach_world || d >= best) continue;
            best = d;
            const std::uint32_t a = base.face(*on / 3)[*on % 3], b = base.to_vertex(*on);
            nearest = BaseEdge{std::min(a, b), std::max(a, b)};
        }
    }
    return nearest;
}

rgb::SharpFeatures with_edges(const rgb::SharpFeatures& features, const std::vector<BaseEdge>& edges, bool untag) {
    rgb::SharpFeatures result = features;
    // BaseMesh keeps the last tag of an edge and drops sharpness 0.
    for (const BaseEdge& e : edges) result.edges.push_back({e.first, e.second, untag ? 0 : rgb::kInfiniteSharpness});
    return result;
}

rgb::SharpFeatures with_edges_above(const rgb::Mesh& mesh, double degrees) {
    rgb::SharpFeatures result = mesh.base().sharp_features();
    for (const rgb::EdgeSharpness& e : rgb::edges_sharper_than(mesh.base(), degrees)) result.edges.push_back(e);
    return result;
}

void CreaseDrag::touch(const BaseEdge& edge) {
    if (std::find(edges_.begin(), edges_.end(), edge) == edges_.end()) edges_.push_back(edge);
}

std::optional<rgb::SharpFeatures> CreaseDrag::result(const rgb::SharpFeatures& before) const {
    const bool changes = std::any_of(edges_.begin(), edges_.end(), [&](const BaseEdge& e) {
        return untag_ ? tag_of(before, e) > 0 : tag_of(before, e) < rgb::kInfiniteSharpness;
    });
    if (!changes) return std::nullopt;
    return with_edges(before, edges_, untag_);
}

}  // namespace app
