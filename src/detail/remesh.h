#pragma once
// A dense mesh M in, a cage with M's detail out (`rgbsub remesh`, issue 28): the whole path from
// the other files of this folder to the core's detail positions.
//
//   1. the cage C: M decimated to a triangle count (cage.h), or the user's cage, which must have M's
//      topology per component;
//   2. fitting: C's control points moved so that its Loop limit surface approximates M
//      (cage_fit.h: least squares over closest points, smoothed, iterated);
//   3. detail: every point of the hierarchy over C up to level K, where Σ_K has at least as many
//      triangles as M, goes where the line through its limit point along its limit normal meets M
//      (the nearest hit within the search distance, both directions), or to the nearest point of M
//      where the line finds none (dense_surface.h). Finer levels interpolate those points linearly
//      (rgb/mesh/detail_positions.h). So every displayed vertex of every level of detail up to K lies
//      on M, and its position depends on its address, C and M only.
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "detail/cage_fit.h"
#include "rgb/mesh/base_mesh.h"

namespace rgbdetail {

struct RemeshOptions {
    // The cage's triangle budget (make_cage), when no cage is given.
    std::size_t cage_triangles = 0;
    // The user's own cage, used as it is (then fitted): it must have M's topology per component.
    std::optional<std::vector<glm::dvec3>> cage_positions;
    std::vector<rgb::Triangle> cage_triangles_given;
    // M's name, kept with the detail for reports.
    std::string source_name;
    // How far along the limit normal a point looks for M, as a share of M's bounding-box diagonal (at
    // least three times the fit's largest distance).
    double search_share = 0.05;
    // The finest sampled level at most (memory: about 12 bytes per triangle of Σ_K, each point saved).
    int max_detail_level = 6;
    FitOptions fit;
    // Told the share of the work done (0..1) and the phase's name; returns false to stop (then
    // remesh throws Stopped, having changed nothing).
    std::function<bool(double, const char*)> progress;
};

struct Stopped : std::runtime_error {
    Stopped() : std::runtime_error("stopped") {}
};

struct RemeshReport {
    std::size_t cage_triangles = 0;
    FitDistances fit_before, fit_after;
    int detail_level = 0;
    std::size_t detail_points = 0, nearest_points = 0;
    double search_distance = 0.0;
    double seconds_cage = 0, seconds_fit = 0, seconds_detail = 0;
};

struct Remeshed {
    std::shared_ptr<const rgb::BaseMesh> base;  // the fitted cage, with the detail
    RemeshReport report;
};

// The level K whose uniform mesh over `cage_faces` triangles first has at least `dense_faces`.
int detail_level_for(std::size_t cage_faces, std::size_t dense_faces, int max_level);

// Throws std::invalid_argument with the reason for a mesh or cage that cannot be used (empty,
// degenerate, one triangle, non-manifold, a cage of another topology, a triangle count below what
// the topology allows), Stopped when progress says stop.
Remeshed remesh(std::span<const glm::dvec3> positions, std::span<const rgb::Triangle> triangles, const RemeshOptions& options);

}  // namespace rgbdetail
