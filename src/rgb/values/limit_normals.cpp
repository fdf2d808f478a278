#include "rgb/values/limit_normals.h"

#include <cmath>
#include <memory>
#include <numbers>

#include <glm/geometric.hpp>

#include "rgb/mesh/base_mesh.h"
#include "rgb/mesh/mesh.h"
#include "rgb/rules/loop_rules.h"
#include "rgb/values/hierarchy_evaluator.h"
#include "rgb/values/loop_geometry.h"

// The limit tangent masks, derived here for the rules of loop_rules.h. One Loop step maps the
// control points of a vertex's 1-ring (v; p_0..p_{n-1}, counter-clockwise) to the next level's
// 1-ring by a matrix S. A row vector l with l S = lambda l (a left eigenvector) gives l.P^j =
// lambda^j l.P^0 on every finer level, and the limit surface around the vertex is, to first order,
// the limit point plus the components of the eigenvectors of the two largest eigenvalues below 1;
// their l.P are its tangents, and their cross product its normal. So the masks below are exact: the
// normal is that of the limit surface, not an estimate from a finite level.
//
// Interior vertex, valence n. Rows: p_k' = 3/8 v + 3/8 p_k + 1/8 (p_{k-1} + p_{k+1}) (indices mod n),
// v' = (1 - alpha) v + alpha/n sum p_k. For l_k = cos(2 pi k / n) or sin(2 pi k / n) and weight 0 on v,
// the weight of v in l S is 3/8 sum l_k = 0 and that of p_k is 3/8 l_k + 1/8 (l_{k-1} + l_{k+1}) =
// (3/8 + cos(2 pi / n) / 4) l_k: both are eigenvectors of lambda = 3/8 + cos(2 pi / n) / 4, Loop's
// subdominant eigenvalue, whatever alpha is. Tangents t1 = sum cos(2 pi k/n) p_k, t2 = sum
// sin(2 pi k/n) p_k, normal t1 x t2. (The masks of Loop's thesis, Hoppe et al. 1994 and OpenSubdiv's
// Sdc::Scheme<SCHEME_LOOP>::assignSmoothLimitTangentMasks.)
//
// Boundary vertex with k faces: ring p_0..p_k, p_0 and p_k its boundary neighbours. Rows:
// v' = 3/4 v + 1/8 (p_0 + p_k), p_0' = (v + p_0)/2, p_k' = (v + p_k)/2, and the interior rule for
// p_1..p_{k-1}.
// - Along the boundary: l = p_0 - p_k gives l S = 1/2 l (the tangent of the cubic B-spline the
//   boundary becomes).
// - Across, k >= 2: try l = (d; b, c_1..c_{k-1}, b) with c_m = sin(m theta), theta = pi/k. At p_m
//   (1 <= m < k) the weight is 3/8 c_m + 1/8 (c_{m-1} + c_{m+1}) with c_0 = sin 0 = 0 and
//   c_k = sin pi = 0 (the rows of p_0 and p_k do not hold p_m): (3/8 + cos(theta)/4) c_m, so
//   lambda = 3/8 + c/4 (c = cos theta, s = sin theta). The weights of p_0 and v must match:
//     b/2 + s/8 + d/8 = lambda b,     3/4 d + b + 3/8 sum_{m=1}^{k-1} sin(m theta) = lambda d,
//   with sum sin(m theta) = s / (1 - c). Solving: b = -s c / ((1 - c)(1 + 2c)),
//   d = -s / ((1 - c)(1 + 2c)). The across tangent is sum c_m p_m + b (p_0 + p_k) + d v. For k = 2 it
//   is p_1 - v and for k = 3 proportional to 2 (p_1 + p_2) - (p_0 + p_3) - 2 v: OpenSubdiv's masks for
//   those cases. For k >= 4 OpenSubdiv (after Hoppe et al. 1994, whose scheme changes the interior
//   edge rule next to irregular boundary vertices) drops the weight of v, which under these rules is
//   not an eigenvector; this one is.
// - Across, k = 1 (a single face): l = p_0 + p_1 - 2 v, with lambda = 1/4.
// Normal: along x across, which points like the faces (v, p_m, p_{m+1}) when the ring runs
// counter-clockwise. Caveat: the antisymmetric mode c_m = sin(2 m theta) has the eigenvalue
// 3/8 + cos(2 theta)/4, which reaches the boundary tangent's 1/2 at k = 6 and exceeds it beyond: the
// standard boundary rules are not tangent-plane continuous at boundary vertices with 6 or more faces
// (normals of nearby surface points do not converge; limit_normals_test measures it). The normal
// given there is still that of the plane of the boundary tangent and the across tangent.

namespace rgb {

namespace {

glm::dvec3 interior_normal(const glm::dvec3* ring, std::size_t n) {
    glm::dvec3 t1(0.0), t2(0.0);
    for (std::size_t k = 0; k < n; ++k) {
        const double angle = 2.0 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(n);
        t1 += std::cos(angle) * ring[k];
        t2 += std::sin(angle) * ring[k];
    }
    return glm::cross(t1, t2);
}

// ring: p_0..p_k.
glm::dvec3 boundary_normal(const glm::dvec3& v, const glm::dvec3* ring, std::size_t points) {
    const std::size_t k = points - 1;
    const glm::dvec3 along = ring[0] - ring[k];
    glm::dvec3 across;
    if (k == 1) {
        across = ring[0] + ring[1] - 2.0 * v;
    } else {
        const double theta = std::numbers::pi / static_cast<double>(k), c = std::cos(theta), s = std::sin(theta);
        const double scale = s / ((1.0 - c) * (1.0 + 2.0 * c));
        across = -scale * (c * (ring[0] + ring[k]) + v);
        for (std::size_t m = 1; m < k; ++m) across += std::sin(static_cast<double>(m) * theta) * ring[m];
    }
    return glm::cross(along, across);
}

glm::dvec3 normal_from_ring(const glm::dvec3& v, const std::vector<glm::dvec3>& ring, bool boundary) {
    const glm::dvec3 n = boundary ? boundary_normal(v, ring.data(), ring.size()) : interior_normal(ring.data(), ring.size());
    const double length = glm::length(n);
    return length > 0.0 ? n / length : n;
}

SurfacePoint stepped(const SurfacePoint& p, int from, int to) {
    SurfacePoint q = p;
    --q.a[static_cast<std::size_t>(from)];
    ++q.a[static_cast<std::size_t>(to)];
    return reduced(q);
}

// The ring of hierarchy vertex p as points.
std::vector<SurfacePoint> ring_points(const BaseMesh& base, const SurfacePoint& p) {
    if (p.level > 0) return ordered_ring(base, p);
    std::vector<SurfacePoint> ring;
    for (std::uint32_t w : base.ring(*base_vertex(base, p))) {
        const std::uint32_t h = base.vertex_halfedge(w);
        ring.push_back(corner_point(h / 3, static_cast<int>(h % 3)));
    }
    return ring;
}

// p^l of a ring point q (level <= l): from the mesh vertex that is q if `mesh_ring` has one (its
// addresses in canonical form, beside the vertices), else from the evaluator. Both give the same bits.
glm::dvec3 ring_control_point(const Mesh* mesh, const std::vector<std::pair<SurfacePoint, VertexId>>& mesh_ring,
                              HierarchyEvaluator& evaluator, const SurfacePoint& q, int l) {
    if (mesh) {
        const SurfacePoint key = canonical(mesh->base(), q);
        for (const auto& [address, w] : mesh_ring) {
            if (address != key) continue;
            if (q.level == l) return mesh->insertion_position(w);
            // The uncached limit, as for display: saving must not fill the operators' cache.
            return closed_form(mesh->insertion_position(w), limit_position_uncached(*mesh, w),
                               loop_gamma(mesh->uniform_valence(w), mesh->is_boundary(w)), l - q.level);
        }
    }
    return evaluator.control_point(q, l);
}

glm::dvec3 normal_at(const BaseMesh& base, const Mesh* mesh, const std::vector<std::pair<SurfacePoint, VertexId>>& mesh_ring,
                     HierarchyEvaluator& evaluator, const SurfacePoint& p, const glm::dvec3& centre) {
    const std::vector<SurfacePoint> points = ring_points(base, p);
    std::vector<glm::dvec3> ring;
    ring.reserve(points.size());
    for (const SurfacePoint& q : points) ring.push_back(ring_control_point(mesh, mesh_ring, evaluator, q, p.level));
    return normal_from_ring(centre, ring, is_boundary(base, p));
}

}  // namespace

std::vector<SurfacePoint> ordered_ring(const BaseMesh& base, const SurfacePoint& p) {
    int z = -1;
    for (int c = 0; c < 3; ++c)
        if (p.a[static_cast<std::size_t>(c)] == 0) z = c;
    if (z < 0)  // Inside the base face: the six lattice directions in angular order.
        return {stepped(p, 0, 1), stepped(p, 0, 2), stepped(p, 1, 2), stepped(p, 1, 0), stepped(p, 2, 0), stepped(p, 2, 1)};
    // On the base edge from corner i to corner j (opposite z), the face to its left: towards j, the
    // two points inside the face, towards i, then the two inside the face across the edge.
    const int i = (z + 1) % 3, j = (z + 2) % 3;
    std::vector<SurfacePoint> ring{stepped(p, i, j), stepped(p, i, z), stepped(p, j, z), stepped(p, j, i)};
    const std::uint32_t o = base.opposite(3 * p.face + static_cast<std::uint32_t>(i));
    if (o == BaseMesh::kNone) return ring;
    // In the face across, the halfedge o runs from the corner at j to the corner at i.
    const int at_j = static_cast<int>(o % 3), at_i = (at_j + 1) % 3, far = (at_j + 2) % 3;
    SurfacePoint q;
    q.face = o / 3;
    q.level = p.level;
    q.a[static_cast<std::size_t>(at_j)] = p.a[static_cast<std::size_t>(j)];
    q.a[static_cast<std::size_t>(at_i)] = p.a[static_cast<std::size_t>(i)];
    ring.push_back(stepped(q, at_j, far));
    ring.push_back(stepped(q, at_i, far));
    return ring;
}

glm::dvec3 limit_normal(const BaseMesh& base, HierarchyEvaluator& evaluator, const SurfacePoint& p) {
    return normal_at(base, nullptr, {}, evaluator, p, evaluator.insertion_position(p));
}

std::vector<glm::dvec3> limit_normals(const Mesh& mesh) {
    std::vector<glm::dvec3> normals(mesh.vertex_capacity(), glm::dvec3(0.0));
    // The evaluator's caches grow with what it evaluates: a fresh one every so many vertices keeps
    // them small on large meshes (neighbouring slots share most of their work).
    constexpr std::size_t kVerticesPerEvaluator = 4096;
    std::unique_ptr<HierarchyEvaluator> evaluator;
    std::size_t done = 0;
    std::vector<std::pair<SurfacePoint, VertexId>> mesh_ring;
    for (VertexId v : mesh.vertices()) {
        if (done++ % kVerticesPerEvaluator == 0) evaluator = std::make_unique<HierarchyEvaluator>(mesh.base());
        mesh_ring.clear();
        const HalfedgeId start = mesh.vertex_halfedge(v);
        HalfedgeId h = start;
        do {
            const VertexId w = mesh.to_vertex(h);
            mesh_ring.emplace_back(canonical(mesh.base(), mesh.address(w)), w);
            if (mesh.is_boundary(v) && !mesh.ccw_rotated(h).valid()) {
                // The last neighbour of a boundary vertex ends the boundary halfedge into it.
                const VertexId last = mesh.opposite_vertex(h);
                mesh_ring.emplace_back(canonical(mesh.base(), mesh.address(last)), last);
            }
            h = mesh.ccw_rotated(h);
        } while (h.valid() && h != start);
        normals[v.idx] = normal_at(mesh.base(), &mesh, mesh_ring, *evaluator, mesh.address(v), mesh.insertion_position(v));
    }
    return normals;
}

}  // namespace rgb
