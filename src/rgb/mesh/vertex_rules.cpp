#include "rgb/mesh/vertex_rules.h"

#include <algorithm>

#include "rgb/mesh/base_mesh.h"

namespace rgb {

namespace {

// A base vertex's edges in ring_at's order, each as (face, the vertex's corner, the other corner).
struct BaseDirection {
    std::uint32_t face;
    int from, to;
    std::uint32_t halfedge;  // of the edge, for its sharpness
};

std::vector<BaseDirection> base_directions(const BaseMesh& base, std::uint32_t v) {
    std::vector<BaseDirection> out;
    const std::uint32_t start = base.vertex_halfedge(v);
    std::uint32_t h = start, last = start;
    do {
        const int c = static_cast<int>(h % 3);
        out.push_back({h / 3, c, (c + 1) % 3, h});
        last = h;
        h = base.ccw_rotated(h);
    } while (h != BaseMesh::kNone && h != start);
    if (h == BaseMesh::kNone) {
        // The last face's incoming boundary edge closes a boundary vertex's ring.
        const int c = static_cast<int>(last % 3);
        const std::uint32_t incoming = last - last % 3 + static_cast<std::uint32_t>((c + 2) % 3);
        out.push_back({last / 3, c, (c + 2) % 3, incoming});
    }
    return out;
}

Regime regime_at(int level, int corner_sharpness, const std::vector<int>& edge_sharpness) {
    Regime r;
    r.start = level;
    std::uint32_t count = 0;
    for (std::uint32_t i = 0; i < edge_sharpness.size(); ++i)
        if (sharp_at_level(edge_sharpness[i], level)) {
            if (count < 2) r.sharp[count] = i;
            ++count;
        }
    if (sharp_at_level(corner_sharpness, level) || count >= 3)
        r.rule = VertexRule::Corner;
    else
        r.rule = count == 2 ? VertexRule::Crease : count == 1 ? VertexRule::Dart : VertexRule::Smooth;
    if (r.rule == VertexRule::Corner || r.rule == VertexRule::Smooth) r.sharp[0] = r.sharp[1] = 0;
    return r;
}

}  // namespace

Regimes base_vertex_regimes(const BaseMesh& base, std::uint32_t v) {
    std::vector<int> sharpness;
    for (const BaseDirection& d : base_directions(base, v)) sharpness.push_back(base.edge_sharpness(d.halfedge));
    const int corner = base.corner_sharpness(v);
    // The rule can only change where a finite sharpness runs out.
    std::vector<int> levels{0};
    for (int s : sharpness)
        if (s > 0 && s < kInfiniteSharpness) levels.push_back(s);
    if (corner > 0 && corner < kInfiniteSharpness) levels.push_back(corner);
    std::sort(levels.begin(), levels.end());
    levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
    Regimes regimes;
    for (int t : levels) {
        const Regime r = regime_at(t, corner, sharpness);
        const bool same = !regimes.empty() && regimes[regimes.size() - 1].rule == r.rule &&
                          regimes[regimes.size() - 1].sharp[0] == r.sharp[0] &&
                          regimes[regimes.size() - 1].sharp[1] == r.sharp[1];
        if (!same) regimes.push_back(r);
    }
    return regimes;
}

Regimes vertex_regimes(const BaseMesh& base, const SurfacePoint& p) {
    if (const auto v = base_vertex(base, p)) {
        if (const Regimes* kept = base.sharp_vertex_regimes(*v)) return *kept;
        return base_vertex_regimes(base, *v);
    }
    const auto h = base_edge_of(p);
    if (!h || !sharp_at_level(base.edge_sharpness(*h), p.level)) return {Regime{p.level, VertexRule::Smooth, {0, 0}}};
    // On a base edge still sharp at p's level: a crease along it (its two neighbours on the edge come
    // first in ring_at_level) until the edge's sharpness runs out.
    Regimes regimes{Regime{p.level, VertexRule::Crease, {0, 1}}};
    const int s = base.edge_sharpness(*h);
    if (s < kInfiniteSharpness) regimes.push_back(Regime{s, VertexRule::Smooth, {0, 0}});
    return regimes;
}

bool follows_untagged_rules(const BaseMesh& base, const SurfacePoint& p) {
    if (!base.has_sharp_features()) return true;
    if (const auto v = base_vertex(base, p)) return !base.has_sharp_rules(*v);
    const auto h = base_edge_of(p);
    return !h || base.opposite(*h) == BaseMesh::kNone || !sharp_at_level(base.edge_sharpness(*h), p.level);
}

bool inserted_at_midpoint(const BaseMesh& base, const SurfacePoint& p) {
    const auto h = base_edge_of(p);
    return h && sharp_at_level(base.edge_sharpness(*h), p.level - 1);
}

bool on_base_edge_or_vertex(const SurfacePoint& p) { return p.level == 0 || base_edge_of(p).has_value(); }

std::optional<std::uint32_t> base_edge_between(const BaseMesh& base, const SurfacePoint& a, const SurfacePoint& b) {
    // The midpoint of an edge inside a base face has no zero coordinate; only both ends on the same
    // base edge give one.
    if (!on_base_edge_or_vertex(a) || !on_base_edge_or_vertex(b)) return std::nullopt;
    return base_edge_of(midpoint(base, a, b));
}

std::vector<SurfacePoint> ring_at(const BaseMesh& base, const SurfacePoint& p, int k) {
    if (const auto v = base_vertex(base, p)) {
        std::vector<SurfacePoint> ring;
        for (const BaseDirection& d : base_directions(base, *v)) {
            if (k == 0) {
                ring.push_back(corner_point(d.face, d.to));
                continue;
            }
            // One step of 1/2^k from the vertex towards the other end (already reduced: odd numerators).
            SurfacePoint q;
            q.face = d.face;
            q.level = k;
            q.a[static_cast<std::size_t>(d.from)] = (std::uint32_t(1) << k) - 1;
            q.a[static_cast<std::size_t>(d.to)] = 1;
            ring.push_back(q);
        }
        return ring;
    }
    const auto ring = ring_at_level(base, p, k);
    return {ring.begin(), ring.end()};
}

}  // namespace rgb
