#include "uv_rules.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "crease_closed_form.h"

namespace osdoracle {
namespace {

UvValue value_of(UvKind kind, const glm::dvec2& uv) {
    UvValue v;
    v.kind = kind;
    v.uv = uv;
    return v;
}

glm::dvec3 lift(const glm::dvec2& uv) { return {uv.x, uv.y, 0.0}; }
glm::dvec2 drop(const glm::dvec3& p) { return {p.x, p.y}; }

int value_at(const UvTopology& topology, const FarLevel& level, int triangle, int vertex) {
    const auto& t = level.triangles[triangle];
    return topology.corner_value[triangle][std::find(t.begin(), t.end(), vertex) - t.begin()];
}

// The triangles around a vertex in fan order: faces[i] is (vertex, ring[i], ring[i+1]), so it lies
// between the edges to ring[i] and ring[i+1] (cyclically for an interior vertex).
std::vector<int> fan_faces(const FarLevel& level, int vertex, const Neighbourhood& n, const std::vector<int>& around) {
    std::map<int, int> face_after;  // neighbour -> the triangle that follows it counter-clockwise
    for (int t : around) {
        const auto& tri = level.triangles[t];
        const auto i = std::find(tri.begin(), tri.end(), vertex) - tri.begin();
        face_after[tri[(i + 1) % 3]] = t;
    }
    std::vector<int> faces;
    for (std::size_t i = 0; i < n.ring_vertices.size() - (n.boundary ? 1 : 0); ++i)
        faces.push_back(face_after.at(n.ring_vertices[i]));
    return faces;
}

// A run of consecutive faces around a vertex sharing one value there.
struct Span {
    int value = -1;
    std::size_t start = 0, size = 0;  // faces start .. start + size - 1, cyclically
    int infinite_edges = 0;           // infinitely sharp edges inside the span
    double semi_sharpness = 0.0;      // largest semi-sharp sharpness inside the span (0: none)
    bool disjoint = false;            // a seam inside the span, or the value in two spans: Far pins it
};

std::vector<Span> spans_around(const FarLevel& level, const LevelTags& tags, const UvTopology& topology, int vertex,
                               const Neighbourhood& n, const std::vector<int>& faces) {
    const std::size_t m = faces.size();
    std::vector<int> values;
    for (int f : faces) values.push_back(value_at(topology, level, f, vertex));
    // Start where a span starts: face 0 of a boundary fan, else a face after a seam or a value change.
    std::size_t first = 0;
    if (!n.boundary) {
        for (std::size_t i = 0; i < m; ++i)
            if (values[i] != values[(i + m - 1) % m] || topology.seams.contains(edge_key(vertex, n.ring_vertices[i]))) {
                first = i;
                break;
            }
    }
    std::vector<Span> spans;
    for (std::size_t k = 0; k < m; ++k) {
        const std::size_t i = (first + k) % m;
        if (k == 0 || values[i] != spans.back().value) {
            spans.push_back({values[i], i, 0, 0, 0.0, false});
        } else if (topology.seams.contains(edge_key(vertex, n.ring_vertices[i]))) {
            spans.back().disjoint = true;
        } else {
            const double s = tags.edge_sharpness.at(edge_key(vertex, n.ring_vertices[i]));  // between faces i-1, i
            if (is_infinite(s)) ++spans.back().infinite_edges;
            else spans.back().semi_sharpness = std::max(spans.back().semi_sharpness, s);
        }
        ++spans.back().size;
    }
    for (Span& a : spans)
        for (Span& b : spans)
            if (&a != &b && a.value == b.value) a.disjoint = b.disjoint = true;
    return spans;
}

// Whether any value of the vertex differs from the vertex's own rule (§2 of the note).
bool is_mismatched(const FarInput& input, const UvTopology& topology, int vertex, const Neighbourhood& n,
                   std::size_t faces) {
    const UvInterpolation option = input.uv->interpolation;
    for (int x : n.ring_vertices)
        if (topology.seams.contains(edge_key(vertex, x))) return true;
    if (!n.boundary) return false;
    const bool linear_boundaries = option == UvInterpolation::boundaries || option == UvInterpolation::all;
    return linear_boundaries || (faces == 1 && input.boundary == BoundaryInterpolation::edge_only &&
                                 option != UvInterpolation::none);
}

void classify_vertex(const FarInput& input, const FarLevel& level, const LevelTags& tags, const UvTopology& topology,
                     const std::vector<glm::dvec2>& uv_of_value, int vertex, const std::vector<int>& around,
                     std::vector<UvValue>& out) {
    const UvInterpolation option = input.uv->interpolation;
    const Neighbourhood n = gather_neighbourhood(level, tags, vertex, around);
    const std::vector<int> faces = fan_faces(level, vertex, n, around);
    const std::vector<Span> spans = spans_around(level, tags, topology, vertex, n, faces);
    const std::size_t m = faces.size();

    if (option == UvInterpolation::all) {
        for (const Span& s : spans) out[s.value] = value_of(UvKind::linear, uv_of_value[s.value]);
        return;
    }
    if (!is_mismatched(input, topology, vertex, n, m)) {
        UvValue& v = out[spans.front().value];
        v = value_of(UvKind::matching, uv_of_value[spans.front().value]);
        v.uv_ring = n;
        v.uv_ring.centre = lift(v.uv);
        for (std::size_t i = 0; i < n.ring_vertices.size(); ++i)
            v.uv_ring.ring[i] = lift(uv_of_value[value_at(topology, level, faces[std::min(i, m - 1)], n.ring_vertices[i])]);
        return;
    }

    std::vector<int> distinct;
    for (const Span& s : spans) distinct.push_back(s.value);
    std::sort(distinct.begin(), distinct.end());
    const std::size_t value_count = static_cast<std::size_t>(std::unique(distinct.begin(), distinct.end()) - distinct.begin());
    const double sigma = tags.vertex_sharpness[vertex];
    // Far's rules for values that do not follow the vertex (fvarLevel.cpp, completeTopologyFromFaceValues).
    const bool dependent_option = option == UvInterpolation::corners_plus1 || option == UvInterpolation::corners_plus2;
    bool all_corners = option == UvInterpolation::boundaries || is_infinite(sigma) ||
                       (dependent_option && value_count > 2) ||
                       (option == UvInterpolation::corners_plus2 && value_count == 1 && !n.boundary);
    bool dependent = false;
    if (!all_corners && dependent_option && value_count == 2) {
        auto any = [&](auto predicate) { return std::any_of(spans.begin(), spans.end(), predicate); };
        all_corners = any([](const Span& s) { return s.disjoint || s.infinite_edges > 0; }) ||
                      (option == UvInterpolation::corners_plus2 && any([](const Span& s) { return s.size == 1; }));
        // One value semi-sharp and the other not: the other is sharpened as long as the first is.
        dependent = (spans[0].semi_sharpness > 0.0) != (spans[1].semi_sharpness > 0.0);
    }
    const double vertex_semi = sigma > 0.0 && !is_infinite(sigma) ? sigma : 0.0;
    for (const Span& s : spans) {
        UvValue v = value_of(UvKind::crease, uv_of_value[s.value]);
        const std::size_t last = (s.start + s.size - 1) % m;
        const std::size_t trailing_edge = n.boundary ? s.start + s.size : (s.start + s.size) % m;
        v.end0 = uv_of_value[value_at(topology, level, faces[s.start], n.ring_vertices[s.start])];
        v.end1 = uv_of_value[value_at(topology, level, faces[last], n.ring_vertices[trailing_edge])];
        const double partner_semi = dependent ? std::max(spans[0].semi_sharpness, spans[1].semi_sharpness) : 0.0;
        v.levels_sharp = static_cast<int>(std::ceil(std::max({s.semi_sharpness, vertex_semi, partner_semi})));
        if (all_corners || s.disjoint || s.infinite_edges > 0 || (s.size == 1 && option != UvInterpolation::none))
            v.kind = UvKind::corner;
        else if (v.levels_sharp > 0)
            v.kind = UvKind::semi_sharp;
        out[s.value] = v;
    }
}

glm::dvec2 crease_closed_form(const glm::dvec2& uv, const glm::dvec2& end0, const glm::dvec2& end1, int j) {
    const double g = std::pow(0.25, j);
    return g * uv + (1.0 - g) * (2.0 / 3.0 * uv + 1.0 / 6.0 * (end0 + end1));
}

// A semi-sharp value's crease ends once it turns into a crease: while it is a corner, the vertices
// inserted on its bounding edges are midpoints, so the ends halve their distance to it every level.
glm::dvec2 end_after_corner_levels(const UvValue& v, const glm::dvec2& end) {
    return v.uv + std::ldexp(1.0, -v.levels_sharp) * (end - v.uv);
}

}  // namespace

std::vector<UvValue> classify_uv_values(const FarInput& input, const FarLevel& level, const LevelTags& tags,
                                        const UvTopology& topology, const std::vector<glm::dvec2>& uv_of_value) {
    std::vector<UvValue> values(topology.value_vertex.size());
    const auto around = triangles_around_vertices(level);
    for (std::size_t v = 0; v < level.positions.size(); ++v)
        classify_vertex(input, level, tags, topology, uv_of_value, static_cast<int>(v), around[v], values);
    return values;
}

std::vector<glm::dvec2> uv_one_level_finer(const FarInput& input, const FarLevel& coarse_level,
                                           const LevelTags& coarse_tags, const UvTopology& coarse,
                                           const std::vector<UvValue>& values, const UvTopology& fine) {
    const UvInterpolation option = input.uv->interpolation;
    std::map<EdgeKey, std::vector<int>> edge_triangles;
    for (std::size_t t = 0; t < coarse_level.triangles.size(); ++t)
        for (int i = 0; i < 3; ++i)
            edge_triangles[edge_key(coarse_level.triangles[t][i], coarse_level.triangles[t][(i + 1) % 3])].push_back(
                static_cast<int>(t));
    auto uv = [&](int triangle, int vertex) { return values[value_at(coarse, coarse_level, triangle, vertex)].uv; };

    std::vector<glm::dvec2> finer;
    for (const UvValueOrigin& o : fine.value_origin) {
        if (!o.on_edge) {
            const UvValue& v = values[o.parent_value];
            switch (v.kind) {
            case UvKind::matching: finer.push_back(drop(one_level_finer(v.uv_ring).centre)); break;
            case UvKind::crease: finer.push_back(0.75 * v.uv + 0.125 * (v.end0 + v.end1)); break;
            case UvKind::linear:
            case UvKind::corner:
            case UvKind::semi_sharp: finer.push_back(v.uv); break;
            }
            continue;
        }
        const EdgeKey e = edge_key(o.a, o.b);
        const std::vector<int>& triangles = edge_triangles.at(e);
        const int side = o.side_triangle >= 0 ? o.side_triangle : triangles.front();
        const bool linear_boundary = (option == UvInterpolation::boundaries && triangles.size() == 1);
        if (option == UvInterpolation::all || o.side_triangle >= 0 || linear_boundary) {
            finer.push_back(0.5 * (uv(side, o.a) + uv(side, o.b)));
            continue;
        }
        std::vector<glm::dvec3> opposite;
        for (int t : triangles)
            for (int x : coarse_level.triangles[t])
                if (x != o.a && x != o.b) opposite.push_back(lift(uv(t, x)));
        finer.push_back(drop(edge_point(lift(uv(side, o.a)), lift(uv(side, o.b)), opposite, coarse_tags.edge_sharpness.at(e))));
    }
    return finer;
}

glm::dvec2 uv_closed_form(const UvValue& v, int j) {
    switch (v.kind) {
    case UvKind::linear:
    case UvKind::corner: return v.uv;
    case UvKind::matching: return drop(piecewise_closed_form(v.uv_ring, j));
    case UvKind::crease: return crease_closed_form(v.uv, v.end0, v.end1, j);
    case UvKind::semi_sharp:
        if (j <= v.levels_sharp) return v.uv;
        return crease_closed_form(v.uv, end_after_corner_levels(v, v.end0), end_after_corner_levels(v, v.end1),
                                  j - v.levels_sharp);
    }
    throw std::logic_error("unknown UV kind");
}

glm::dvec2 uv_limit(const UvValue& v) {
    switch (v.kind) {
    case UvKind::linear:
    case UvKind::corner: return v.uv;
    case UvKind::matching: return drop(piecewise_limit(v.uv_ring));
    case UvKind::crease: return 2.0 / 3.0 * v.uv + 1.0 / 6.0 * (v.end0 + v.end1);
    case UvKind::semi_sharp:
        return 2.0 / 3.0 * v.uv +
               1.0 / 6.0 * (end_after_corner_levels(v, v.end0) + end_after_corner_levels(v, v.end1));
    }
    throw std::logic_error("unknown UV kind");
}

bool far_limit_is_exact(const UvValue& v) { return v.kind != UvKind::matching || final_rule(v.uv_ring) != VertexRule::dart; }

}  // namespace osdoracle
