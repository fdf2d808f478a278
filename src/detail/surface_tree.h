// The search tree over the dense mesh M's triangles that DenseSurface answers from: its layout and
// its build. Internal to src/detail (dense_surface.cpp searches it); the build is a file of its own
// because it is the long first step of a remesh, with progress reports and a stop of its own.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "detail/progress.h"
#include "rgb/mesh/base_mesh.h"

namespace rgbdetail::dense_surface_internal {

struct Corners {
    glm::dvec3 p0, p1, p2;
};

// The BVH as searched: each node holds its two children's boxes, in float rounded outwards, and
// what each child is (a node, a leaf of `count` triangles from slot `index`, or nothing), so that a
// visit reads one cache line; on a million triangles the searches are bound by cache misses.
enum ChildKind : std::uint8_t { kNoChild = 0, kInnerChild = 1, kLeafChild = 2 };
struct alignas(64) Node {
    float lo[2][3];
    float hi[2][3];
    std::uint32_t index[2];
    std::uint8_t kind[2];
    std::uint8_t count[2];

    glm::dvec3 box_lo(int c) const { return {lo[c][0], lo[c][1], lo[c][2]}; }
    glm::dvec3 box_hi(int c) const { return {hi[c][0], hi[c][1], hi[c][2]}; }
};

// Nodes from the root (index 0), each triangle's corners and original index by slot (the tree's
// order of the triangles: a leaf holds consecutive slots).
struct SurfaceTree {
    std::vector<Node> nodes;
    std::vector<Corners> corners;
    std::vector<std::uint32_t> original;
};

// Median splits on the longest axis of the centroids' box, leaves of at most four triangles; every
// box grown by box_pad, so that a triangle's rounded intersection or closest point is never outside
// it. Reports its share of the work through progress (which may throw to stop it).
SurfaceTree build_surface_tree(std::span<const glm::dvec3> positions, std::span<const rgb::Triangle> triangles,
                               double box_pad, const ProgressFunction& progress);

}  // namespace rgbdetail::dense_surface_internal
