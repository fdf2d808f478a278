#pragma once
// Addresses of the vertices of the uniform hierarchy Σk above a base mesh (spec §3.5): a vertex of
// Σk is a point of a base triangle with barycentric coordinates (a0, a1, a2) / 2^k, integers that sum
// to 2^k. Every vertex an RGB mesh can ever hold has one, whether the adaptive mesh holds it or not,
// so the address is the vertex's identity in the hierarchy: its level, its parent edge, its stencil
// and its ring are arithmetic on it, and its base-space position (midpoint subdivision of the base
// mesh) is a fixed function of it.
//
// A point on a base edge or at a base vertex has several addresses (one per incident base face);
// every function here gives the same answer for each of them.
#include <array>
#include <cstdint>
#include <optional>

#include <glm/vec3.hpp>

#include "rgb/support/inline_vector.h"

namespace rgb {

class BaseMesh;

struct SurfacePoint {
    std::uint32_t face = 0;            // base face
    std::array<std::uint32_t, 3> a{};  // barycentric numerators, sum 2^level
    int level = 0;                     // reduced: level 0, or not all of a even

    friend bool operator==(const SurfacePoint&, const SurfacePoint&) = default;
};

// The address of base vertex `corner` of base face f.
SurfacePoint corner_point(std::uint32_t f, int corner);
// Divides out common factors of two, so that `level` is the level at which the vertex first appears.
SurfacePoint reduced(SurfacePoint p);
// The same point with denominator 2^k (k >= p.level).
std::array<std::uint32_t, 3> numerators_at(const SurfacePoint& p, int k);
// Twice the signed area of the triangle of three numerator triples of one level, in the plane of the
// free coordinates (a1, a2): positive when (p, q, r) runs counter-clockwise like the base face's corners.
std::int64_t lattice_orientation(const std::array<std::uint32_t, 3>& p, const std::array<std::uint32_t, 3>& q,
                                 const std::array<std::uint32_t, 3>& r);

// The base vertex p is, if it is one.
std::optional<std::uint32_t> base_vertex(const BaseMesh& base, const SurfacePoint& p);
// The base halfedge of p's face that p lies on, if p is a point of level >= 1 on a base edge.
std::optional<std::uint32_t> base_edge_of(const SurfacePoint& p);
// The address of p in base face g, if p lies on g's closed triangle.
std::optional<SurfacePoint> in_face(const BaseMesh& base, const SurfacePoint& p, std::uint32_t g);
// A representation chosen by a rule that does not depend on which face p was given in (base
// vertex: the face of its vertex halfedge; edge point: the smaller face id), for use as a key.
SurfacePoint canonical(const BaseMesh& base, const SurfacePoint& p);
bool is_boundary(const BaseMesh& base, const SurfacePoint& p);

// The midpoint of two points that are the ends of an edge of some Σk (so they share a base face).
SurfacePoint midpoint(const BaseMesh& base, const SurfacePoint& p, const SurfacePoint& q);

// Base-space position: the point of the base triangle (spec §3.5). Computed from the corners in an
// order that depends only on their positions, so every address of a point and every storage order of
// the input give the same bits.
glm::dvec3 base_space_position(const BaseMesh& base, const SurfacePoint& p);

// Spec §4.4: a vertex of level l >= 1 sits on an edge of Σ(l-1); its Loop stencil is the edge's two
// endpoints and (interior edges) the two vertices opposite the edge in Σ(l-1). Each opposite vertex
// is given in the base face of its triangle (ends, opposite), so these are also v's parent triangles.
struct PointStencil {
    SurfacePoint ends[2];
    InlineVector<SurfacePoint, 2> opposite;  // one on the boundary, where the Loop rule does not use it
    bool boundary = false;
};
PointStencil parent_stencil(const BaseMesh& base, const SurfacePoint& p);

// The neighbours of p (level >= 1) in Σk for k = p.level: six points, or four on the boundary with
// the two along the boundary first. (A base vertex's ring is BaseMesh::ring.)
InlineVector<SurfacePoint, 6> ring_at_own_level(const BaseMesh& base, const SurfacePoint& p);
// The same for k >= p.level: the neighbours of p (level >= 1) in Σk, in the same order.
InlineVector<SurfacePoint, 6> ring_at_level(const BaseMesh& base, const SurfacePoint& p, int k);

}  // namespace rgb
