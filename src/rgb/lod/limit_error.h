#pragma once
// The tolerance criterion (docs/requests.md "Tolerance to the limit surface"): how far from the Loop limit
// surface (on a cage with detail: from the dense surface, values/surface_error.h target_position) the
// displayed surface next to an edge of Σl can be while the edge stays unsplit.
//
// The displayed surface over a triangle T of Σl that the mesh holds unrefined is flat pieces between
// T's corners (shown at p^k for some k <= l, spec §4.6) and the midpoints of T's split edges (shown at
// p^(l+1)), cut as spec §1.3 says for the edges split. It is measured at T's samples, the 15 vertices
// of Σ(l+2) in T (hierarchy_triangle.h), against their exact limit points. An edge's value is the
// largest such error over its two triangles, over every way the rest of the mesh can show them with
// the edge unsplit: either other edge split or not, and each corner shown at level l or at the
// coarsest level at which its own error is still within the tolerance (any level between gives an
// error between those two, the error being convex along each corner's path p^k -> p^inf).
//
// A run of the LOD driver with this value and the tolerance as threshold (splitting past
// dependencies, lod_driver.h) ends with no unsplit edge above the tolerance. Then every corner is
// shown at a level at least as fine as that coarsest level (a coarser incident edge would have shown
// the corner's own error above it, and been split), and every face is a piece of some T with an
// unsplit edge whose value covered it; so every sample of every face is within the tolerance. And
// the result is the smallest RGB mesh in which no unsplit edge exceeds it.
#include <array>
#include <cstdint>
#include <memory>
#include <unordered_map>

#include "rgb/lod/lod_criteria.h"
#include "rgb/mesh/surface_point.h"
#include "rgb/values/face_grid_cache.h"
#include "rgb/values/hierarchy_evaluator.h"
#include "rgb/values/hierarchy_triangle.h"

namespace rgb {

class BaseMesh;

class LimitErrorCriterion {
public:
    // Which samples of a triangle beside the edge its value takes: all of them, over every way the rest
    // of the mesh can show the triangle (what a tolerance needs, above); or only those beside the edge,
    // in the two pieces of level l that stay next to it when the triangle's other two edges are split,
    // the departure that no other split removes (what a budget orders by, detail_error_value).
    enum class Samples { AnyNeighbourhood, BesideTheEdge };

    // Throws std::invalid_argument for a tolerance that is not positive and finite.
    LimitErrorCriterion(std::shared_ptr<const BaseMesh> base, double tolerance, Samples samples = Samples::AnyNeighbourhood);

    // The value of the edge (a, b) of Σl, l = the finer of their levels. Not for several threads at
    // once (the criterion fills its caches as it goes; the LOD driver and requests ask one edge at a time).
    double value(const SurfacePoint& a, const SurfacePoint& b);
    double tolerance() const { return tolerance_; }

private:
    struct TriangleKey {
        std::uint32_t face;
        int level;
        std::array<std::uint32_t, 3> first;  // the smallest corner: with the face and level, the triangle
        std::array<std::uint32_t, 3> sum;
        friend bool operator==(const TriangleKey&, const TriangleKey&) = default;
    };
    struct TriangleKeyHash {
        std::size_t operator()(const TriangleKey& k) const noexcept;
    };
    // The values of the three edges of t (edge i: corner i to corner i+1), t in its canonical
    // rotation (smallest corner first); each triangle is evaluated once for all its edges.
    const std::array<double, 3>& triangle_values(const HierarchyTriangle& t);

    std::shared_ptr<const BaseMesh> base_;
    HierarchyEvaluator evaluator_;
    // The limit points a triangle's samples, corners and midpoints need, read from grids of its base
    // face (the evaluator's bits, at a few array reads each instead of its address arithmetic).
    FaceGridCache grids_;
    double tolerance_;
    Samples samples_;
    std::unordered_map<TriangleKey, std::array<double, 3>, TriangleKeyHash> triangles_;
};

// The criterion as requests take it; the returned function owns its criterion (and its caches).
EdgeValue limit_error_value(const std::shared_ptr<const BaseMesh>& base, double tolerance);

// On a cage with detail (BaseMesh::detail): how far the displayed surface beside the edge departs
// from the dense surface, at the samples of its triangles that only its own split can bring closer
// (Samples::BesideTheEdge); what a budget orders the splits by there, so that it spends triangles
// where splitting brings the surface closest to it. With all of a triangle's samples, all three of its
// edges took the value of its worst sample wherever that lay, and a budget that stopped in their band
// split the edges far from it as readily as the one beside it: on the ridged torus at 1% its cage
// triangles across the valleys kept their largest departure, at the midpoint of an unsplit edge,
// while their other edges were split (docs/detail.md). Throws std::invalid_argument without detail.
EdgeValue detail_error_value(const std::shared_ptr<const BaseMesh>& base);

}  // namespace rgb
