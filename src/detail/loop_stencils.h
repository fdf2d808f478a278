#pragma once
// Explicit sparse Loop stencils of a cage (issue 28, "Fitting"): which linear combination of the cage's
// control points is each vertex of one or two uniform Loop steps, and each such vertex's limit
// position. Smooth Loop with boundaries as spec §4.1-§4.2 (docs in /work/shared: rgb-subdivision.md):
// Loop's original weights (rgb/rules/loop_rules.h's alpha_n and limit weights, so these stencils and
// the core give the same surface), boundary edges as creases (even 1/8, 3/4, 1/8; odd the midpoint;
// limit 1/6, 2/3, 1/6). Crease and corner tags (rgb/rules/sharp_features.h) are not handled yet:
// every interior edge is smooth.
//
// The cage is plain data (positions are not even needed: stencils depend on the connectivity alone):
// rgb::Triangle index triples, an oriented 2-manifold, possibly with boundary, every vertex used.
// The adjacency is this file's own, not rgb::Mesh's.
//
// Ordering of the vertices of level k+1 (deterministic, a function of the triangle list alone): the
// vertices of level k keep their indices, then one vertex per edge of level k in the order of the
// edges' first appearance in the faces (face f, halfedge corner i -> i+1, i = 0, 1, 2). Face f =
// (a, b, c) with edge points ab, bc, ca becomes the four faces 4f + 0..3:
// (a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca).
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include <Eigen/SparseCore>

#include "rgb/mesh/base_mesh.h"

namespace rgbdetail {

// Row-major: one row per evaluated point, one column per cage control point.
using StencilMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

// The adjacency of one level: edges, rings and boundary flags.
class LoopTopology {
public:
    static constexpr std::uint32_t kNone = 0xffffffffu;

    struct Edge {
        std::uint32_t a = 0, b = 0;          // as in the first face that has it (a -> b is its halfedge)
        std::uint32_t c = kNone, d = kNone;  // the vertex opposite in that face, in the other (kNone: boundary)
    };

    // Throws std::invalid_argument when the triangles are not an oriented 2-manifold over
    // vertex_count vertices with every vertex used (an index out of range, a repeated corner, a
    // directed edge used twice, a vertex whose faces form more than one fan, an unused vertex).
    LoopTopology(std::size_t vertex_count, std::span<const rgb::Triangle> triangles);

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

    // The triangles of one uniform Loop step, in the order of this file's header comment.
    std::vector<rgb::Triangle> refined_triangles() const;

private:
    std::vector<rgb::Triangle> triangles_;
    std::vector<Edge> edges_;
    std::vector<std::array<std::uint32_t, 3>> face_edges_;
    std::vector<std::vector<std::uint32_t>> rings_;
    std::vector<std::uint8_t> boundary_;
};

// One uniform Loop step, (V + E) x V: even rows (the vertices, kept indices) then odd rows (the edge
// points, edge order).
StencilMatrix subdivision_matrix(const LoopTopology& topology);
// V x V: each vertex's limit position from its level's control points.
StencilMatrix limit_matrix(const LoopTopology& topology);
// The weights of a vertex and of each neighbour that takes part: every ring neighbour inside, the two
// boundary neighbours on the boundary.
struct RingMask {
    double centre = 0.0, neighbour = 0.0;
};
// One row per vertex, from the mask that its boundary flag and valence give (limit_matrix's, the
// fit's Laplacian).
StencilMatrix ring_mask_matrix(const LoopTopology& topology, const std::function<RingMask(bool boundary, int valence)>& mask);

// The limit positions of the vertices of level `level` (0 = the cage's own vertices) as rows over
// the cage's control points: L_level * S_(level-1) * ... * S_0.
struct LoopStencils {
    int level = 0;
    StencilMatrix limit;                   // rows: vertices of that level; columns: cage vertices
    std::vector<rgb::Triangle> triangles;  // the triangles of that level, over the rows' indices
};
LoopStencils limit_stencils(std::size_t cage_vertex_count, std::span<const rgb::Triangle> cage_triangles, int level);

}  // namespace rgbdetail
