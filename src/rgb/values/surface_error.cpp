#include "rgb/values/surface_error.h"

#include <array>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "rgb/mesh/detail_positions.h"
#include "rgb/mesh/face_location.h"
#include "rgb/mesh/mesh.h"
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

// face_surface_error with the face's corners shown at shown(v).
template <class Shown>
SurfaceError face_error_shown(const Mesh& mesh, HierarchyEvaluator& evaluator, FaceId f, const Shown& shown_at) {
    const BaseMesh& base = mesh.base();
    SurfaceError out;
    const int level = mesh.level(f);
    const std::uint32_t g = base_face_of(mesh, f);
    std::array<Numerators, 3> corners;
    std::array<glm::dvec3, 3> shown;
    for (int c = 0; c < 3; ++c) {
        const VertexId v = mesh.face_vertices(f)[static_cast<std::size_t>(c)];
        corners[static_cast<std::size_t>(c)] = numerators_at(*in_face(base, mesh.address(v), g), level + 2);
        shown[static_cast<std::size_t>(c)] = shown_at(v);
    }
    // The samples of the face are those of the triangle of Σl it is a piece of that lie in it.
    HierarchyTriangle parent;
    parent.face = g;
    parent.level = level;
    const std::array<SurfacePoint, 3> t = parent_triangle(mesh, f, g);
    for (std::size_t c = 0; c < 3; ++c) parent.corners[c] = numerators_at(t[c], level);
    const std::int64_t area = cross(corners[0], corners[1], corners[2]);
    for (const SampleWeights& w : sample_weights()) {
        const SurfacePoint s = parent.sample(w);
        const Numerators q = numerators_at(s, level + 2);
        const std::int64_t w0 = cross(q, corners[1], corners[2]), w1 = cross(corners[0], q, corners[2]),
                           w2 = cross(corners[0], corners[1], q);
        if (w0 < 0 || w1 < 0 || w2 < 0) continue;
        const std::array<double, 3> weights{double(w0) / double(area), double(w1) / double(area), double(w2) / double(area)};
        const glm::dvec3 limit = target_position(base, evaluator, s);
        const double error = glm::distance(interpolate(shown, weights), limit);
        ++out.samples;
        if (error > out.max_error) {
            out.max_error = error;
            out.where = limit;
        }
    }
    return out;
}

}  // namespace

SurfaceError face_surface_error(const Mesh& mesh, HierarchyEvaluator& evaluator, FaceId f) {
    return face_error_shown(mesh, evaluator, f, [&](VertexId v) { return displayed_position(mesh, v); });
}

SurfaceError surface_error_at(const Mesh& mesh, const std::vector<glm::dvec3>& corner_positions) {
    // Per block of face slots its own evaluator (it caches), the blocks joined in slot order.
    std::vector<SurfaceError> blocks(parallel_blocks(mesh.face_capacity(), 1 << 12));
    parallel_blocks_for(mesh.face_capacity(), blocks.size(), [&](std::size_t b, std::size_t begin, std::size_t end) {
        HierarchyEvaluator evaluator(mesh.base());
        for (std::size_t i = begin; i < end; ++i) {
            const FaceId f(static_cast<std::uint32_t>(i));
            if (!mesh.is_live(f)) continue;
            const SurfaceError face = face_error_shown(mesh, evaluator, f, [&](VertexId v) { return corner_positions[v.idx]; });
            blocks[b].samples += face.samples;
            if (face.max_error > blocks[b].max_error) {
                blocks[b].max_error = face.max_error;
                blocks[b].where = face.where;
            }
        }
    });
    SurfaceError out;
    for (const SurfaceError& block : blocks) {
        out.samples += block.samples;
        if (block.max_error > out.max_error) {
            out.max_error = block.max_error;
            out.where = block.where;
        }
    }
    return out;
}

SurfaceError displayed_surface_error(const Mesh& mesh) {
    HierarchyEvaluator evaluator(mesh.base());
    SurfaceError out;
    for (FaceId f : mesh.faces()) {
        const SurfaceError face = face_surface_error(mesh, evaluator, f);
        out.samples += face.samples;
        if (face.max_error > out.max_error) {
            out.max_error = face.max_error;
            out.where = face.where;
        }
    }
    return out;
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
