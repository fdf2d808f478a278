#include "rgb/values/uv_layout.h"

#include <algorithm>
#include <span>
#include <stdexcept>
#include <string>

#include "rgb/mesh/base_mesh.h"

namespace rgb {

namespace {

// A run of consecutive faces around a vertex that share one value there (docs/loop-face-varying.md §1).
struct FanSpan {
    std::uint32_t value = 0;
    std::size_t start = 0, size = 0;  // fan faces start .. start + size - 1, cyclically
    bool infinite_edge = false;       // an infinitely sharp edge between two of its faces
    int semi_sharpness = 0;           // the largest finite sharpness of such an edge
    bool pinned = false;              // a seam inside it, or its Far sibling in another span too
};

constexpr const char* kOptionNames[] = {"none", "corners", "boundaries", "all"};

// Far's sibling (its value slot at the vertex) of each fan face, as vtr/fvarLevel.cpp's
// completeTopologyFromFaceValues assigns them, for fan faces `value` in fan order and Far's first
// face `start` (docs/loop-face-varying.md §5): walking the faces from there, a face with its
// predecessor's value shares its sibling; a new value gets a new sibling unless an earlier sibling
// has it, except that while there are exactly two siblings Far compares with the first only, so the
// second value's return after the first's (A B A B) becomes a sibling of its own.
std::vector<std::uint32_t> far_siblings(std::span<const std::uint32_t> value, std::size_t start) {
    const std::size_t m = value.size();
    std::vector<std::uint32_t> sibling(m), unique{value[start]};
    sibling[start] = 0;
    for (std::size_t k = 1; k < m; ++k) {
        const std::size_t i = (start + k) % m, previous = (start + k - 1) % m;
        if (value[i] == value[previous]) {
            sibling[i] = sibling[previous];
            continue;
        }
        const auto searched_end = unique.size() == 2 ? unique.begin() + 1 : unique.end();
        const auto found = std::find(unique.begin(), searched_end, value[i]);
        if (found != searched_end) {
            sibling[i] = static_cast<std::uint32_t>(found - unique.begin());
        } else {
            sibling[i] = static_cast<std::uint32_t>(unique.size());
            unique.push_back(value[i]);
        }
    }
    return sibling;
}

}  // namespace

const char* uv_interpolation_name(UvInterpolation option) { return kOptionNames[static_cast<int>(option)]; }

std::optional<UvInterpolation> parse_uv_interpolation(std::string_view name) {
    for (int i = 0; i < 4; ++i)
        if (name == kOptionNames[i]) return static_cast<UvInterpolation>(i);
    return std::nullopt;
}

UvLayout::UvLayout(const BaseMesh& base, UvChannel channel) : channel_(std::move(channel)) {
    if (channel_.corners.size() != base.num_faces())
        throw std::invalid_argument("UV channel: " + std::to_string(channel_.corners.size()) + " faces of UV indices for " +
                                    std::to_string(base.num_faces()) + " faces");
    for (std::size_t f = 0; f < channel_.corners.size(); ++f)
        for (std::uint32_t i : channel_.corners[f])
            if (i >= channel_.values.size())
                throw std::invalid_argument("UV channel: face " + std::to_string(f) + " names UV " + std::to_string(i) +
                                            " of " + std::to_string(channel_.values.size()));
    seam_.assign(3 * base.num_faces(), 0);
    for (std::uint32_t h = 0; h < seam_.size(); ++h) {
        const std::uint32_t o = base.opposite(h);
        if (o == BaseMesh::kNone) continue;
        const std::uint32_t f = h / 3, g = o / 3;
        const int a = static_cast<int>(h % 3), b = static_cast<int>(o % 3);  // h runs a -> a+1, o runs b -> b+1
        seam_[h] = channel_.corners[f][a] != channel_.corners[g][(b + 1) % 3] ||
                   channel_.corners[f][(a + 1) % 3] != channel_.corners[g][b];
    }
    span_of_corner_.assign(3 * base.num_faces(), kNone);
    for (std::uint32_t v = 0; v < base.num_vertices(); ++v) classify_vertex(base, v);
}

void UvLayout::classify_vertex(const BaseMesh& base, std::uint32_t v) {
    const UvInterpolation option = channel_.interpolation;
    // The fan of v in BaseMesh::ring's order: face j lies between ring entries j and j+1, and ring
    // entry i is reached along edge[i].
    std::vector<std::uint32_t> out;  // outgoing halfedge of v in each fan face
    std::uint32_t h = base.vertex_halfedge(v);
    do {
        out.push_back(h);
        h = base.ccw_rotated(h);
    } while (h != BaseMesh::kNone && h != base.vertex_halfedge(v));
    const bool boundary = base.is_boundary_vertex(v);
    const std::size_t m = out.size();
    std::vector<std::uint32_t> edge(out);
    if (boundary) edge.push_back(out.back() - out.back() % 3 + (out.back() % 3 + 2) % 3);
    auto value_in = [&](std::size_t j) { return channel_.corners[out[j] / 3][out[j] % 3]; };
    auto seam_at = [&](std::size_t i) { return is_seam(edge[i]); };

    bool mismatched = std::any_of(edge.begin(), edge.end(), [&](std::uint32_t e) { return is_seam(e); });
    if (boundary) {
        const bool linear_boundaries = option == UvInterpolation::Boundaries || option == UvInterpolation::All;
        const bool lone_corner = m == 1 && base.sharp_features().boundary == BoundaryInterpolation::EdgeOnly &&
                                 option != UvInterpolation::None;
        mismatched = mismatched || linear_boundaries || lone_corner;
    }

    std::vector<FanSpan> spans;
    std::size_t first = 0;
    if (!boundary)
        for (std::size_t i = 0; i < m; ++i)
            if (value_in(i) != value_in((i + m - 1) % m) || seam_at(i)) {
                first = i;
                break;
            }
    for (std::size_t k = 0; k < m; ++k) {
        const std::size_t i = (first + k) % m;
        if (!mismatched && k > 0) {
            ++spans.back().size;
            continue;
        }
        if (k == 0 || value_in(i) != spans.back().value) {
            spans.push_back({value_in(i), i, 0});
        } else if (seam_at(i)) {
            spans.back().pinned = true;
        } else {
            const int s = base.edge_sharpness(edge[i]);
            if (s >= kInfiniteSharpness) spans.back().infinite_edge = true;
            else spans.back().semi_sharpness = std::max(spans.back().semi_sharpness, s);
        }
        ++spans.back().size;
    }
    // A Far sibling with two separate spans (a UV bow-tie) is a corner. Far starts at the boundary,
    // or around an interior vertex at its lowest-numbered face.
    std::vector<std::uint32_t> fan_values(m);
    for (std::size_t j = 0; j < m; ++j) fan_values[j] = value_in(j);
    const std::size_t far_start =
        boundary ? 0 : static_cast<std::size_t>(std::min_element(out.begin(), out.end()) - out.begin());
    const std::vector<std::uint32_t> sibling = far_siblings(fan_values, far_start);
    for (FanSpan& a : spans)
        for (const FanSpan& b : spans)
            if (&a != &b && sibling[a.start] == sibling[b.start]) a.pinned = true;

    const int sigma = base.corner_sharpness(v);
    for (const FanSpan& s : spans) {
        Span span;
        span.face = out[s.start] / 3;
        if (option == UvInterpolation::All) {
            span.regimes.push_back(UvRegime{});
        } else if (mismatched) {
            // §2's table for the options without dependent sharpness.
            const bool corner = option == UvInterpolation::Boundaries || sigma >= kInfiniteSharpness || s.pinned ||
                                s.infinite_edge || (s.size == 1 && option != UvInterpolation::None);
            const int levels_sharp = std::max(s.semi_sharpness, sigma < kInfiniteSharpness ? sigma : 0);
            UvRegime crease;
            crease.rule = VertexRule::Crease;
            crease.sharp[0] = static_cast<std::uint32_t>(s.start);
            crease.end_face[0] = out[s.start] / 3;
            crease.sharp[1] = static_cast<std::uint32_t>(boundary ? s.start + s.size : (s.start + s.size) % m);
            crease.end_face[1] = out[(s.start + s.size - 1) % m] / 3;
            if (corner || levels_sharp > 0) span.regimes.push_back(UvRegime{});
            if (!corner && levels_sharp > 0) crease.start = levels_sharp;
            if (!corner) span.regimes.push_back(crease);
        }
        const auto id = static_cast<std::uint32_t>(spans_.size());
        for (std::size_t k = 0; k < s.size; ++k) {
            // Halfedge 3f+i leaves corner i of face f: its index is the corner's.
            span_of_corner_[out[(s.start + k) % m]] = id;
        }
        spans_.push_back(std::move(span));
    }
}

}  // namespace rgb
