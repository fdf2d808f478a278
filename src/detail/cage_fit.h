#pragma once
// Fitting a cage to a dense mesh M (issue 28, "Any mesh in", item 2): the cage's control points move
// so that its Loop limit surface approximates M. Each iteration samples the limit surface at the
// vertices of `sample_level` uniform Loop steps (explicit stencils, loop_stencils.h), asks M for the
// closest point of each sample, and solves the linear least-squares problem
//
//     min_P  ||A P - T||^2  +  lambda_eff ||Lap P||^2,      lambda_eff = lambda * rows(A) / cols(A)
//
// per coordinate, where A is the samples' limit stencil (rows(A) samples over cols(A) control points),
// T the closest points, and Lap the umbrella Laplacian of the control net (interior vertex: itself
// minus the mean of its ring; boundary vertex: itself minus the mean of its two boundary neighbours,
// so that the boundary curve is smoothed along itself and not pulled inward; crease vertices like
// boundary ones along their crease; no row for corners). The smoothing choice:
// both terms are squared lengths, so lambda is dimensionless and needs no scale of M; the factor
// rows/cols makes it the ratio of the mean squared Laplacian per control point to the mean squared
// residual per sample, so the same lambda means the same trade-off at every sample level and cage
// size. It is a fairness term on the control net: it keeps the system well conditioned where samples
// are few or the targets noisy (a dense mesh with detail finer than the cage), at the price of a bias
// of about lambda * |Lap P| towards a flatter, smaller net. Measured on an icosahedron fitted to the
// unit sphere (level-1 samples): the default 1e-3 moves the control points inward by 0.9e-3 of the
// radius and raises the samples' rms distance from 4.36e-3 (lambda 0) to 4.40e-3; 1e-2 gives 7.5e-3
// and 1e-1 5.8e-2, so 1e-3 is about the largest weight that costs the fit nothing visible. A and Lap
// do not change between iterations, so the
// normal matrix A^T A + lambda_eff Lap^T Lap is factored once (Eigen's SimplicialLDLT) and each
// iteration is one closest-point pass and three back-substitutions.
//
// The cage's sharp features (rgb/rules/sharp_features.h) are part of its surface: the stencils follow
// the core's crease and corner rules (loop_stencils.h), so the fit places a tagged cage's limit
// surface, sharp edges included, and the Laplacian smooths a crease vertex only along its crease and
// a corner not at all (umbrella_laplacian in cage_fit.cpp says why).
#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "detail/progress.h"
#include "rgb/mesh/base_mesh.h"

namespace rgbdetail {

// The point of M closest to a point. fit_cage calls it from one thread unless
// FitOptions::parallel_targets says it may be called from several at once.
using TargetFunction = std::function<glm::dvec3(const glm::dvec3&)>;

struct FitOptions {
    int iterations = 4;
    // The limit surface is sampled at the vertices of this many uniform Loop steps (1: the cage's
    // vertices and edge midpoints, about 4 samples per control point; 2: about 16).
    int sample_level = 2;
    // The smoothing weight (see the header comment); 0 is plain least squares.
    double lambda = 1e-3;
    // Whether closest_on_m may be called concurrently (rgb::parallel_for over the samples).
    bool parallel_targets = false;
    // Told the share of the fit done, many times while it runs (between chunks of closest points);
    // returning false stops fit_cage, which then throws Stopped.
    ProgressFunction progress;
};

// The samples' distances to their closest points on M.
struct FitDistances {
    double rms = 0.0;
    double max = 0.0;
};

struct FitResult {
    std::vector<glm::dvec3> positions;
    // distances[0]: the cage as given; distances[i]: after i solves (iterations + 1 entries).
    std::vector<FitDistances> distances;
    std::size_t samples = 0;
};

// Throws std::invalid_argument when the cage is not an oriented manifold with every vertex used or
// its features name missing edges or vertices (loop_stencils.h), when the positions do not match it,
// or when an option is out of range.
FitResult fit_cage(const std::vector<glm::dvec3>& cage_positions, const std::vector<rgb::Triangle>& cage_triangles,
                   const rgb::SharpFeatures& cage_features, const TargetFunction& closest_on_m, const FitOptions& options = {});

}  // namespace rgbdetail
