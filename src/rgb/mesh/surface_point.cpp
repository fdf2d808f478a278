#include "rgb/mesh/surface_point.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rgb/mesh/base_mesh.h"

namespace rgb {

namespace {

// p moved by d (numerators at p's level), then reduced.
SurfacePoint moved(const SurfacePoint& p, std::array<int, 3> d) {
    SurfacePoint q = p;
    for (int i = 0; i < 3; ++i) q.a[i] = static_cast<std::uint32_t>(static_cast<std::int64_t>(p.a[i]) + d[i]);
    return reduced(q);
}

int zero_coordinate(const SurfacePoint& p) {
    for (int i = 0; i < 3; ++i)
        if (p.a[i] == 0) return i;
    return -1;
}

// p (on the edge of its face opposite corner z) in the base face across that edge; the corner of that
// face that is not on the edge comes back in `far`. Nothing on the boundary.
std::optional<SurfacePoint> across_edge(const BaseMesh& base, const SurfacePoint& p, int z, int& far) {
    const int i = (z + 1) % 3;  // the edge runs from corner i to corner i+1
    const std::uint32_t o = base.opposite(3 * p.face + static_cast<std::uint32_t>(i));
    if (o == BaseMesh::kNone) return std::nullopt;
    const int j = static_cast<int>(o % 3);
    SurfacePoint q;
    q.face = o / 3;
    q.level = p.level;
    q.a[j] = p.a[(i + 1) % 3];
    q.a[(j + 1) % 3] = p.a[i];
    q.a[(j + 2) % 3] = 0;
    far = (j + 2) % 3;
    return q;
}

// Both points expressed in one base face.
std::pair<SurfacePoint, SurfacePoint> in_common_face(const BaseMesh& base, const SurfacePoint& p, const SurfacePoint& q) {
    // Most edges of the hierarchy lie inside one base face, or one address names the other's face.
    if (p.face == q.face) return {p, q};
    if (auto q2 = in_face(base, q, p.face)) return {p, *q2};
    if (auto p2 = in_face(base, p, q.face)) return {*p2, q};
    // An edge point's other face, or any face around a base vertex.
    for (const SurfacePoint* x : {&p, &q}) {
        if (x->level == 0) {
            const std::uint32_t v = *base_vertex(base, *x);
            std::uint32_t h = base.vertex_halfedge(v);
            do {
                const auto p2 = in_face(base, p, h / 3), q2 = in_face(base, q, h / 3);
                if (p2 && q2) return {*p2, *q2};
                h = base.ccw_rotated(h);
            } while (h != BaseMesh::kNone && h != base.vertex_halfedge(v));
        } else if (const int z = zero_coordinate(*x); z >= 0) {
            int far = 0;
            if (const auto other = across_edge(base, *x, z, far)) {
                const auto p2 = in_face(base, p, other->face), q2 = in_face(base, q, other->face);
                if (p2 && q2) return {*p2, *q2};
            }
        }
    }
    throw std::logic_error("midpoint: the points share no base face");
}

}  // namespace

SurfacePoint corner_point(std::uint32_t f, int corner) {
    SurfacePoint p;
    p.face = f;
    p.a[static_cast<std::size_t>(corner)] = 1;
    return p;
}

SurfacePoint reduced(SurfacePoint p) {
    while (p.level > 0 && ((p.a[0] | p.a[1] | p.a[2]) & 1u) == 0) {
        for (std::uint32_t& x : p.a) x >>= 1;
        --p.level;
    }
    return p;
}

std::array<std::uint32_t, 3> numerators_at(const SurfacePoint& p, int k) {
    const int shift = k - p.level;
    return {p.a[0] << shift, p.a[1] << shift, p.a[2] << shift};
}

std::int64_t lattice_orientation(const std::array<std::uint32_t, 3>& p, const std::array<std::uint32_t, 3>& q,
                                 const std::array<std::uint32_t, 3>& r) {
    const std::int64_t ux = std::int64_t(q[1]) - p[1], uy = std::int64_t(q[2]) - p[2];
    const std::int64_t vx = std::int64_t(r[1]) - p[1], vy = std::int64_t(r[2]) - p[2];
    return ux * vy - uy * vx;
}

std::optional<std::uint32_t> base_vertex(const BaseMesh& base, const SurfacePoint& p) {
    if (p.level != 0) return std::nullopt;
    for (int c = 0; c < 3; ++c)
        if (p.a[c] != 0) return base.face(p.face)[c];
    return std::nullopt;
}

std::optional<std::uint32_t> base_edge_of(const SurfacePoint& p) {
    if (p.level == 0) return std::nullopt;
    const int z = zero_coordinate(p);
    if (z < 0) return std::nullopt;
    return 3 * p.face + static_cast<std::uint32_t>((z + 1) % 3);
}

std::optional<SurfacePoint> in_face(const BaseMesh& base, const SurfacePoint& p, std::uint32_t g) {
    if (g == p.face) return p;
    if (p.level == 0) {
        const std::uint32_t v = *base_vertex(base, p);
        for (int c = 0; c < 3; ++c)
            if (base.face(g)[c] == v) return corner_point(g, c);
        return std::nullopt;
    }
    const int z = zero_coordinate(p);
    if (z < 0) return std::nullopt;
    int far = 0;
    const auto q = across_edge(base, p, z, far);
    if (q && q->face == g) return q;
    return std::nullopt;
}

SurfacePoint canonical(const BaseMesh& base, const SurfacePoint& p) {
    if (p.level == 0) {
        const std::uint32_t h = base.vertex_halfedge(*base_vertex(base, p));
        return corner_point(h / 3, static_cast<int>(h % 3));
    }
    const int z = zero_coordinate(p);
    if (z < 0) return p;
    int far = 0;
    const auto q = across_edge(base, p, z, far);
    return q && q->face < p.face ? *q : p;
}

bool is_boundary(const BaseMesh& base, const SurfacePoint& p) {
    if (p.level == 0) return base.is_boundary_vertex(*base_vertex(base, p));
    const int z = zero_coordinate(p);
    if (z < 0) return false;
    return base.opposite(3 * p.face + static_cast<std::uint32_t>((z + 1) % 3)) == BaseMesh::kNone;
}

SurfacePoint midpoint(const BaseMesh& base, const SurfacePoint& p, const SurfacePoint& q) {
    const auto [x, y] = in_common_face(base, p, q);
    const int level = std::max(x.level, y.level) + 1;
    const auto nx = numerators_at(x, level), ny = numerators_at(y, level);
    SurfacePoint m;
    m.face = x.face;
    m.level = level;
    for (int i = 0; i < 3; ++i) m.a[i] = (nx[i] + ny[i]) / 2;
    return reduced(m);
}

glm::dvec3 base_space_position(const BaseMesh& base, const SurfacePoint& p) {
    const Triangle& t = base.face(p.face);
    std::array<int, 3> order{0, 1, 2};
    auto lexicographic = [&](int i, int j) {
        const glm::dvec3 &x = base.position(t[i]), &y = base.position(t[j]);
        if (x.x != y.x) return x.x < y.x;
        if (x.y != y.y) return x.y < y.y;
        return x.z < y.z;
    };
    std::sort(order.begin(), order.end(), lexicographic);
    glm::dvec3 sum(0.0);
    bool first = true;
    const double unit = std::ldexp(1.0, -p.level);  // a power of two: a * unit is exact
    for (int c : order) {
        if (p.a[c] == 0) continue;
        const glm::dvec3 term = (static_cast<double>(p.a[c]) * unit) * base.position(t[c]);
        sum = first ? term : sum + term;
        first = false;
    }
    return sum;
}

PointStencil parent_stencil(const BaseMesh& base, const SurfacePoint& p) {
    if (p.level == 0) throw std::logic_error("parent_stencil: a base vertex has no parent edge");
    int e = 0;
    for (int c = 0; c < 3; ++c)
        if (p.a[c] % 2 == 0) e = c;
    const int i = (e + 1) % 3, j = (e + 2) % 3;
    auto delta = [&](int di, int dj, int de) {
        std::array<int, 3> d{};
        d[i] = di;
        d[j] = dj;
        d[e] = de;
        return d;
    };
    PointStencil s{{moved(p, delta(1, -1, 0)), moved(p, delta(-1, 1, 0))}, {}};
    s.opposite.push_back(moved(p, delta(-1, -1, 2)));
    if (p.a[e] >= 2) {
        s.opposite.push_back(moved(p, delta(1, 1, -2)));
    } else {
        // p lies on the base edge opposite corner e: the other Σ(l-1) triangle is across it.
        int far = 0;
        if (const auto q = across_edge(base, p, e, far)) {
            std::array<int, 3> d{-1, -1, -1};
            d[far] = 2;
            s.opposite.push_back(moved(*q, d));
        } else {
            s.boundary = true;
        }
    }
    return s;
}

InlineVector<SurfacePoint, 6> ring_at_own_level(const BaseMesh& base, const SurfacePoint& p) {
    if (p.level == 0) throw std::logic_error("ring_at_own_level: use BaseMesh::ring for a base vertex");
    auto step = [&](const SurfacePoint& q, int from, int to) {
        std::array<int, 3> d{};
        d[from] = -1;
        d[to] = 1;
        return moved(q, d);
    };
    InlineVector<SurfacePoint, 6> ring;
    const int z = zero_coordinate(p);
    if (z < 0) {
        for (int from = 0; from < 3; ++from)
            for (int to = 0; to < 3; ++to)
                if (from != to) ring.push_back(step(p, from, to));
        return ring;
    }
    const int i = (z + 1) % 3, j = (z + 2) % 3;
    ring.push_back(step(p, i, j));
    ring.push_back(step(p, j, i));
    ring.push_back(step(p, i, z));
    ring.push_back(step(p, j, z));
    int far = 0;
    if (const auto q = across_edge(base, p, z, far))
        for (int c = 0; c < 3; ++c)
            if (c != far) ring.push_back(step(*q, c, far));
    return ring;
}

InlineVector<SurfacePoint, 6> ring_at_level(const BaseMesh& base, const SurfacePoint& p, int k) {
    // p written with denominator 2^k (not reduced): its steps of 1/2^k are its neighbours in Σk.
    SurfacePoint fine = p;
    fine.a = numerators_at(p, k);
    fine.level = k;
    return ring_at_own_level(base, fine);
}

}  // namespace rgb
