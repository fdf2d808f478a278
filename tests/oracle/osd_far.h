#pragma once
// OpenSubdiv's Far as a test oracle (issues 12 and 13): uniform Loop refinement of a triangle mesh
// with crease and corner tags and an optional face-varying UV channel, computed by Far in double
// precision and handed back as plain data. Test-only: it links Debian's libosd-dev, which nothing in
// src/ may use. The rules Far applies are written down in docs/loop-creases.md and
// docs/loop-face-varying.md.
#include <array>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace osdoracle {

// Far's sharpness scale: 0 is smooth, 10 (Sdc::Crease::SHARPNESS_INFINITE) or more is infinitely
// sharp, values in between are semi-sharp (uniform creasing: one unit is used up per level).
inline constexpr double infinite_sharpness = 10.0;

// Sdc::Options::VTX_BOUNDARY_EDGE_ONLY / VTX_BOUNDARY_EDGE_AND_CORNER.
enum class BoundaryInterpolation { edge_only, edge_and_corner };

// Sdc::Options::FVAR_LINEAR_NONE, _CORNERS_ONLY, _CORNERS_PLUS1, _CORNERS_PLUS2, _BOUNDARIES, _ALL.
enum class UvInterpolation { none, corners_only, corners_plus1, corners_plus2, boundaries, all };

// Sdc::Crease::Rule of a vertex: which mask Far applies to it when it refines this level.
enum class VertexRule { smooth, dart, crease, corner };

struct SharpEdge {
    int a = 0, b = 0;  // base vertex indices; the edge must exist
    double sharpness = infinite_sharpness;
};

struct SharpVertex {
    int vertex = 0;
    double sharpness = infinite_sharpness;
};

// Face-varying UVs: each triangle corner names one of `values`; corners that share a value are joined
// in UV space, corners of the same vertex with different values are separated by a seam.
struct UvChannel {
    std::vector<glm::dvec2> values;
    std::vector<std::array<int, 3>> corners;  // parallel to FarInput::triangles
    UvInterpolation interpolation = UvInterpolation::corners_only;
};

struct FarInput {
    std::vector<glm::dvec3> positions;
    std::vector<std::array<int, 3>> triangles;  // counter-clockwise, manifold
    std::vector<SharpEdge> creases;
    std::vector<SharpVertex> corners;
    BoundaryInterpolation boundary = BoundaryInterpolation::edge_only;
    std::optional<UvChannel> uv;
};

// An edge of a level as Far stores it, with its sharpness there (boundary edges are infinitely sharp
// whatever the input says) and the index of the vertex Far inserts on it in the next level.
struct FarEdge {
    int a = 0, b = 0;
    double sharpness = 0.0;
    int child = -1;  // -1 on the last level
};

// Where a vertex of level k >= 1 comes from: the child of vertex `a` of level k-1, or the vertex
// inserted on the edge {a, b} of level k-1 (b = -1 for a vertex child). Chaining origins down to
// level 0 gives a vertex an identity independent of Far's numbering.
struct VertexOrigin {
    bool on_edge = false;
    int a = 0, b = -1;
};

struct FarLevel {
    std::vector<glm::dvec3> positions;
    std::vector<std::array<int, 3>> triangles;
    std::vector<FarEdge> edges;
    std::vector<double> vertex_sharpness;  // after the boundary option (edge-and-corner corners are 10)
    std::vector<VertexRule> rules;
    std::vector<int> vertex_child;                 // index in level k+1; empty on the last level
    std::vector<VertexOrigin> origins;             // empty on level 0
    std::vector<std::array<glm::dvec2, 3>> uv;     // per triangle corner; empty without a UV channel
    // Far's UV value index of each triangle corner: corners with the same index are one value (joined
    // in UV space), so this is the face-varying topology Far derived. Empty without a UV channel.
    std::vector<std::array<int, 3>> uv_value_index;
};

struct FarRefinement {
    std::vector<FarLevel> levels;  // 0 .. k
    // PrimvarRefiner::Limit applied to level k (Far's limit masks for level k's rules; see
    // docs/loop-creases.md §5 for where they are not the exact limit).
    std::vector<glm::dvec3> limit_positions;
    // PrimvarRefiner::LimitFaceVarying applied to level k, per triangle corner; empty without UVs.
    std::vector<std::array<glm::dvec2, 3>> limit_uv;
};

// Refines `input` uniformly `levels` times (0 to 10) with Far's Loop scheme and uniform creasing.
// Throws std::invalid_argument naming the offending triangle, edge or vertex when the input is not a
// manifold triangle mesh, a tag names a missing edge or vertex, or the UV channel does not fit; throws
// std::runtime_error if Far reports an error.
FarRefinement refine_uniform(const FarInput& input, int levels);

}  // namespace osdoracle
