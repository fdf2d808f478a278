#pragma once
// Level of detail by what the user means (docs/requests.md "Detail by size, accuracy and view"): a criterion,
// a number for every edge of the hierarchy computed from the addresses of its ends alone, and a
// threshold, over the whole surface or in a ball of base space.
//
//   - Set over the whole surface: the LOD driver's threshold run, splitting past dependencies
//     (lod_driver.h): the smallest RGB mesh in which no unsplit green edge has a value above the
//     threshold, whatever the mesh held before; a triangle budget stops it at a whole band or a
//     spatially coherent part of one.
//   - Refine splits every green edge meeting the region (its base-space segment comes within the
//     ball's radius of the centre) whose value is above the threshold, with what the RGB topology
//     needs, until none is left: the smallest mesh containing the current one with that property.
//   - Coarsen removes every vertex in the region (its base-space position in the ball) whose parent
//     edge's value is not above the threshold, with every vertex that cannot exist without one of
//     them.
//   - Set in a ball does both, coarsening first.
// Each result is a function of the current vertex set and the request alone (so of neither the
// order of work nor the input's storage), and a Set in a ball holding the whole surface gives the
// Set over the whole surface.
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>

#include <glm/vec3.hpp>

#include "rgb/lod/lod_driver.h"
#include "rgb/lod/requests.h"
#include "rgb/mesh/surface_point.h"

namespace rgb {

class BaseMesh;

// A criterion: the value of the edge (a, b) of Σl (l the finer of their levels). It must depend on
// the edge alone; it may keep caches.
using EdgeValue = std::function<double(const SurfacePoint& a, const SurfacePoint& b)>;

// Detail size: the edge's length in the uniform Loop mesh of its level (the bits of rgb::edge_length).
EdgeValue edge_length_value(const std::shared_ptr<const BaseMesh>& base);

// A criterion as the LOD driver takes it.
SplitValue on_mesh(EdgeValue value);

struct DetailRequest {
    RequestKind kind = RequestKind::Set;
    EdgeValue value;
    // Optional: the same values, bit for bit, computed from the mesh (rgb::edge_length for
    // edge_length_value), which a Set over the whole surface then uses: the driver keys such edges
    // from the limits it keeps by slot instead of descending the hierarchy evaluator for each.
    SplitValue mesh_value;
    double threshold = 0.0;  // split where the value is above it, keep only where it is
    std::optional<Sphere> sphere;  // none: the whole surface
    std::size_t max_triangles = 1'000'000;
    int max_level = kMaxLevel;  // edges of this level are never split
    // How much the values fall per level, for estimated_detail_triangles: 2 for a length (edges
    // halve), 4 for a distance to the limit surface (it falls with the square of the edge length).
    double shrink_per_level = 2.0;
};

// A lower estimate of the triangles the request leaves, made before any work and bounded whatever
// the threshold: each base face the region meets needs the level at which its largest level-0
// edge value falls to the threshold (shrink_per_level per level), capped at max_level; two levels
// less are counted, as a margin for values that fall faster. So a request whose result cannot fit
// (a threshold of 1e-300 asks for every face at the maximum level) is known at once.
double estimated_detail_triangles(const Mesh& mesh, const DetailRequest& request);

// Throws std::invalid_argument for a threshold that is negative or not finite, a bad sphere, or a
// request without a value. With budget_bound set the result is cut short: over the whole surface at
// a band of the driver's order, in a ball where the budget ran out.
LodReport apply_detail_request(Mesh& mesh, const DetailRequest& request);

// The LOD driver's settings that carry out a Set over the whole surface (for callers that run the
// driver a slice at a time, like the editor). Throws as apply_detail_request.
LodSettings whole_surface_settings(const DetailRequest& request);

// Whether the segment (p, q) comes within the ball (independent of the order of p and q).
bool segment_meets_sphere(glm::dvec3 p, glm::dvec3 q, const Sphere& sphere);

}  // namespace rgb
