#pragma once
// The cage of a dense mesh: a coarse manifold triangle mesh with the dense mesh's topology (as its
// indices give it: vertices that merely share a position stay apart), for `rgbsub remesh` (issue 28)
// to subdivide and fit. The simplification is OpenMesh's decimation (its quadric error and normal
// flip modules and its collapse, in a faster loop of ours: cage.cpp), whose collapse test
// (TriConnectivity::is_collapse_ok: the link condition, no interior edge between two boundary
// vertices) keeps the surface manifold and its Euler characteristic and boundary loops; a guard
// module of ours also refuses ears and keeps each boundary loop long enough for the smallest cage,
// and every cage is checked (manifold, topology) before it is returned.
// meshoptimizer's meshopt_simplify was the other candidate: it collapses by an error bound on an
// index buffer and does not promise manifoldness or topology, so it is not used.
//
// Plain data in and out: positions and rgb::Triangle index triples, counter-clockwise outside. The
// topology it keeps, and the smallest cage of each, are mesh_topology.h's.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "detail/dense_features.h"
#include "detail/mesh_topology.h"
#include "detail/progress.h"
#include "rgb/mesh/base_mesh.h"

namespace rgbdetail {

struct CageOptions {
    // First pass: refuse collapses that turn a face's normal by more than this (degrees); a second
    // pass without it runs when the first stops above the target.
    double max_normal_deviation_degrees = 60.0;
    // When the collapses stall above a component's share (an irreducible triangulation: every edge
    // lies on a non-facial triangle), random edge flips make collapses possible again; at most this
    // many flips per component before it stays where it stalled (make_cage then asks the other
    // components to give up the excess, or refuses the target).
    std::size_t max_flips = 20000;
    std::uint32_t seed = 1;
    // The dense mesh's sharp features to keep (dense_features.h), or none: a feature vertex is only
    // collapsed along a feature edge into its neighbour on the chain, never so that a feature edge
    // merges away, and the chains' anchors stay; so every feature chain of M is a chain of the cage's
    // edges between kept vertices, and no flip crosses one.
    const FeatureGraph* features = nullptr;
    // Told the share of the decimation done, many times while it runs (the faces removed, of those to
    // remove); returning false stops make_cage, which then throws Stopped.
    ProgressFunction progress;
};

struct Cage {
    std::vector<glm::dvec3> positions;
    std::vector<rgb::Triangle> triangles;
    // For each cage vertex, the input vertex it is (collapses keep original vertices and positions).
    std::vector<std::uint32_t> source_vertex;
    // The cage edges (a < b) that stand for chains of CageOptions::features, ascending.
    std::vector<std::array<std::uint32_t, 2>> feature_edges;
    // Edge flips made where the collapses stalled above a component's share (0 but near the
    // smallest counts).
    std::size_t flips = 0;
};

// Decimates the mesh to at most target_triangles triangles (and, when the mesh has more, at least
// about target_triangles / 3: each component gets a share of the target proportional to its area,
// at least its own smallest count, and is decimated to it). A mesh with no more than the target is
// returned as it is. Throws std::invalid_argument for an empty, one-triangle, all-degenerate
// (zero-area) or non-finite or non-manifold mesh, and for a target below smallest_cage_triangles
// (the message names that number: "the smallest is N triangles"). Where that bound is not
// attainable (it is exact for closed surfaces, genus 0 and a torus with one hole; see mesh_topology.cpp) or
// the search does not find it, a component stalls above its share: the others give up the excess
// when they can, and otherwise the target is refused with the count the stalled components reached
// ("the smallest that works here is N triangles"). Deterministic for given options.
Cage make_cage(std::span<const glm::dvec3> positions, std::span<const rgb::Triangle> triangles,
               std::size_t target_triangles, const CageOptions& options = {});

}  // namespace rgbdetail
