#pragma once
// A dense mesh M in, a cage with M's detail out (`rgbsub remesh`, issue 28): the whole path from
// the other files of this folder to the core's detail positions.
//
//   1. the cage C: M decimated to a triangle count (cage.h), or the user's cage, which must have M's
//      topology per component;
//   2. fitting: C's control points moved so that its Loop limit surface approximates M
//      (cage_fit.h: least squares over closest points, smoothed, iterated), with the creases that
//      RemeshOptions::sharp_angle finds on C as made;
//   3. detail: every point of the hierarchy over C up to level K, where Σ_K has at least as many
//      triangles as M, goes where the line through its limit point along its limit normal meets M
//      (the nearest hit within the search distance, both directions), or to the nearest point of M
//      where the line finds none (dense_surface.h). From those samples, how many of M's triangles
//      each cage face covers (dense_triangles_per_face), and each face's own level K_f >= K where its
//      grid is as dense (face_detail_levels); the finer points are sampled the same way, a base
//      edge's to the coarser level of its faces. Finer levels interpolate the samples linearly
//      (rgb/mesh/detail_positions.h). So every displayed vertex of every level of detail up to its
//      face's (its edge's) level lies on M, and its position depends on its address, C and M only.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "detail/cage_fit.h"
#include "detail/progress.h"
#include "rgb/mesh/base_mesh.h"

namespace rgbdetail {

struct RemeshOptions {
    // The cage's triangle budget (make_cage), when no cage is given.
    std::size_t cage_triangles = 0;
    // The user's own cage, used as it is (then fitted): it must have M's topology per component.
    std::optional<std::vector<glm::dvec3>> cage_positions;
    std::vector<rgb::Triangle> cage_triangles_given;
    // If set, the cage's interior edges whose faces' normals differ by more than this many degrees
    // (0-180) are tagged infinitely sharp before the fit (rgb/mesh/sharp_angle.h, the classification
    // `refine --sharp-angle` makes on a base mesh), so the fit places the creased limit surface and
    // the result carries the tags.
    std::optional<double> sharp_angle;
    // M's name, kept with the detail for reports.
    std::string source_name;
    // How far along the limit normal a point looks for M, as a share of M's bounding-box diagonal (at
    // least three times the fit's largest distance).
    double search_share = 0.05;
    // The finest level a face is sampled to at most, and the most points the detail may hold (each
    // kept in memory at DetailPositions::kBytesPerPoint = 24 bytes, about 60 in a saved file, and
    // about 200 more while it is sampled): a mesh that needs more is refused before they are sampled.
    // Each face's level keeps its grid below 4 times M's triangles there (plus the first level
    // everywhere), so the points stay below about 2 per triangle of M plus those of Σ_K.
    int max_detail_level = 10;
    std::size_t max_detail_points = std::size_t(1) << 25;
    // Told the detail's points before they are sampled, below max_detail_points; may throw to refuse
    // them (the CLI's --max-triangles: what this machine's memory allows).
    std::function<void(std::size_t)> check_points;
    FitOptions fit;
    // Told the share of the work done (0..1) and the phase's name; returns false to stop (then
    // remesh throws Stopped, having changed nothing).
    std::function<bool(double, const char*)> progress;
};

struct RemeshReport {
    std::size_t cage_triangles = 0;
    FitDistances fit_before, fit_after;
    // The first level, sampled everywhere, and the finest a face reached.
    int detail_level = 0, finest_detail_level = 0;
    std::size_t detail_points = 0, nearest_points = 0;
    // Points on the cage's feature edges and vertices, put on M's feature chains (not by rays).
    std::size_t feature_points = 0;
    double search_distance = 0.0;
    double seconds_cage = 0, seconds_fit = 0, seconds_detail = 0;
};

struct Remeshed {
    std::shared_ptr<const rgb::BaseMesh> base;  // the fitted cage, with the detail
    RemeshReport report;
};

// The level K whose uniform mesh over `cage_faces` triangles first has at least `dense_faces`.
int detail_level_for(std::size_t cage_faces, std::size_t dense_faces, int max_level);

// How many of M's triangles each cage face covers, estimated from a sampling of every face at
// `level`: `values`, one per point of rgb::DetailPositions::grid_points(cage, level), on M, and
// hit_areas, the area of the triangle of M each lies on. Each triangle of Σ_level's grid adds its
// area on M (the flat triangle of its three samples) over the mean area of M's triangles at its
// corners: M's triangles per area there times its area. Grid triangles whose corners all lie on
// triangles of no area add nothing.
std::vector<double> dense_triangles_per_face(const rgb::BaseMesh& cage, int level, std::span<const glm::dvec3> values,
                                             std::span<const double> hit_areas);
// Each face's detail level: the smallest from first_level on whose 4^K grid triangles are at least
// its dense triangles, at most max_level.
std::vector<std::uint8_t> face_detail_levels(std::span<const double> dense_triangles, int first_level, int max_level);

// Throws std::invalid_argument with the reason for a mesh or cage that cannot be used (empty,
// degenerate, one triangle, non-manifold, a cage of another topology, a triangle count below what
// the topology allows, a sharp angle out of range), Stopped when progress says stop.
Remeshed remesh(std::span<const glm::dvec3> positions, std::span<const rgb::Triangle> triangles, const RemeshOptions& options);

}  // namespace rgbdetail
