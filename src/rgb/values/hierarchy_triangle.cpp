#include "rgb/values/hierarchy_triangle.h"

#include <algorithm>
#include <stdexcept>

#include "rgb/mesh/base_mesh.h"
#include "rgb/mesh/surface_point.h"

namespace rgb {

namespace {

std::array<SampleWeights, kSamplesPerTriangle> make_sample_weights() {
    std::array<SampleWeights, kSamplesPerTriangle> w{};
    std::size_t n = 0;
    for (int i = 4; i >= 0; --i)
        for (int j = 4 - i; j >= 0; --j) w[n++] = {i, j, 4 - i - j};
    return w;
}

}  // namespace

const std::array<SampleWeights, kSamplesPerTriangle>& sample_weights() {
    static const std::array<SampleWeights, kSamplesPerTriangle> weights = make_sample_weights();
    return weights;
}

SurfacePoint HierarchyTriangle::corner(int c) const {
    SurfacePoint p;
    p.face = face;
    p.level = level;
    p.a = corners[static_cast<std::size_t>(c)];
    return reduced(p);
}

SurfacePoint HierarchyTriangle::sample(const SampleWeights& w) const { return reduced(sample_at_level(w)); }

SurfacePoint HierarchyTriangle::sample_at_level(const SampleWeights& w) const {
    // Numerators over 2^(level+2): (sum w_c * 4 * corner_c) / 4.
    SurfacePoint p;
    p.face = face;
    p.level = level + 2;
    for (int i = 0; i < 3; ++i)
        p.a[i] = static_cast<std::uint32_t>(w[0]) * corners[0][i] + static_cast<std::uint32_t>(w[1]) * corners[1][i] +
                 static_cast<std::uint32_t>(w[2]) * corners[2][i];
    return p;
}

std::array<int, 3> interpolation_order(const std::array<glm::dvec3, 3>& corners) {
    std::array<int, 3> order{0, 1, 2};
    auto less = [&](int i, int j) {
        const glm::dvec3 &x = corners[static_cast<std::size_t>(i)], &y = corners[static_cast<std::size_t>(j)];
        if (x.x != y.x) return x.x < y.x;
        if (x.y != y.y) return x.y < y.y;
        return x.z < y.z;
    };
    std::sort(order.begin(), order.end(), less);
    return order;
}

glm::dvec3 interpolate(const std::array<glm::dvec3, 3>& corners, const std::array<double, 3>& weights) {
    return interpolate_in_order(corners, interpolation_order(corners), weights);
}

InlineVector<HierarchyTriangle, 2> triangles_beside(const BaseMesh& base, const SurfacePoint& a, const SurfacePoint& b) {
    // The midpoint's Loop stencil names the edge's ends and the corners opposite it (one on the
    // boundary), each opposite corner in the base face of its triangle.
    const SurfacePoint m = midpoint(base, a, b);
    const PointStencil s = parent_stencil(base, m);
    InlineVector<HierarchyTriangle, 2> out;
    for (const SurfacePoint& far : s.opposite) {
        HierarchyTriangle t;
        t.face = far.face;
        t.level = m.level - 1;
        const std::array<SurfacePoint, 2> ends{a, b};
        for (std::size_t i = 0; i < 2; ++i) {
            const auto p = in_face(base, ends[i], far.face);
            if (!p) throw std::logic_error("triangles_beside: an end of the edge is not in its triangle's face");
            t.corners[i] = numerators_at(*p, t.level);
        }
        t.corners[2] = numerators_at(far, t.level);
        if (lattice_orientation(t.corners[0], t.corners[1], t.corners[2]) < 0) std::swap(t.corners[0], t.corners[1]);
        out.push_back(t);
    }
    return out;
}

}  // namespace rgb
