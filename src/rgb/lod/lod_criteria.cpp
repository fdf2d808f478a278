#include "rgb/lod/lod_criteria.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>
#include <vector>

#include <glm/geometric.hpp>

#include "rgb/lod/refine.h"
#include "rgb/lod/request_steps.h"
#include "rgb/mesh/mesh.h"
#include "rgb/values/hierarchy_evaluator.h"

namespace rgb {

namespace {

// The faces to start from: those meeting the ball, or all of them.
std::vector<FaceId> faces_meeting_or_all(const Mesh& mesh, const std::optional<Sphere>& sphere) {
    if (sphere) return faces_meeting(mesh, *sphere);
    std::vector<FaceId> faces;
    faces.reserve(mesh.num_faces());
    for (FaceId f : mesh.faces()) faces.push_back(f);
    return faces;
}

void check(const DetailRequest& r) {
    if (!r.value) throw std::invalid_argument("a detail request needs a criterion");
    if (!(r.threshold >= 0.0) || !std::isfinite(r.threshold)) throw std::invalid_argument("a detail threshold must be finite and not negative");
    check_sphere(r.sphere);
}

void coarsen(Mesh& mesh, const DetailRequest& r) {
    std::vector<VertexId> doomed;
    std::vector<bool> seen(mesh.vertex_capacity(), false);
    for (FaceId f : faces_meeting_or_all(mesh, r.sphere))
        for (VertexId v : mesh.face_vertices(f)) {
            if (mesh.level(v) == 0 || seen[v.idx]) continue;
            seen[v.idx] = true;
            if (r.sphere && glm::distance(mesh.base_space_position(v), r.sphere->centre) > r.sphere->radius) continue;
            const PointStencil s = parent_stencil(mesh.base(), mesh.address(v));
            if (!(r.value(s.ends[0], s.ends[1]) > r.threshold)) doomed.push_back(v);
        }
    remove_finest_first(mesh, std::move(doomed));
}

void refine(Mesh& mesh, const DetailRequest& r, OperatorLog& log, LodReport& report) {
    std::vector<FaceId> stack = faces_meeting_or_all(mesh, r.sphere);
    while (!stack.empty()) {
        const FaceId f = stack.back();
        stack.pop_back();
        if (!mesh.is_live(f)) continue;
        for (int i = 0; i < 3; ++i) {
            const HalfedgeId h = Mesh::halfedge(f, i);
            const EdgeType t = mesh.edge_type(h);
            if (t.colour != Colour::Green) continue;
            const VertexId a = mesh.from_vertex(h), b = mesh.to_vertex(h);
            if (r.sphere && !segment_meets_sphere(mesh.base_space_position(a), mesh.base_space_position(b), *r.sphere)) continue;
            if (!(r.value(mesh.address(a), mesh.address(b)) > r.threshold)) continue;
            if (t.level >= r.max_level) {
                report.level_cap_bound = true;
                continue;
            }
            log.added.clear();
            refine_edge(mesh, h);
            stack.insert(stack.end(), log.added.begin(), log.added.end());
            if (mesh.num_faces() > r.max_triangles) {
                report.budget_bound = true;
                return;
            }
            break;  // f is gone; the faces that replaced it are on the stack
        }
    }
}

}  // namespace

bool segment_meets_sphere(glm::dvec3 p, glm::dvec3 q, const Sphere& sphere) {
    if (std::tie(q.x, q.y, q.z) < std::tie(p.x, p.y, p.z)) std::swap(p, q);
    const glm::dvec3 d = q - p;
    const double length2 = glm::dot(d, d);
    const double t = length2 > 0.0 ? std::clamp(glm::dot(sphere.centre - p, d) / length2, 0.0, 1.0) : 0.0;
    return glm::distance(p + t * d, sphere.centre) <= sphere.radius;
}

EdgeValue edge_length_value(const std::shared_ptr<const BaseMesh>& base) {
    auto evaluator = std::make_shared<HierarchyEvaluator>(*base);
    return [base, evaluator](const SurfacePoint& a, const SurfacePoint& b) {
        const int level = std::max(a.level, b.level);
        return glm::distance(evaluator->control_point(a, level), evaluator->control_point(b, level));
    };
}

SplitValue on_mesh(EdgeValue value) {
    return [value = std::move(value)](const Mesh& mesh, VertexId a, VertexId b, int) { return value(mesh.address(a), mesh.address(b)); };
}

LodSettings whole_surface_settings(const DetailRequest& r) {
    check(r);
    LodSettings settings;
    settings.value = r.mesh_value ? r.mesh_value : on_mesh(r.value);
    settings.threshold = r.threshold;
    settings.max_triangles = r.max_triangles;
    settings.max_level = r.max_level;
    settings.split_past_dependencies = true;
    return settings;
}

double estimated_detail_triangles(const Mesh& mesh, const DetailRequest& r) {
    constexpr int kMarginLevels = 2;
    check(r);
    if (r.kind == RequestKind::Coarsen) return static_cast<double>(mesh.num_faces());
    // Base faces by the level they need (less the margin: Loop's limit surface is smaller than its
    // cage, so lengths may fall faster than halving), each level's group estimated as a
    // level request restricted to it (which scales by the part of a face a ball can cover).
    const BaseMesh& base = mesh.base();
    std::vector<std::vector<std::uint32_t>> by_level(static_cast<std::size_t>(std::max(r.max_level, 0)) + 1);
    for (std::uint32_t f = 0; f < base.num_faces(); ++f) {
        double value = 0.0;
        for (int i = 0; i < 3; ++i) value = std::max(value, r.value(corner_point(f, i), corner_point(f, (i + 1) % 3)));
        int level = 0;
        if (value > r.threshold) {
            const double levels = std::log(value / r.threshold) / std::log(r.shrink_per_level);  // inf for a tiny threshold
            level = levels < double(r.max_level) ? std::max(0, static_cast<int>(std::ceil(levels)) - kMarginLevels) : r.max_level - kMarginLevels;
        }
        by_level[static_cast<std::size_t>(std::max(level, 0))].push_back(f);
    }
    double total = 0.0;
    for (std::size_t level = 0; level < by_level.size(); ++level) {
        if (by_level[level].empty()) continue;
        LevelRequest group;
        group.kind = RequestKind::Refine;
        group.level = static_cast<int>(level);
        group.sphere = r.sphere;
        group.base_faces = std::move(by_level[level]);
        total += estimated_triangles(mesh, group) - static_cast<double>(mesh.num_faces());
    }
    return total;
}

LodReport apply_detail_request(Mesh& mesh, const DetailRequest& r) {
    check(r);
    if (r.kind == RequestKind::Set && !r.sphere) {
        LodDriver driver(mesh, whole_surface_settings(r));
        driver.run();
        return driver.report();
    }
    OperatorLog log(mesh);
    LodReport report;
    if (r.kind != RequestKind::Refine) coarsen(mesh, r);
    if (r.kind != RequestKind::Coarsen) refine(mesh, r, log, report);
    report.splits = log.splits;
    report.removals = log.removals;
    return report;
}

}  // namespace rgb
