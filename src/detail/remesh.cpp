#include "detail/remesh.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "detail/cage.h"
#include "detail/dense_surface.h"
#include "rgb/mesh/detail_positions.h"
#include "rgb/support/parallel.h"
#include "rgb/values/hierarchy_evaluator.h"
#include "rgb/values/limit_normals.h"

namespace rgbdetail {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

void report_progress(const RemeshOptions& options, double share, const char* phase) {
    if (options.progress && !options.progress(share, phase)) throw Stopped();
}

double bounding_box_diagonal(std::span<const glm::dvec3> positions) {
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
    for (const glm::dvec3& p : positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    return glm::distance(lo, hi);
}

// The cage: the user's, checked against M's topology, or M decimated.
Cage cage_for(std::span<const glm::dvec3> positions, std::span<const rgb::Triangle> triangles, const RemeshOptions& options) {
    if (!options.cage_positions) return make_cage(positions, triangles, options.cage_triangles);
    const MeshTopology dense = topology_of(positions, triangles);
    const MeshTopology given = topology_of(*options.cage_positions, options.cage_triangles_given);
    if (const std::optional<std::string> mismatch = topology_mismatch(dense, given))
        throw std::invalid_argument("the cage does not have the mesh's topology: " + *mismatch);
    Cage cage;
    cage.positions = *options.cage_positions;
    cage.triangles = options.cage_triangles_given;
    return cage;
}

// The limit point and unit limit normal of every grid point, each block of points with an evaluator
// of its own (an evaluator keeps the values its points share, and is not for several threads).
void limit_frames(const rgb::BaseMesh& base, std::span<const rgb::SurfacePoint> points, std::vector<glm::dvec3>& origins,
                  std::vector<glm::dvec3>& normals) {
    origins.resize(points.size());
    normals.resize(points.size());
    rgb::parallel_for(points.size(), 4096, [&](std::size_t begin, std::size_t end) {
        rgb::HierarchyEvaluator evaluator(base);
        for (std::size_t i = begin; i < end; ++i) {
            origins[i] = evaluator.limit_position(points[i]);
            normals[i] = rgb::limit_normal(base, evaluator, points[i]);
        }
    });
}

}  // namespace

int detail_level_for(std::size_t cage_faces, std::size_t dense_faces, int max_level) {
    int level = 0;
    while (level < max_level && (cage_faces << (2 * level)) < dense_faces) ++level;
    return level;
}

Remeshed remesh(std::span<const glm::dvec3> positions, std::span<const rgb::Triangle> triangles, const RemeshOptions& options) {
    Remeshed result;
    RemeshReport& report = result.report;
    report_progress(options, 0.0, "making the cage");
    auto start = Clock::now();
    const Cage cage = cage_for(positions, triangles, options);
    report.cage_triangles = cage.triangles.size();
    report.seconds_cage = seconds_since(start);

    report_progress(options, 0.3, "fitting the cage");
    start = Clock::now();
    const DenseSurface surface(std::vector<glm::dvec3>(positions.begin(), positions.end()),
                               std::vector<rgb::Triangle>(triangles.begin(), triangles.end()));
    FitOptions fit = options.fit;
    fit.parallel_targets = true;  // DenseSurface's queries are thread-safe
    const FitResult fitted =
        fit_cage(cage.positions, cage.triangles, [&surface](const glm::dvec3& p) { return surface.closest_point(p).point; }, fit);
    report.fit_before = fitted.distances.front();
    report.fit_after = fitted.distances.back();
    report.seconds_fit = seconds_since(start);

    report_progress(options, 0.6, "sampling the detail");
    start = Clock::now();
    const rgb::BaseMesh plain(fitted.positions, cage.triangles);
    report.detail_level = detail_level_for(cage.triangles.size(), triangles.size(), options.max_detail_level);
    const std::vector<rgb::SurfacePoint> points = rgb::DetailPositions::grid_points(plain, report.detail_level);
    std::vector<glm::dvec3> origins, normals;
    limit_frames(plain, points, origins, normals);
    report_progress(options, 0.8, "sampling the detail");
    // At least a few times the fit's largest distance: where the cage is far from M (a thin part it
    // cannot follow), a shorter search would leave the line without M and the point at M's nearest
    // point, which may lie on another part.
    report.search_distance = std::max(options.search_share * bounding_box_diagonal(positions), 3.0 * report.fit_after.max);
    // A point where the limit surface has no normal (a degenerate cage) takes the nearest point of M.
    std::vector<std::uint8_t> no_normal(normals.size(), 0);
    for (std::size_t i = 0; i < normals.size(); ++i)
        if (!(glm::length(normals[i]) > 0.5)) {
            no_normal[i] = 1;
            normals[i] = glm::dvec3(0, 0, 1);
        }
    std::vector<SurfaceHit> hits = surface.projections(origins, normals, report.search_distance);
    for (std::size_t i = 0; i < hits.size(); ++i)
        if (no_normal[i]) hits[i] = surface.closest_point(origins[i]);
    std::vector<glm::dvec3> values(hits.size());
    for (std::size_t i = 0; i < hits.size(); ++i) {
        values[i] = hits[i].point;
        report.nearest_points += !hits[i].by_ray;
    }
    report.detail_points = values.size();
    auto detail = std::make_shared<const rgb::DetailPositions>(
        plain, report.detail_level, values, rgb::DetailOrigin{options.source_name, triangles.size(), report.nearest_points});
    result.base = std::make_shared<const rgb::BaseMesh>(fitted.positions, cage.triangles, rgb::SharpFeatures{}, std::move(detail));
    report.seconds_detail = seconds_since(start);
    report_progress(options, 1.0, "done");
    return result;
}

}  // namespace rgbdetail
