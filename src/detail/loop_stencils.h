#pragma once
// Explicit sparse Loop stencils of a cage (issue 28, "Fitting"): which linear combination of the cage's
// control points is each vertex of one or two uniform Loop steps, and each such vertex's limit
// position. Loop with the core's crease and corner tags (rgb/rules/sharp_features.h), exactly as
// docs/loop-creases.md states the rules and the core evaluates them (spec §4.1-§4.2 without tags;
// docs in /work/shared: rgb-subdivision.md): Loop's original weights (rgb/rules/loop_rules.h's
// alpha_n and limit weights, rgb/rules/dart_masks.h's dart limit, so these stencils and the core give
// the same surface); boundary edges infinitely sharp whatever the tags say.
//  * Tags pass to the next level as OpenSubdiv's uniform creasing does (§2): both halves of an edge
//    of sharpness s get s - 1 (10, infinite, stays 10), the edges inside a face are smooth, a kept
//    vertex's corner sharpness loses one too, a new vertex has none.
//  * Rule of a vertex at a level (§2): corner if it has a corner sharpness or three or more sharp
//    edges, crease with two, dart with one, smooth with none. Even rows: smooth and dart by Loop's
//    mask, crease 3/4 + 1/8 of each crease neighbour, corner the vertex itself. Odd rows: the midpoint
//    on a sharp edge, Loop's edge mask on a smooth one, whatever the rules of its ends (§3).
//  * Limits (§4, §6): smooth (1 - c_n, c_n / n), crease 2/3 + 1/6 of each crease neighbour, corner
//    the vertex, dart the exact dart limit mask lambda_n (not the smooth mask OpenSubdiv's Limit
//    applies). A vertex that a semi-sharp tag still reaches first steps its one-ring (closed under
//    refinement) level by level until every finite sharpness at it has run out (§5.1), then takes its
//    final rule's limit mask.
//
// The cage is plain data (positions are not even needed: stencils depend on the connectivity and the
// tags alone): rgb::Triangle index triples, an oriented 2-manifold, possibly with boundary, every
// vertex used. The adjacency is this file's own, not rgb::Mesh's.
//
// Ordering of the vertices of level k+1 (deterministic, a function of the triangle list alone): the
// vertices of level k keep their indices, then one vertex per edge of level k in the order of the
// edges' first appearance in the faces (face f, halfedge corner i -> i+1, i = 0, 1, 2). Face f =
// (a, b, c) with edge points ab, bc, ca becomes the four faces 4f + 0..3:
// (a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca).
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/SparseCore>

#include "rgb/mesh/base_mesh.h"
#include "rgb/mesh/vertex_rules.h"
#include "rgb/rules/sharp_features.h"

namespace rgbdetail {

// Row-major: one row per evaluated point, one column per cage control point.
using StencilMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

// The adjacency of one level and its sharpness: edges, rings, boundary flags, tags.
class LoopTopology {
public:
    static constexpr std::uint32_t kNone = 0xffffffffu;

    struct Edge {
        std::uint32_t a = 0, b = 0;          // as in the first face that has it (a -> b is its halfedge)
        std::uint32_t c = kNone, d = kNone;  // the vertex opposite in that face, in the other (kNone: boundary)
    };

    // Throws std::invalid_argument when the triangles are not an oriented 2-manifold over
    // vertex_count vertices with every vertex used (an index out of range, a repeated corner, a
    // directed edge used twice, a vertex whose faces form more than one fan, an unused vertex), or
    // when a tag names a missing edge or vertex or has a negative sharpness. Tags are read as BaseMesh
    // reads them: a later tag of the same edge or vertex replaces an earlier one, above 10 counts as
    // 10, and edge-and-corner boundaries make every boundary vertex with a single face a corner.
    LoopTopology(std::size_t vertex_count, std::span<const rgb::Triangle> triangles, const rgb::SharpFeatures& features);

    std::size_t num_vertices() const { return rings_.size(); }
    std::size_t num_faces() const { return triangles_.size(); }
    std::span<const rgb::Triangle> triangles() const { return triangles_; }
    std::span<const Edge> edges() const { return edges_; }
    // The three edge indices of face f (edge of corner i -> i+1).
    const std::array<std::uint32_t, 3>& face_edges(std::size_t f) const { return face_edges_[f]; }
    bool is_boundary(std::uint32_t v) const { return boundary_[v] != 0; }
    // The neighbours of v counter-clockwise; for a boundary vertex the first and last are its two
    // boundary neighbours (first: the end of its outgoing boundary halfedge).
    std::span<const std::uint32_t> ring(std::uint32_t v) const { return rings_[v]; }
    // The edge from v to each of its ring's vertices, in ring order.
    std::span<const std::uint32_t> ring_edges(std::uint32_t v) const { return ring_edges_[v]; }

    // Sharpness at this level (0 smooth, 1-9 semi-sharp, 10 infinite): boundary edges 10.
    int edge_sharpness(std::uint32_t e) const { return edge_sharpness_[e]; }
    int corner_sharpness(std::uint32_t v) const { return corner_sharpness_[v]; }
    // v's rule at this level (header comment), and the ends of its sharp edges in ring order (a
    // boundary vertex's two boundary neighbours among them).
    rgb::VertexRule rule(std::uint32_t v) const;
    std::vector<std::uint32_t> sharp_neighbours(std::uint32_t v) const;

    // The triangles and the tags of one uniform Loop step, in the order of this file's header comment.
    std::vector<rgb::Triangle> refined_triangles() const;
    rgb::SharpFeatures refined_features() const;

private:
    std::vector<rgb::Triangle> triangles_;
    std::vector<Edge> edges_;
    std::vector<std::array<std::uint32_t, 3>> face_edges_;
    std::vector<std::vector<std::uint32_t>> rings_, ring_edges_;
    std::vector<std::uint8_t> boundary_;
    std::vector<std::uint8_t> edge_sharpness_, corner_sharpness_;
    rgb::BoundaryInterpolation boundary_interpolation_ = rgb::BoundaryInterpolation::EdgeOnly;
};

// One uniform Loop step, (V + E) x V: even rows (the vertices, kept indices) then odd rows (the edge
// points, edge order).
StencilMatrix subdivision_matrix(const LoopTopology& topology);
// V x V: each vertex's exact limit position from its level's control points.
StencilMatrix limit_matrix(const LoopTopology& topology);

// The limit positions of the vertices of level `level` (0 = the cage's own vertices) as rows over
// the cage's control points: L_level * S_(level-1) * ... * S_0.
struct LoopStencils {
    int level = 0;
    StencilMatrix limit;                   // rows: vertices of that level; columns: cage vertices
    std::vector<rgb::Triangle> triangles;  // the triangles of that level, over the rows' indices
};
LoopStencils limit_stencils(std::size_t cage_vertex_count, std::span<const rgb::Triangle> cage_triangles,
                            const rgb::SharpFeatures& cage_features, int level);

}  // namespace rgbdetail
