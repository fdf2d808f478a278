#include "rgb/mesh/face_location.h"

#include <optional>
#include <queue>
#include <stdexcept>
#include <tuple>
#include <unordered_set>
#include <vector>

#include "rgb/mesh/mesh.h"
#include "rgb/mesh/surface_point.h"

namespace rgb {

namespace {

// The three corners of f as numerators over 2^level in base face g, if f lies in g.
std::optional<CornerNumerators> corners_in(const Mesh& mesh, FaceId f, std::uint32_t g, int level) {
    CornerNumerators out;
    const auto& fv = mesh.face_vertices(f);
    for (int c = 0; c < 3; ++c) {
        const SurfacePoint a = mesh.address(fv[c]);
        // Most corners are given in g itself: no conversion (this runs for every face loaded).
        const auto p = a.face == g ? std::optional<SurfacePoint>(a) : in_face(mesh.base(), a, g);
        if (!p) return std::nullopt;
        for (int i = 0; i < 3; ++i) out[c][i] = p->a[i] << (level - p->level);
    }
    // All three corners on g's boundary does not put f inside g: its centroid must be interior.
    for (int i = 0; i < 3; ++i)
        if (out[0][i] + out[1][i] + out[2][i] == 0) return std::nullopt;
    return out;
}

int top_level(const Mesh& mesh, FaceId f) {
    int level = 0;
    for (VertexId v : mesh.face_vertices(f)) level = std::max(level, mesh.level(v));
    return level;
}

// The base face holding f, and f's corners there as numerators over 2^level.
std::pair<std::uint32_t, CornerNumerators> locate(const Mesh& mesh, FaceId f, int level) {
    const BaseMesh& base = mesh.base();
    // A corner inside a base edge leaves two candidates, the faces on either side of that edge.
    for (VertexId v : mesh.face_vertices(f)) {
        const SurfacePoint p = mesh.address(v);
        const int zeros = (p.a[0] == 0) + (p.a[1] == 0) + (p.a[2] == 0);
        if (zeros != 1) continue;
        const int z = p.a[0] == 0 ? 0 : (p.a[1] == 0 ? 1 : 2);
        if (const auto c = corners_in(mesh, f, p.face, level)) return {p.face, *c};
        const std::uint32_t o = base.opposite(3 * p.face + static_cast<std::uint32_t>((z + 1) % 3));
        if (o != BaseMesh::kNone)
            if (const auto c = corners_in(mesh, f, o / 3, level)) return {o / 3, *c};
        break;
    }
    // Each corner's own face and, for a corner on a base edge, the faces across its edges.
    for (VertexId v : mesh.face_vertices(f)) {
        const SurfacePoint p = mesh.address(v);
        if (const auto c = corners_in(mesh, f, p.face, level)) return {p.face, *c};
        for (std::uint32_t i = 0; i < 3; ++i) {
            const std::uint32_t o = base.opposite(3 * p.face + i);
            if (o == BaseMesh::kNone) continue;
            if (const auto c = corners_in(mesh, f, o / 3, level)) return {o / 3, *c};
        }
    }
    // Three base vertices: f is a base face still. (Any other corner has a base face of its own,
    // tried above; and only a base vertex's id names a base vertex.)
    const VertexId v0 = mesh.face_vertices(f)[0];
    if (!mesh.is_base_vertex(v0)) throw std::logic_error("base_face_of: the face lies in no base face");
    std::uint32_t h = base.vertex_halfedge(v0.idx);
    do {
        if (const auto c = corners_in(mesh, f, h / 3, level)) return {h / 3, *c};
        h = base.ccw_rotated(h);
    } while (h != BaseMesh::kNone && h != base.vertex_halfedge(v0.idx));
    throw std::logic_error("base_face_of: the face lies in no base face");
}

// The cell of Σl holding the centroid of a triangle with corners c (numerators over 2^(l+1)), as
// numerators over 2^l.
CornerNumerators cell_corners(const CornerNumerators& c, int l) {
    // The centroid, in units of Σl, lies strictly inside the cell of Σl that holds f: the integer
    // parts of its barycentric coordinates sum to 2^l - 1 in an upright cell, 2^l - 2 in an upside-down one.
    std::array<std::uint32_t, 3> cell;
    std::uint32_t sum = 0;
    for (int i = 0; i < 3; ++i) {
        cell[i] = (c[0][i] + c[1][i] + c[2][i]) / 6;
        sum += cell[i];
    }
    const bool upright = sum + 1 == (std::uint32_t(1) << l);
    CornerNumerators corners;
    for (int k = 0; k < 3; ++k) {
        corners[k] = cell;
        if (upright) {
            corners[k][k] += 1;
        } else {
            corners[k][(k + 1) % 3] += 1;
            corners[k][(k + 2) % 3] += 1;
        }
    }
    return corners;
}

}  // namespace

std::uint32_t base_face_of(const Mesh& mesh, FaceId f) {
    // A corner inside a base face (not on its edges) names it; most faces have one.
    for (VertexId v : mesh.face_vertices(f)) {
        const SurfacePoint p = mesh.address(v);
        if (p.a[0] != 0 && p.a[1] != 0 && p.a[2] != 0) return p.face;
    }
    return locate(mesh, f, top_level(mesh, f)).first;
}

std::array<SurfacePoint, 3> parent_triangle(const Mesh& mesh, FaceId f, std::uint32_t base_face) {
    const int l = mesh.level(f);
    const CornerNumerators cell = cell_corners(*corners_in(mesh, f, base_face, l + 1), l);
    std::array<SurfacePoint, 3> corners;
    for (int k = 0; k < 3; ++k) corners[k] = reduced(SurfacePoint{base_face, cell[k], l});
    return corners;
}

FaceCorners face_corners(const Mesh& mesh, FaceId f) {
    FaceCorners c;
    c.top = top_level(mesh, f);
    std::tie(c.base_face, c.numerators) = locate(mesh, f, c.top);
    return c;
}

CornerNumerators corners_at(const FaceCorners& corners, int level) {
    CornerNumerators out = corners.numerators;
    for (auto& corner : out)
        for (std::uint32_t& x : corner) x <<= level - corners.top;
    return out;
}

CornerNumerators parent_corners(const FaceCorners& corners, int l) {
    CornerNumerators cell = cell_corners(corners_at(corners, l + 1), l);
    for (auto& corner : cell)
        for (std::uint32_t& x : corner) x <<= 1;
    return cell;
}

FaceId face_containing(const Mesh& mesh, std::uint32_t base_face, const std::array<std::uint32_t, 3>& target, int level) {
    // Best-first search inside the base face: always expand the face whose centroid is nearest the
    // target. It reaches the target along about a straight line, and it cannot miss it.
    auto distance = [&](const CornerNumerators& c) {
        double d = 0;
        for (int i = 0; i < 3; ++i) {
            const double x = (double(c[0][i]) + c[1][i] + c[2][i]) / 3.0 - target[i];
            d += x * x;
        }
        return d;
    };
    using Entry = std::pair<double, std::uint32_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
    std::unordered_set<std::uint32_t> seen;
    const VertexId corner(mesh.base().face(base_face)[0]);
    HalfedgeId h = mesh.vertex_halfedge(corner);
    do {
        const FaceId f = Mesh::face(h);
        if (const auto c = corners_in(mesh, f, base_face, level)) {
            open.push({distance(*c), f.idx});
            seen.insert(f.idx);
        }
        h = mesh.ccw_rotated(h);
    } while (h.valid() && h != mesh.vertex_halfedge(corner));
    while (!open.empty()) {
        const FaceId f(open.top().second);
        open.pop();
        const auto c = *corners_in(mesh, f, base_face, level);
        if (lattice_orientation(c[0], c[1], target) >= 0 && lattice_orientation(c[1], c[2], target) >= 0 &&
            lattice_orientation(c[2], c[0], target) >= 0)
            return f;
        for (int i = 0; i < 3; ++i) {
            const HalfedgeId o = mesh.opposite(Mesh::halfedge(f, i));
            if (!o.valid() || !seen.insert(Mesh::face(o).idx).second) continue;
            if (const auto n = corners_in(mesh, Mesh::face(o), base_face, level)) open.push({distance(*n), Mesh::face(o).idx});
        }
    }
    throw std::logic_error("face_containing: the point is not in the base face");
}

}  // namespace rgb
