#include "detail/remesh.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <utility>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "detail/cage.h"
#include "detail/dense_features.h"
#include "detail/dense_surface.h"
#include "rgb/mesh/detail_positions.h"
#include "rgb/mesh/sharp_angle.h"
#include "rgb/support/parallel.h"
#include "rgb/values/hierarchy_evaluator.h"
#include "rgb/values/limit_normals.h"

namespace rgbdetail {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// RemeshOptions::progress through the phases, never decreasing: each phase tells its own share
// (0..1), placed in its span of the whole. The spans are about the phases' shares of the time for the
// 940,544-triangle bunny to 5,000 (cage 45%, M's search tree and the fit 10%, detail 45%, 2026-12-05).
class RemeshProgress {
public:
    explicit RemeshProgress(const RemeshOptions& options) : options_(options) {}

    // The progress of the phase from `from` to `to` of the whole; tells its start.
    ProgressFunction phase(double from, double to, const char* name) {
        ProgressFunction progress = span(from, to, name);
        report_share(progress, 0.0);
        return progress;
    }

    void done() { report_share(span(1.0, 1.0, "done"), 1.0); }

private:
    ProgressFunction span(double from, double to, const char* name) {
        if (!options_.progress) return {};
        return [this, from, to, name](double share) {
            whole_ = std::max(whole_, from + std::clamp(share, 0.0, 1.0) * (to - from));
            return options_.progress(whole_, name);
        };
    }

    const RemeshOptions& options_;
    double whole_ = 0.0;
};

double bounding_box_diagonal(std::span<const glm::dvec3> positions) {
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
    for (const glm::dvec3& p : positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    return glm::distance(lo, hi);
}

std::string degrees_text(double degrees) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", degrees);
    return text;
}

// M's sharp features at the option's angle, for a cage made by decimation to keep: the edges of
// chains at least as long as a cage edge of the target count (an equilateral triangle of M's area
// over that count), since a shorter one cannot be a cage edge and would only pin vertices. Refused
// when their anchors (corners, ends, three a closed ridge) would take more than a quarter of the
// cage's triangle budget: the cage could keep little else.
FeatureGraph dense_features(std::span<const glm::dvec3> positions, std::span<const rgb::Triangle> triangles,
                            const RemeshOptions& options) {
    if (!options.sharp_angle || options.cage_positions) return {};
    double area = 0.0;
    for (const rgb::Triangle& t : triangles)
        area += triangle_area(positions, t);
    const double cage_edge = std::sqrt(4.0 * area / (std::sqrt(3.0) * static_cast<double>(std::max<std::size_t>(options.cage_triangles, 1))));
    FeatureGraph features = find_sharp_features(positions, triangles, *options.sharp_angle, cage_edge);
    const std::size_t anchors = feature_anchors(features).size();
    if (4 * anchors > options.cage_triangles)
        throw std::invalid_argument("the sharp features above " + degrees_text(*options.sharp_angle) + " degrees have " +
                                    std::to_string(anchors) + " corners and ends, more than a cage of " +
                                    std::to_string(options.cage_triangles) +
                                    " triangles can keep (a quarter of its count): raise --sharp-angle or --cage-triangles");
    return features;
}

// The cage: the user's, checked against M's topology, or M decimated (keeping M's features).
Cage cage_for(std::span<const glm::dvec3> positions, std::span<const rgb::Triangle> triangles, const FeatureGraph& features,
              const RemeshOptions& options, const ProgressFunction& progress) {
    if (!options.cage_positions) {
        CageOptions cage_options;
        if (!features.empty()) cage_options.features = &features;
        cage_options.progress = progress;
        return make_cage(positions, triangles, options.cage_triangles, cage_options);
    }
    const MeshTopology dense = topology_of(positions, triangles);
    const MeshTopology given = topology_of(*options.cage_positions, options.cage_triangles_given);
    if (const std::optional<std::string> mismatch = topology_mismatch(dense, given))
        throw std::invalid_argument("the cage does not have the mesh's topology: " + *mismatch);
    Cage cage;
    cage.positions = *options.cage_positions;
    cage.triangles = options.cage_triangles_given;
    return cage;
}

// The cage's tags, before the fit, which keeps them sharp, so that the fitted surface has its sharp
// edges where they are: a decimated cage's edges that stand for M's feature chains, or on the user's
// cage the creases of sharp_angle on it as it is.
rgb::SharpFeatures cage_features(const Cage& cage, const RemeshOptions& options) {
    rgb::SharpFeatures features;
    if (!options.sharp_angle) return features;
    if (!options.cage_positions) {
        for (const auto& [a, b] : cage.feature_edges) features.edges.push_back({a, b, rgb::kInfiniteSharpness});
        return features;
    }
    features.edges = rgb::edges_sharper_than(rgb::BaseMesh(cage.positions, cage.triangles), *options.sharp_angle);
    return features;
}

// The limit point and unit limit normal of every grid point, each block of points with an evaluator
// of its own (an evaluator keeps the values its points share, and is not for several threads).
void limit_frames(const rgb::BaseMesh& base, std::span<const rgb::SurfacePoint> points, std::span<glm::dvec3> origins,
                  std::span<glm::dvec3> normals) {
    rgb::parallel_for(points.size(), 4096, [&](std::size_t begin, std::size_t end) {
        rgb::HierarchyEvaluator evaluator(base);
        for (std::size_t i = begin; i < end; ++i) {
            origins[i] = evaluator.limit_position(points[i]);
            normals[i] = rgb::limit_normal(base, evaluator, points[i]);
        }
    });
}

// Points of the hierarchy put on M: a point on a feature kept by the cage on its chain of M
// (FeatureDetail), any other where the line through its limit point along its limit normal meets M,
// or at M's nearest point (no hit within the search distance, or no normal).
struct DetailSamples {
    std::vector<glm::dvec3> values;
    std::vector<std::uint32_t> triangles;  // the M triangle each value lies on, or its ray's (a feature point)
    std::size_t nearest_points = 0, feature_points = 0;
};

DetailSamples sample_detail(const DenseSurface& surface, const rgb::BaseMesh& base, std::span<const rgb::SurfacePoint> points,
                            const FeatureDetail* feature_detail, double search_distance, const ProgressFunction& progress) {
    std::vector<glm::dvec3> origins(points.size()), normals(points.size());
    std::vector<std::uint8_t> no_normal(points.size(), 0);
    std::vector<SurfaceHit> hits(points.size());
    // In chunks of 8192 points, about 40 ms each on this machine when busy (the bunny's detail took
    // as long as in chunks of 32768 or in one, within the noise).
    in_chunks(points.size(), 8192, progress, [&](std::size_t begin, std::size_t end) {
        const std::span<glm::dvec3> chunk_origins(origins.data() + begin, end - begin), chunk_normals(normals.data() + begin, end - begin);
        limit_frames(base, points.subspan(begin, end - begin), chunk_origins, chunk_normals);
        // A point where the limit surface has no normal (a degenerate cage) takes the nearest point of M.
        for (std::size_t i = begin; i < end; ++i)
            if (!(glm::length(normals[i]) > 0.5)) {
                no_normal[i] = 1;
                normals[i] = glm::dvec3(0, 0, 1);
            }
        const std::vector<SurfaceHit> chunk_hits = surface.projections(chunk_origins, chunk_normals, search_distance);
        std::copy(chunk_hits.begin(), chunk_hits.end(), hits.begin() + static_cast<std::ptrdiff_t>(begin));
    });
    DetailSamples samples;
    samples.values.resize(hits.size());
    samples.triangles.resize(hits.size());
    for (std::size_t i = 0; i < hits.size(); ++i) {
        if (no_normal[i]) hits[i] = surface.closest_point(origins[i]);
        samples.triangles[i] = hits[i].triangle;
        if (feature_detail != nullptr)
            if (const std::optional<glm::dvec3> on_feature = feature_detail->position(base, points[i], origins[i])) {
                samples.values[i] = *on_feature;
                ++samples.feature_points;
                continue;
            }
        samples.values[i] = hits[i].point;
        samples.nearest_points += !hits[i].by_ray;
    }
    return samples;
}


// Refuses, before sampling them, more detail points than the options allow.
void check_detail_size(std::size_t points, const RemeshOptions& options) {
    if (points > options.max_detail_points)
        throw std::invalid_argument("the detail would hold " + std::to_string(points) + " points (" +
                                std::to_string(points * rgb::DetailPositions::kBytesPerPoint >> 20) + " MB), more than the " +
                                std::to_string(options.max_detail_points) +
                                " allowed: the mesh is far denser, at least in places, than the cage's faces; give the cage more triangles");
    if (options.check_points) options.check_points(points);
}

}  // namespace

int detail_level_for(std::size_t cage_faces, std::size_t dense_faces, int max_level) {
    int level = 0;
    while (level < max_level && (cage_faces << (2 * level)) < dense_faces) ++level;
    return level;
}

std::vector<double> dense_triangles_per_face(const rgb::BaseMesh& cage, int level, std::span<const glm::dvec3> values,
                                             std::span<const double> hit_areas) {
    const std::vector<std::uint32_t> indices =
        rgb::DetailPositions::grid_point_indices(cage, rgb::DetailPositions::uniform_levels(cage, level));
    const std::size_t per_face = rgb::DetailPositions::points_per_face(level);
    const std::uint32_t n = std::uint32_t(1) << level;
    std::vector<double> estimates(cage.num_faces(), 0.0);
    for (std::uint32_t f = 0; f < cage.num_faces(); ++f) {
        const std::uint32_t* grid = indices.data() + f * per_face;
        auto at = [&](std::uint32_t a1, std::uint32_t a2) { return grid[rgb::DetailPositions::grid_index(level, a1, a2)]; };
        auto add = [&](std::uint32_t i, std::uint32_t j, std::uint32_t k) {
            const double dense_area = hit_areas[i] + hit_areas[j] + hit_areas[k];
            if (dense_area > 0.0) estimates[f] += 3.0 * triangle_area(values[i], values[j], values[k]) / dense_area;
        };
        for (std::uint32_t a2 = 0; a2 < n; ++a2)
            for (std::uint32_t a1 = 0; a1 + a2 < n; ++a1) {
                add(at(a1, a2), at(a1 + 1, a2), at(a1, a2 + 1));
                if (a1 + a2 + 1 < n) add(at(a1 + 1, a2), at(a1 + 1, a2 + 1), at(a1, a2 + 1));
            }
    }
    return estimates;
}

std::vector<std::uint8_t> face_detail_levels(std::span<const double> dense_triangles, int first_level, int max_level) {
    std::vector<std::uint8_t> levels(dense_triangles.size());
    for (std::size_t f = 0; f < levels.size(); ++f) {
        int level = first_level;
        while (level < max_level && std::ldexp(1.0, 2 * level) < dense_triangles[f]) ++level;
        levels[f] = static_cast<std::uint8_t>(level);
    }
    return levels;
}

Remeshed remesh(std::span<const glm::dvec3> positions, std::span<const rgb::Triangle> triangles, const RemeshOptions& options) {
    Remeshed result;
    RemeshReport& report = result.report;
    RemeshProgress progress(options);
    const ProgressFunction cage_progress = progress.phase(0.0, 0.45, "making the cage");
    auto start = Clock::now();
    if (options.sharp_angle && !(*options.sharp_angle >= 0.0 && *options.sharp_angle <= 180.0))
        throw std::invalid_argument("the sharp angle must be between 0 and 180 degrees");
    const FeatureGraph features_of_dense = dense_features(positions, triangles, options);
    const Cage cage = cage_for(positions, triangles, features_of_dense, options, cage_progress);
    report.cage_triangles = cage.triangles.size();
    const rgb::SharpFeatures features = cage_features(cage, options);
    report.seconds_cage = seconds_since(start);

    start = Clock::now();
    const DenseSurface surface(std::vector<glm::dvec3>(positions.begin(), positions.end()),
                               std::vector<rgb::Triangle>(triangles.begin(), triangles.end()),
                               progress.phase(0.45, 0.5, "indexing the dense mesh"));
    FitOptions fit = options.fit;
    fit.progress = progress.phase(0.5, 0.55, "fitting the cage");
    fit.parallel_targets = true;  // DenseSurface's queries are thread-safe
    const FitResult fitted =
        fit_cage(cage.positions, cage.triangles, features, [&surface](const glm::dvec3& p) { return surface.closest_point(p).point; }, fit);
    report.fit_before = fitted.distances.front();
    report.fit_after = fitted.distances.back();
    report.seconds_fit = seconds_since(start);

    // The first sampling is about 60% of the detail's time (the bunny: 640,002 points of 1,005,498).
    const ProgressFunction detail_progress = progress.phase(0.55, 0.78, "sampling the detail");
    start = Clock::now();
    const rgb::BaseMesh plain(fitted.positions, cage.triangles, features);
    report.detail_level = detail_level_for(cage.triangles.size(), triangles.size(), options.max_detail_level);
    // At least a few times the fit's largest distance: where the cage is far from M (a thin part it
    // cannot follow), a shorter search would leave the line without M and the point at M's nearest
    // point, which may lie on another part.
    report.search_distance = std::max(options.search_share * bounding_box_diagonal(positions), 3.0 * report.fit_after.max);
    // First every face to the level where Σ_K is as dense as M overall; from those samples, how many
    // of M's triangles each face covers, and each face further to where its own grid is as dense.
    check_detail_size(rgb::DetailPositions::num_points(plain, rgb::DetailPositions::uniform_levels(plain, report.detail_level)), options);
    const std::vector<rgb::SurfacePoint> first_points = rgb::DetailPositions::grid_points(plain, report.detail_level);
    std::optional<FeatureDetail> feature_detail;
    if (!cage.feature_edges.empty()) feature_detail.emplace(features_of_dense, positions, cage.source_vertex, cage.feature_edges);
    const FeatureDetail* on_features = feature_detail ? &*feature_detail : nullptr;
    const DetailSamples first = sample_detail(surface, plain, first_points, on_features, report.search_distance, detail_progress);
    // Between the samplings and after them, steps of a fraction of a second each on a million points
    // (0.1-0.7 s on the bunny with the machine busy, 2026-12-05), each a report: a stop is heard
    // between them instead of at the next sampling.
    const ProgressFunction levels_progress = progress.phase(0.78, 0.8, "choosing the detail levels");
    std::vector<double> hit_areas(first.triangles.size());
    for (std::size_t i = 0; i < hit_areas.size(); ++i) {
        hit_areas[i] = triangle_area(positions, triangles[first.triangles[i]]);
    }
    report_share(levels_progress, 0.2);
    std::vector<std::uint8_t> levels = face_detail_levels(dense_triangles_per_face(plain, report.detail_level, first.values, hit_areas),
                                                          report.detail_level, options.max_detail_level);
    report.finest_detail_level = *std::max_element(levels.begin(), levels.end());
    check_detail_size(rgb::DetailPositions::num_points(plain, levels), options);
    report_share(levels_progress, 0.4);
    // The points of the first level keep their samples; only the finer ones are sampled now.
    const rgb::DetailPositions first_detail(plain, report.detail_level, first.values);
    report_share(levels_progress, 0.6);
    const std::vector<rgb::SurfacePoint> points = rgb::DetailPositions::grid_points(plain, levels);
    report_share(levels_progress, 0.8);
    std::vector<rgb::SurfacePoint> finer;
    for (const rgb::SurfacePoint& p : points)
        if (p.level > report.detail_level) finer.push_back(p);
    const DetailSamples second = sample_detail(surface, plain, finer, on_features, report.search_distance,
                                               progress.phase(0.8, 0.97, "sampling the detail"));
    const ProgressFunction storing_progress = progress.phase(0.97, 1.0, "storing the detail");
    std::vector<glm::dvec3> values(points.size());
    for (std::size_t i = 0, j = 0; i < points.size(); ++i)
        values[i] = points[i].level > report.detail_level ? second.values[j++] : first_detail.position(plain, points[i]);
    report.nearest_points = first.nearest_points + second.nearest_points;
    report.feature_points = first.feature_points + second.feature_points;
    report.detail_points = values.size();
    report_share(storing_progress, 0.3);
    auto detail = std::make_shared<const rgb::DetailPositions>(
        plain, std::move(levels), values, rgb::DetailOrigin{options.source_name, triangles.size(), report.nearest_points});
    report_share(storing_progress, 1.0);
    result.base = std::make_shared<const rgb::BaseMesh>(fitted.positions, cage.triangles, features, std::move(detail));
    report.seconds_detail = seconds_since(start);
    progress.done();
    return result;
}

}  // namespace rgbdetail
