#include "rgb/values/surface_error.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <stdexcept>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "rgb/mesh/detail_positions.h"
#include "rgb/mesh/face_location.h"
#include "rgb/mesh/mesh.h"
#include "rgb/values/face_grid_limits.h"
#include "rgb/values/hierarchy_evaluator.h"
#include "rgb/values/hierarchy_triangle.h"
#include "rgb/support/parallel.h"
#include "rgb/values/loop_geometry.h"

namespace rgb {

namespace {

using Numerators = std::array<std::uint32_t, 3>;

std::int64_t cross(const Numerators& p, const Numerators& q, const Numerators& r) {
    const std::int64_t ux = std::int64_t(q[1]) - p[1], uy = std::int64_t(q[2]) - p[2];
    const std::int64_t vx = std::int64_t(r[1]) - p[1], vy = std::int64_t(r[2]) - p[2];
    return ux * vy - uy * vx;
}

}  // namespace

glm::dvec3 target_position(const BaseMesh& base, HierarchyEvaluator& evaluator, const SurfacePoint& p) {
    if (const DetailPositions* detail = base.detail()) return detail->position(base, p);
    return evaluator.limit_position(p);
}

namespace {

// A face's corners as numerators over 2^(l+2) in base face g (l its level), and the corners of the
// triangle of Σl it is a piece of, in parent_triangle's order, over 2^l: from its corners' addresses
// at l + 1 (a face's corners are of level l + 1 at most), converted only where a corner's address is
// in another face (a corner on a base edge), with none of parent_triangle's reducing.
struct FaceLattice {
    std::array<Numerators, 3> corners, parent;
};

FaceLattice face_lattice(const Mesh& mesh, FaceId f, std::uint32_t g, int level) {
    FaceCorners at;
    at.base_face = g;
    at.top = level + 1;
    for (std::size_t c = 0; c < 3; ++c) {
        const SurfacePoint a = mesh.address(mesh.face_vertices(f)[c]);
        at.numerators[c] = numerators_at(a.face == g ? a : *in_face(mesh.base(), a, g), level + 1);
    }
    FaceLattice out;
    out.corners = corners_at(at, level + 2);
    out.parent = parent_corners(at, level);  // over 2^(l+1), the lattice's corners even
    for (Numerators& corner : out.parent)
        for (std::uint32_t& x : corner) x >>= 1;
    return out;
}

// face_surface_error of face f in base face g, with the face's corners shown at shown_at(v) and the
// samples' target points from target_at(sample), the sample as numerators over 2^(l+2) (not reduced).
template <class Shown, class Target>
SurfaceError face_error_shown(const Mesh& mesh, FaceId f, std::uint32_t g, const Shown& shown_at, Target&& target_at) {
    SurfaceError out;
    const int level = mesh.level(f);
    const FaceLattice lattice = face_lattice(mesh, f, g, level);
    const std::array<Numerators, 3>& corners = lattice.corners;
    std::array<glm::dvec3, 3> shown;
    for (std::size_t c = 0; c < 3; ++c) shown[c] = shown_at(mesh.face_vertices(f)[c]);
    // The samples of the face are those of the triangle of Σl it is a piece of that lie in it.
    HierarchyTriangle parent;
    parent.face = g;
    parent.level = level;
    parent.corners = lattice.parent;
    const std::int64_t area = cross(corners[0], corners[1], corners[2]);
    // A face's area is a power of two in units of Σ(l+2) (16 for a whole triangle of Σl, 8 for a
    // half, 4 for a quarter), so a weight is its numerator times 1/area, exactly the quotient: no
    // division per sample.
    if (area <= 0 || !std::has_single_bit(static_cast<std::uint64_t>(area)))
        throw std::logic_error("face_error_shown: a face's lattice area is no power of two");
    const double inverse = 1.0 / double(area);
    // A whole triangle of Σl (area 16: every face of a uniform level) holds all 15 samples, and the
    // crosses are affine in the sample, so its weight at a face corner is its parent weight at the
    // same corner times 1/4, the quotient's bits: no inside test and no crosses per sample.
    const bool whole = area == 16;
    std::array<std::size_t, 3> parent_corner{};
    for (std::size_t c = 0; whole && c < 3; ++c)
        for (std::size_t k = 0; k < 3; ++k)
            if (corners[c] == Numerators{4 * lattice.parent[k][0], 4 * lattice.parent[k][1], 4 * lattice.parent[k][2]}) parent_corner[c] = k;
    const std::array<int, 3> order = interpolation_order(shown);
    // The largest error is kept as its square too: sqrt is monotone, so a sample whose square is no
    // larger than the largest square yet cannot have a larger error, and only the others need sqrt.
    double max_squared = 0.0;
    for (const SampleWeights& w : sample_weights()) {
        const SurfacePoint s = parent.sample_at_level(w);
        std::array<double, 3> weights;
        if (whole) {
            for (std::size_t c = 0; c < 3; ++c) weights[c] = double(w[parent_corner[c]]) * 0.25;
        } else {
            const Numerators& q = s.a;
            const std::int64_t w0 = cross(q, corners[1], corners[2]), w1 = cross(corners[0], q, corners[2]),
                               w2 = cross(corners[0], corners[1], q);
            if (w0 < 0 || w1 < 0 || w2 < 0) continue;
            weights = {double(w0) * inverse, double(w1) * inverse, double(w2) * inverse};
        }
        const glm::dvec3 limit = target_at(s);
        // glm::distance(shown point, limit), as sqrt(dot(d, d)) of d = limit - shown point.
        const glm::dvec3 d = limit - interpolate_in_order(shown, order, weights);
        const double squared = glm::dot(d, d);
        ++out.samples;
        if (squared <= max_squared) continue;
        max_squared = squared;
        const double error = std::sqrt(squared);
        if (error > out.max_error) {
            out.max_error = error;
            out.where = limit;
        }
    }
    return out;
}

}  // namespace

SurfaceError face_surface_error(const Mesh& mesh, HierarchyEvaluator& evaluator, FaceId f) {
    return face_error_shown(mesh, f, base_face_of(mesh, f), [&](VertexId v) { return displayed_position(mesh, v); },
                            [&](const SurfacePoint& s) { return target_position(mesh.base(), evaluator, reduced(s)); });
}

namespace {

// LOD0 faces per chunk of base faces that surface_errors_at measures with one evaluator: small enough
// that its caches stay in the processor's caches, large enough that the values a chunk shares with
// its neighbours (points on the base edges between them, and their coarser ancestors) are few.
constexpr std::size_t kFacesPerChunk = 512;
// A base face's grid is filled whole where the finest mesh has at least 1/kFillShare of the faces of
// a uniform refinement to its deepest level there (see surface_errors_at).
constexpr std::uint32_t kFillShare = 8;

// Each mesh's live faces by base face: the faces of base face g are faces[start[g]..start[g + 1]),
// in slot order.
struct FacesByBaseFace {
    std::vector<std::uint32_t> start, faces;
};

FacesByBaseFace faces_by_base_face(const Mesh& mesh) {
    FacesByBaseFace out;
    const std::size_t n = mesh.base().num_faces();
    std::vector<std::uint32_t> base_of(mesh.face_capacity());
    out.start.assign(n + 1, 0);
    parallel_for(mesh.face_capacity(), 1 << 14, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
            if (mesh.is_live(FaceId(static_cast<std::uint32_t>(i)))) base_of[i] = base_face_of(mesh, FaceId(static_cast<std::uint32_t>(i)));
    });
    for (FaceId f : mesh.faces()) ++out.start[base_of[f.idx] + 1];
    for (std::size_t g = 0; g < n; ++g) out.start[g + 1] += out.start[g];
    out.faces.resize(out.start[n]);
    std::vector<std::uint32_t> next(out.start.begin(), out.start.end() - 1);
    for (FaceId f : mesh.faces()) out.faces[next[base_of[f.idx]]++] = f.idx;
    return out;
}

// The larger error, the first face in slot order where tied.
struct FaceError {
    SurfaceError error;
    std::uint32_t face = 0;
};

void take(FaceError& into, const SurfaceError& error, std::uint32_t face) {
    into.error.samples += error.samples;
    if (error.max_error > into.error.max_error || (error.max_error == into.error.max_error && error.max_error > 0.0 && face < into.face)) {
        into.error.max_error = error.max_error;
        into.error.where = error.where;
        into.face = face;
    }
}

}  // namespace

std::vector<SurfaceError> surface_errors_at(std::span<const Mesh* const> meshes, std::span<const std::vector<glm::dvec3>> corner_positions) {
    if (meshes.empty()) return {};
    const BaseMesh& base = meshes[0]->base();
    std::vector<FacesByBaseFace> groups;
    for (const Mesh* mesh : meshes) groups.push_back(faces_by_base_face(*mesh));
    // Chunks of consecutive base faces with about kFacesPerChunk faces of the first (finest) mesh.
    std::vector<std::uint32_t> chunk_start{0};
    for (std::uint32_t g = 0; g < base.num_faces(); ++g)
        if (groups[0].start[g + 1] - groups[0].start[chunk_start.back()] >= kFacesPerChunk) chunk_start.push_back(g + 1);
    if (chunk_start.back() != base.num_faces()) chunk_start.push_back(static_cast<std::uint32_t>(base.num_faces()));
    const std::size_t chunks = chunk_start.size() - 1;
    // The deepest samples in each base face: two levels below its deepest face in any mesh.
    std::vector<int> deepest(base.num_faces(), 0);
    for (std::size_t m = 0; m < meshes.size(); ++m)
        for (std::uint32_t g = 0; g < base.num_faces(); ++g)
            for (std::uint32_t k = groups[m].start[g]; k < groups[m].start[g + 1]; ++k)
                deepest[g] = std::max(deepest[g], meshes[m]->level(FaceId(groups[m].faces[k])) + 2);
    // Per thread one evaluator, emptied between chunks, and one grid of the limit points inside a base
    // face (face_grid_limits.h); within a base face every mesh in turn, finest first, so that a
    // coarser mesh's samples that a finer one has are looked up. The threads take the chunks in turn
    // as they finish the last (on a busy machine one may get far less of the processor than the
    // other); each chunk's errors are its own and `take` keeps the same one whatever the order.
    const std::size_t blocks = parallel_blocks(chunks, 1);
    std::vector<std::vector<FaceError>> found(blocks, std::vector<FaceError>(meshes.size()));
    const DetailPositions* detail = base.detail();
    std::atomic<std::size_t> next_chunk = 0;
    parallel_blocks_for(blocks, blocks, [&](std::size_t b, std::size_t, std::size_t) {
        HierarchyEvaluator evaluator(base);
        FaceGridLimits grid(base, evaluator);
        const auto target = [&](const SurfacePoint& s) { return detail ? detail->position(base, reduced(s)) : grid.limit_position(s); };
        for (std::size_t c = next_chunk++; c < chunks; c = next_chunk++) {
            evaluator.clear();
            for (std::uint32_t g = chunk_start[c]; g < chunk_start[c + 1]; ++g) {
                grid.start(g, deepest[g]);
                // Where the finest mesh's faces are at least an eighth of a uniform level l = deepest - 2
                // (4^l faces), its samples are enough of the grid's points that computing them all at
                // once is cheaper than one by one (measured on the bunny's budget sets: a
                // third did worse, as did filling nearly always).
                if (grid.level() == deepest[g] && deepest[g] >= 2 &&
                    kFillShare * (groups[0].start[g + 1] - groups[0].start[g]) >= std::uint32_t(1) << (2 * (deepest[g] - 2)))
                    grid.fill();
                for (std::size_t m = 0; m < meshes.size(); ++m) {
                    const std::vector<glm::dvec3>& shown = corner_positions[m];
                    const FacesByBaseFace& group = groups[m];
                    for (std::uint32_t k = group.start[g]; k < group.start[g + 1]; ++k) {
                        const FaceId f(group.faces[k]);
                        take(found[b][m], face_error_shown(*meshes[m], f, g, [&](VertexId v) { return shown[v.idx]; }, target), f.idx);
                    }
                }
            }
        }
    });
    std::vector<SurfaceError> out;
    for (std::size_t m = 0; m < meshes.size(); ++m) {
        FaceError total;
        for (const std::vector<FaceError>& block : found) take(total, block[m].error, block[m].face);
        out.push_back(total.error);
    }
    return out;
}

SurfaceError surface_error_at(const Mesh& mesh, const std::vector<glm::dvec3>& corner_positions) {
    const Mesh* const meshes[] = {&mesh};
    return surface_errors_at(meshes, std::span(&corner_positions, 1))[0];
}

// face_surface_error's corners and targets, the faces taken base face by base face with the grids of
// surface_errors_at (the same bits, and the same face where tied: the first in slot order): the
// tolerance requests print this error, which through the evaluator alone cost a third of a request.
SurfaceError displayed_surface_error(const Mesh& mesh) {
    std::vector<glm::dvec3> shown(mesh.vertex_capacity());
    for (VertexId v : mesh.vertices()) shown[v.idx] = displayed_position(mesh, v);
    return surface_error_at(mesh, shown);
}

double bounding_box_diagonal(const BaseMesh& base) {
    glm::dvec3 lo(1e300), hi(-1e300);
    for (std::uint32_t v = 0; v < base.num_vertices(); ++v) {
        lo = glm::min(lo, base.position(v));
        hi = glm::max(hi, base.position(v));
    }
    return glm::distance(lo, hi);
}

}  // namespace rgb
